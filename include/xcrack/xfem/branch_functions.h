#ifndef xcrack_xfem_branch_functions_h
#define xcrack_xfem_branch_functions_h

#include <deal.II/base/function.h>

#include <xcrack/crack/crack_geometry.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * One of the four crack-tip branch functions of X-FEM,
   *
   *   F1 = sqrt(r) sin(theta/2),          F2 = sqrt(r) cos(theta/2),
   *   F3 = sqrt(r) sin(theta/2) sin(theta), F4 = sqrt(r) cos(theta/2)
   * sin(theta),
   *
   * which span the displacements of the Williams fields (all three modes,
   * both plane models) about the front. The polar coordinates come from the
   * crack's level sets, r = sqrt(lsn^2 + lst^2), theta = atan2(lsn, lst), so
   * the same four functions serve every tip of a 2D crack and every point of
   * a 3D front. F1 jumps across the lips (theta = +-pi); on the crack
   * (lsn = 0) theta = +pi, the side H(0) = +1 belongs to.
   *
   * The gradient combines the analytic derivatives in (r, theta) with the
   * gradients of the level sets, which are smooth near the front (the
   * singularity is in F, not in lsn and lst).
   */
  template <int dim>
  class BranchFunction : public Function<dim>
  {
  public:
    /// Branch function F_{@p index + 1} of the level sets @p crack,
    /// @p index < 4.
    BranchFunction(const LevelSetFunctions<dim> &crack,
                   const unsigned int            index);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

    static constexpr unsigned int n_functions = 4;

    /**
     * Multiply by a cut-off chi(r): 1 for r <= @p inner, 0 for r >= @p outer,
     * the C1 cubic 1 - 3t^2 + 2t^3 (t = (r - inner)/(outer - inner)) between.
     * With DOF gathering the zone then carries F chi, which vanishes with
     * its gradient before the zone ends: no blending cells.
     */
    void
    set_cutoff(const double inner, const double outer);

  private:
    /// F and its derivatives with respect to r and theta.
    std::array<double, 3>
    polar_values(const double r, const double theta) const;

    const LevelSetFunctions<dim> &crack;
    const unsigned int            index;
    double                        cutoff_inner = 0;
    double                        cutoff_outer = 0;
  };
} // namespace xcrack

#endif
