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
   * Every entry of @p prm with its default and documentation, as
   * ParameterHandler prints them in @p style (PRM or JSON), but the
   * subsections `Cracks/Crack 2`, `Crack 3`, ...: they repeat `Crack 1`,
   * which says so (`xcrack --print-parameters`).
   */
  void
  print_parameters(const ParameterHandler             &prm,
                   std::ostream                       &out,
                   const ParameterHandler::OutputStyle style);

  /**
   * Read @p filename into @p prm. Unknown entries, values that do not match
   * their pattern, unbalanced subsections and unreadable files become an
   * InputError whose message names the entry and the line of the file.
   * An `include` and an entry declared with Patterns::FileName name a file
   * relative to the directory of the parameter file that holds them, as
   * MOOSE's input files do: a scene runs from any directory. (`Output
   * directory` stays relative to the working directory: results go where
   * the run is started.)
   */
  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename);

  /**
   * Set one entry from the command line (`xcrack -s
   * "Propagation/Maximum advance=0.002" scene.prm`): @p assignment is the
   * entry's path, subsections separated by '/', '=' and the value. A
   * relative file name is taken from the working directory. An entry or
   * a subsection that does not exist, or a value that does not match,
   * is an InputError naming the assignment.
   */
  void
  set_from_command_line(ParameterHandler &prm, const std::string &assignment);

  /// Same as read_parameter_file() for a file's content in memory (tests).
  void
  read_parameter_string(ParameterHandler &prm, const std::string &content);
} // namespace xcrack

#endif
