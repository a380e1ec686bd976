#ifndef xcrack_command_line_h
#define xcrack_command_line_h

#include <string>

namespace xcrack
{
  /// The command line of this process (Linux), arguments separated by
  /// spaces: what run.json records and what a directory lock names.
  std::string
  command_line();

  /// xcrack's version: the commit the build was configured from (`git
  /// describe`), `-dirty` if it had changes.
  std::string
  version();
} // namespace xcrack

#endif
