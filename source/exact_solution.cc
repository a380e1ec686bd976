#include <deal.II/base/utilities.h>

#include <xcrack/exact_solution.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/input_error.h>

namespace xcrack
{
  void
  ExactSolution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    {
      prm.declare_entry("Type",
                        "parsed",
                        Patterns::Selection("parsed|williams"),
                        "parsed: the expressions of Displacement (no exact "
                        "solution if empty); williams: the crack-tip field "
                        "of BENCHMARKS.md Case 1.");
      prm.declare_entry("Displacement",
                        "",
                        Patterns::Anything(),
                        "parsed: exact displacement 'ux; uy[; uz]' if known; "
                        "L2_error and energy_error are then computed, "
                        "relative to the norms of the exact solution.");
      prm.declare_entry("Stress intensity factors",
                        "1, 0, 0",
                        Patterns::Anything(),
                        "williams: K_I, K_II, K_III.");
      prm.declare_entry("Tip",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "williams: the tip (in 3D a point of the straight "
                        "front).");
      prm.declare_entry("Tip direction",
                        "1, 0, 0",
                        Patterns::Anything(),
                        "williams: e1, pointing ahead of the tip.");
      prm.declare_entry("Crack normal",
                        "0, 1, 0",
                        Patterns::Anything(),
                        "williams: e2, pointing to the upper lip.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  std::shared_ptr<Function<dim>>
  ExactSolution::create(ParameterHandler        &prm,
                        const FunctionConstants &constants,
                        const Material          &material)
  {
    const std::string section = "Exact solution/";
    prm.enter_subsection("Exact solution");
    const std::string type         = prm.get("Type");
    const std::string displacement = prm.get("Displacement");
    const std::string sif          = prm.get("Stress intensity factors");
    const std::string tip          = prm.get("Tip");
    const std::string direction    = prm.get("Tip direction");
    const std::string normal       = prm.get("Crack normal");
    prm.leave_subsection();

    if (type == "parsed")
      {
        if (Utilities::trim(displacement).empty())
          return nullptr;
        return std::make_shared<ParsedVectorFunction<dim>>(
          displacement, dim, constants, section + "Displacement");
      }

    const std::vector<double> k =
      parse_numbers(sif, 3, section + "Stress intensity factors");
    WilliamsField field;
    field.k_I   = k[0];
    field.k_II  = k[1];
    field.k_III = k[2];
    field.mu    = material.mu();
    field.kappa = material.kappa(dim);

    const Point<dim>     p(parse_vector<dim>(tip, section + "Tip"));
    const Tensor<1, dim> e1 =
      parse_vector<dim>(direction, section + "Tip direction");
    const Tensor<1, dim> e2 =
      parse_vector<dim>(normal, section + "Crack normal");
    check_input(e1.norm() > 0 && e2.norm() > 0 &&
                  std::abs(e1 * e2) < 1e-10 * e1.norm() * e2.norm(),
                section + "Tip direction and " + section +
                  "Crack normal must be non-zero and orthogonal.");
    return std::make_shared<WilliamsSolution<dim>>(field, p, e1, e2);
  }



  template std::shared_ptr<Function<2>>
  ExactSolution::create<2>(ParameterHandler &,
                           const FunctionConstants &,
                           const Material &);
  template std::shared_ptr<Function<3>>
  ExactSolution::create<3>(ParameterHandler &,
                           const FunctionConstants &,
                           const Material &);
} // namespace xcrack
