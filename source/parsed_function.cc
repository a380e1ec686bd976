#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <xcrack/input_error.h>
#include <xcrack/parsed_function.h>

#include <sstream>

namespace xcrack
{
  std::vector<std::string>
  split_and_trim(const std::string &text, const char separator)
  {
    std::vector<std::string> parts;
    if (Utilities::trim(text).empty())
      return parts;
    std::string       part;
    std::stringstream stream(text);
    while (std::getline(stream, part, separator))
      parts.push_back(Utilities::trim(part));
    if (!text.empty() && text.back() == separator)
      parts.emplace_back();
    return parts;
  }



  std::vector<double>
  parse_numbers(const std::string &text,
                const unsigned int n,
                const std::string &entry)
  {
    const std::vector<std::string> parts = split_and_trim(text, ',');
    check_input(parts.size() == n,
                entry + " = '" + text + "': expected " + std::to_string(n) +
                  " comma-separated numbers.");
    std::vector<double> values;
    for (unsigned int i = 0; i < parts.size(); ++i)
      try
        {
          values.push_back(Utilities::string_to_double(parts[i]));
        }
      catch (...)
        {
          throw InputError(entry + " = '" + text + "': '" + parts[i] +
                           "' is not a number.");
        }
    return values;
  }



  template <int dim>
  Tensor<1, dim>
  parse_vector(const std::string &text, const std::string &entry)
  {
    // In 2D a third coordinate is dropped only if it is zero (a default
    // written for 3D); else the point is not where the user meant it.
    const bool three_in_2d =
      (dim == 2 && split_and_trim(text, ',').size() == 3);
    const std::vector<double> values =
      parse_numbers(text, three_in_2d ? 3 : dim, entry);
    if (three_in_2d)
      check_input(values[2] == 0,
                  entry + " = '" + text +
                    "': three coordinates in a 2D scene; give x, y (the "
                    "third, " +
                    Utilities::to_string(values[2]) + ", would be ignored).");
    Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = values[d];
    return t;
  }



  namespace
  {
    std::string
    coordinate_names(const unsigned int dim)
    {
      return (dim == 1 ? "x" : (dim == 2 ? "x,y" : "x,y,z"));
    }
  } // namespace



  template <int dim>
  ParsedVectorFunction<dim>::ParsedVectorFunction(
    const std::string       &expressions,
    const unsigned int       n_components,
    const FunctionConstants &constants,
    const std::string       &entry)
    // A step of 1e-4 balances the h^4 truncation error of the fourth-order
    // formula against round-off (eps/h) for functions of unit scale.
    : AutoDerivativeFunction<dim>(1e-4, n_components)
    , parser(n_components)
  {
    this->set_formula(AutoDerivativeFunction<dim>::FourthOrder);

    const std::vector<std::string> parts = split_and_trim(expressions, ';');
    check_input(parts.size() == n_components,
                entry + " = '" + expressions + "': expected " +
                  std::to_string(n_components) +
                  " expressions separated by ';' (one per component), got " +
                  std::to_string(parts.size()) + ".");
    for (const auto &part : parts)
      check_input(!part.empty(),
                  entry + " = '" + expressions +
                    "': a component expression is empty.");

    try
      {
        parser.initialize(coordinate_names(dim), parts, constants);
        // muparser reports some errors only on evaluation: try once at the
        // origin so that a typo fails at start-up, not deep in assembly.
        Vector<double> values(n_components);
        parser.vector_value(Point<dim>(), values);
      }
    catch (const std::exception &e)
      {
        std::ostringstream message;
        message << entry << " = '" << expressions
                << "': cannot evaluate the expression. Variables are "
                << coordinate_names(dim) << "; constants are";
        for (const auto &c : constants)
          message << ' ' << c.first;
        message << '.';
        message << " Parser says: " << message_of(e);
        throw InputError(message.str());
      }
  }



  template <int dim>
  double
  ParsedVectorFunction<dim>::value(const Point<dim>  &p,
                                   const unsigned int component) const
  {
    return parser.value(p, component);
  }



  template <int dim>
  void
  ParsedVectorFunction<dim>::vector_value(const Point<dim> &p,
                                          Vector<double>   &values) const
  {
    parser.vector_value(p, values);
  }



  template Tensor<1, 2>
  parse_vector<2>(const std::string &, const std::string &);
  template Tensor<1, 3>
  parse_vector<3>(const std::string &, const std::string &);
  template class ParsedVectorFunction<2>;
  template class ParsedVectorFunction<3>;
} // namespace xcrack
