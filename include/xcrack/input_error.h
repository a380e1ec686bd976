#ifndef xcrack_input_error_h
#define xcrack_input_error_h

#include <exception>
#include <stdexcept>
#include <string>

namespace xcrack
{
  /**
   * An error in what the user gave us: a parameter entry, a mesh file, a
   * combination of options that cannot work together. The message names the
   * culprit (subsection and entry, file, boundary id) and says what was
   * expected, so that the user can fix the input without reading our code.
   *
   * Input errors are raised while the run is being set up, before the output
   * directory is touched, so a failed start loses no earlier results.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A computation that produced what no answer can be: a value that is not
   * finite, or a system that is singular (rigid-body motions left free).
   * The run stops with exit status 3 and a message that names the likely
   * cause, rather than writing numbers an engineer would trust.
   */
  class NumericalError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Throw an InputError with @p message unless @p condition holds. Unlike
   * deal.II's AssertThrow this is meant for user input: the message is shown
   * as is, without file names and line numbers of our sources.
   */
  inline void
  check_input(const bool condition, const std::string &message)
  {
    if (!condition)
      throw InputError(message);
  }

  /**
   * The message of @p e for a user: for a deal.II exception only its
   * additional information, without the source file, line and stack trace
   * that what() adds.
   */
  std::string
  message_of(const std::exception &e);
} // namespace xcrack

#endif
