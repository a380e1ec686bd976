#ifndef xcrack_exact_solution_h
#define xcrack_exact_solution_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <xcrack/material.h>
#include <xcrack/parsed_function.h>

#include <memory>

namespace xcrack
{
  using namespace dealii;

  /**
   * A known displacement field for verification (`subsection Exact
   * solution`): with one, every solve reports relative L2 and energy errors,
   * and Dirichlet data may be given as `exact` to take the boundary values
   * from it.
   *
   * - `parsed`: the expressions of `Displacement` (none if empty);
   * - `williams`: the crack-tip field of doc/benchmarks.md Case 1 with the
   * given `Stress intensity factors` (K_I, K_II, K_III) at `Tip`, with e1 =
   *   `Tip direction` and e2 = `Crack normal`, for the material of the run;
   * - `griffith` (2D): the complete field of a straight crack of half-length
   *   `Half-length` centred at `Tip` (used as the centre) along `Tip
   *   direction`, with traction-free lips, in an infinite plate under the
   *   uniform `Remote stress` (sigma_xx, sigma_yy, sigma_xy): Westergaard's
   *   solution for modes I and II plus the uniform stress that makes up the
   *   remote sigma along the crack (doc/benchmarks.md Case 4 with exact
   *   boundary data). K_I = sigma_nn sqrt(pi a), K_II = tau sqrt(pi a) at
   *   both tips.
   */
  class ExactSolution
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// The exact solution the file describes, or nullptr for none.
    template <int dim>
    static std::shared_ptr<Function<dim>>
    create(ParameterHandler        &prm,
           const FunctionConstants &constants,
           const Material          &material);
  };
} // namespace xcrack

#endif
