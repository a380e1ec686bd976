#ifndef xcrack_output_file_h
#define xcrack_output_file_h

#include <functional>
#include <ostream>
#include <string>

namespace xcrack
{
  /**
   * Write the file @p path with @p write: into `path.tmp` first, the stream
   * checked after closing, then renamed. A reader never finds a half-written
   * file, a killed run leaves the previous version whole, and a write that
   * fails (a full disk, a directory of that name) throws a
   * std::runtime_error naming the file instead of losing results silently.
   * The temporary file is created anew (exclusively, not through a
   * symbolic link): whatever stood at its name is removed first.
   */
  void
  write_file(const std::string                         &path,
             const std::function<void(std::ostream &)> &write);
} // namespace xcrack

#endif
