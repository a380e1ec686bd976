#ifndef xcrack_parsed_function_h
#define xcrack_parsed_function_h

#include <deal.II/base/auto_derivative_function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>

namespace xcrack
{
  using namespace dealii;

  /**
   * Named constants available in every expression of a parameter file: the
   * material constants (E, nu, mu, lambda), pi, and the user's own
   * `Function constants`. Keeping them in one place lets a manufactured
   * body force be written with the same constants as the material.
   */
  using FunctionConstants = std::map<std::string, double>;

  /**
   * A vector-valued function given in a parameter file as expressions of
   * x, y (and z in 3D), one per component, separated by semicolons.
   *
   * Gradients come from fourth-order central differences so that exact
   * solutions typed by the user can be used for energy-norm errors without
   * asking for their derivatives as well.
   */
  template <int dim>
  class ParsedVectorFunction : public AutoDerivativeFunction<dim>
  {
  public:
    /**
     * Parse @p expressions for @p n_components components. @p entry names
     * the parameter the expressions came from; it is quoted in the error
     * (an InputError) if the expressions do not parse or do not have
     * @p n_components parts.
     */
    ParsedVectorFunction(const std::string       &expressions,
                         const unsigned int       n_components,
                         const FunctionConstants &constants,
                         const std::string       &entry);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;

  private:
    FunctionParser<dim> parser;
  };

  /**
   * Split @p text at @p separator and trim white space around every part.
   * An empty text gives no parts.
   */
  std::vector<std::string>
  split_and_trim(const std::string &text, const char separator);

  /**
   * The @p n comma-separated numbers of the parameter @p entry whose value
   * is @p text; InputError (naming the entry) otherwise.
   */
  std::vector<double>
  parse_numbers(const std::string &text,
                const unsigned int n,
                const std::string &entry);

  /**
   * A point or vector of dim coordinates. In 2D a third coordinate is
   * accepted only if it is zero (a default written for 3D): a point with
   * z = 0.5 in a 2D scene is an InputError, not a silently moved point.
   */
  template <int dim>
  Tensor<1, dim>
  parse_vector(const std::string &text, const std::string &entry);
} // namespace xcrack

#endif
