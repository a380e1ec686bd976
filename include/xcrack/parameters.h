#ifndef xcrack_parameters_h
#define xcrack_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/parsed_function.h>

#include <string>

namespace xcrack
{
  using namespace dealii;

  /**
   * The top level of a parameter file: what kind of run it is and where its
   * results go. Each part of the program declares and parses its own
   * subsection next to its code; declare_all_parameters() collects them.
   */
  class RunParameters
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    unsigned int      dimension = 2;
    std::string       output_directory;
    FunctionConstants user_constants;
    bool              write_vtu      = true;
    bool              timing_summary = true;
    /// The detail of every solve on screen also in a growth run.
    bool detailed_screen = false;
    /// Largest problem whose condition number is computed (0: never).
    unsigned int condition_number_limit = 0;
  };

  /// Declare every entry of every subsection xcrack knows.
  void
  declare_all_parameters(ParameterHandler &prm);

  /**
   * Read @p filename into @p prm. Unknown entries, values that do not match
   * their pattern, unbalanced subsections and unreadable files become an
   * InputError whose message names the entry and the line of the file.
   */
  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename);

  /// Same as read_parameter_file() for a file's content in memory (tests).
  void
  read_parameter_string(ParameterHandler &prm, const std::string &content);
} // namespace xcrack

#endif
