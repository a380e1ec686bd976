#ifndef xcrack_fracture_k_error_estimator_h
#define xcrack_fracture_k_error_estimator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/material.h>
#include <xcrack/xfem/enrichment.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * A goal-oriented estimate of the error of K by recovered stresses (after
   * the estimates of Gonzalez-Estrada, Rodenas et al. for X-FEM, without
   * their equilibration). K is a linear functional of u, and with z the
   * solution of the dual problem a(v, z) = dK . v (KDerivatives) and
   * Galerkin orthogonality,
   *
   *   K(u) - K(u_h) = a(u - u_h, z - z_h)
   *                 ~ int (sigma*(u_h) - sigma_h) : C^-1 : (sigma*(z_h) -
   *                   sigma_h(z_h)) dx,
   *
   * the error of each field replaced by the distance of its stress to a
   * recovered, smoother one. The recovery of a field's stress sigma_h:
   *
   * - its singular part sigma_s = chi(r) sum_m c_m(s) sigma^aux_m (the
   *   Williams stresses of unit K's in the front frame, chi = 1 up to
   *   r_sup from the front and 0 beyond 2 r_sup: a cut-off as gentle as
   *   can be, since the recovery of a steep one reads as error; along a
   *   curved front also 0 beyond half the radius of curvature on its
   *   concave side, where the foot on the front, and so sigma_s, jumps
   *   from point to point) is set aside, its c_m(s) (hats
   *   on the front's K nodes) fitted to sigma_h by least squares within
   *   r_inf of the front (where, in 2D, the dual problems carry no load);
   * - the rest, sigma_h - sigma_s, is averaged at the vertices (L2
   *   projection onto continuous Q1 fields with a lumped mass), on each
   *   side of the crack separately behind the front at the vertices whose
   *   support the crack cuts (those with free jump or branch DoFs);
   * - sigma* = that average + sigma_s.
   *
   * Why this one: the cheap estimates from the K's alone (the spread of
   * crowns, the displacement jumps) were measured unreliable (effectivity
   * 0.01 to 465, doc/verification.md); a residual needs the dual's error
   * z - z_h, which the recovered stresses give without a second mesh or a
   * higher-order space. The branch part of the enriched solution is no
   * substitute for sigma_s: in the blending cells at the edge of a
   * geometric zone the standard part makes up for the incomplete branch
   * part, and its stress there is O(u / h), not an error.
   *
   * The dual problem must be one the mesh resolves: with the crowns of a
   * few cells that K is extracted on, the dual load (made of the gradient
   * of theta, interpolated on the cells) jumps from cell to cell, no
   * recovery sees the dual's error, and the estimate was measured off in
   * sign and size. Simulator::estimate_k_errors() therefore applies this
   * estimate to K on a crown as wide as the body allows, whose weight q is
   * a smooth step of the distance to the front evaluated at the points
   * (FractureParameters::smooth_weight: no jump of the load at the cells'
   * faces nor at the crown's edges), and adds the difference between the
   * two K's.
   *
   * Galerkin orthogonality holds for errors that vanish on the Dirichlet
   * boundary. The discrete solution takes the interpolant of the data g
   * there, and with the dual's tractions sigma(z) n on that boundary
   *
   *   K(u) - K(u_h) = a(u - u_h, z - z_h) - int_{Gamma_D} (g - u_h) .
   *                   sigma(z) n ds,
   *
   * the second term computed with sigma(z_h) on the prescribed components.
   * It is second order in h, as the first is where the tip is enriched in
   * a geometric zone.
   *
   * The integrals of the product over each cell (and of the boundary
   * term over its faces) are also the cell's share of the error: a
   * goal-oriented refinement indicator.
   */
  template <int dim>
  class KErrorEstimator
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    using FEValuesOf   = typename InteractionIntegral<dim>::FEValuesOf;

    /**
     * On @p dof_handler, whose cells @p fe_values_of gives with their
     * X-FEM rules; @p constraints tell the vertices whose enriched DoFs
     * are free. The singular parts are those of @p fronts (as given to
     * InteractionIntegral::compute()), with the crown radii and the K
     * nodes of @p front_values. The Dirichlet data are those of
     * @p boundary_conditions.
     */
    KErrorEstimator(const DoFHandler<dim>           &dof_handler,
                    const Enrichment<dim>           &enrichment,
                    const AffineConstraints<double> &constraints,
                    const Material                  &material,
                    const BoundaryConditions<dim>   &boundary_conditions,
                    const FEValuesOf                &fe_values_of,
                    const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                    const std::vector<FrontValues<dim>> &front_values);

    /**
     * The estimates of K(u) - K(u_h) for the dual solutions @p duals
     * (ghosted, with their constraints distributed) of the primal
     * @p solution (ghosted). With @p shares, each dual's signed share per
     * active cell index (locally owned cells; their sum over the cells is
     * the estimate): combined as the goal needs, they are refinement
     * indicators. Collective.
     */
    std::vector<double>
    estimate(const TrilinosWrappers::MPI::Vector              &solution,
             const std::vector<TrilinosWrappers::MPI::Vector> &duals,
             std::vector<Vector<float>> *shares = nullptr) const;

    /**
     * The cut-off chi of the recovery's singular part at a point @p
     * distance from the front, whose Jacobian along the front is @p h_s
     * (FrontCurve::Projection::jacobian_s(): 1 in 2D and along a straight
     * front, 1 - r / rho towards a centre of curvature): 1 up to @p r_sup,
     * a smooth step down to 0 at 2 r_sup, and, along a curved front, also
     * down to 0 where h_s falls from 3/4 to 1/2 (a quarter to half the
     * radius of curvature away on the concave side). Beyond, the foot on
     * the front jumps from point to point (FrontCurve::normal_plane_foot()),
     * and with it the singular part's frame and coefficients; the recovery
     * read those jumps as error (doc/verification.md, "The singular part's
     * cut-off along a curved front").
     */
    static double
    singular_cutoff(const double distance,
                    const double r_sup,
                    const double h_s);

    /// The size of each field's recovered stresses: the memory of
    /// estimate() is about twice this per field.
    types::global_dof_index
    n_recovery_dofs() const
    {
      return recovery_dof_handler.n_dofs();
    }

  private:
    static constexpr unsigned int n_modes = dim;
    static constexpr unsigned int n_stress =
      SymmetricTensor<2, dim>::n_independent_components;
    /// Slots of a vertex: 0 where the field is continuous, 1 and 2 on the
    /// lsn > 0 and lsn < 0 sides behind the front where it jumps.
    static constexpr unsigned int n_slots = 3;
    /// Per slot: the stress components, then the lumped mass.
    static constexpr unsigned int n_components = n_slots * (n_stress + 1);

    /// One front as the singular parts need it.
    struct Front
    {
      std::unique_ptr<FrontCurve<dim>> curve;
      double                           r_inf = 0, r_sup = 0;
      /// Abscissae of the K nodes, increasing.
      std::vector<double> nodes;
      /// The hats on the nodes at abscissa @p s: (node, value) pairs.
      std::vector<std::pair<unsigned int, double>>
      hats(const double s) const;
    };

    /// At a point: per front near it, the hats, the unit Williams
    /// stresses (mode by mode) and the cut-off chi.
    struct NearFront
    {
      unsigned int                                 front;
      std::vector<std::pair<unsigned int, double>> hats;
      SymmetricTensor<2, dim>                      unit_stress[dim];
      double                                       chi;
    };

    /// The fronts within 2 r_sup of @p x.
    std::vector<NearFront>
    near_fronts(const Point<dim> &x) const;

    /// The stresses of @p fields at the points of @p values.
    void
    field_stresses(
      const FEValues<dim>                                      &values,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &fields,
      std::vector<std::vector<SymmetricTensor<2, dim>>>        &stresses) const;

    /// The coefficients c_m at the K nodes of each front fitted to the
    /// stress of each of @p fields: per field, per front, node after node,
    /// K_I, K_II (, K_III) (for the primal solution close to its K's).
    std::vector<std::vector<std::vector<double>>>
    fit(const std::vector<const TrilinosWrappers::MPI::Vector *> &fields) const;

    /// The slot of vertex @p v of @p cell at reference point @p xi, given
    /// the cell's level sets (empty: no jump there).
    unsigned int
    slot(const CellIterator                                        &cell,
         const unsigned int                                         v,
         const std::pair<std::vector<double>, std::vector<double>> &level_sets,
         const Point<dim>                                          &xi) const;

    /// e : C^-1 : e'.
    double
    energy_product(const SymmetricTensor<2, dim> &e,
                   const SymmetricTensor<2, dim> &e_dual) const;

    /// Add to @p result and @p shares (per dual; per cell, if given) the
    /// Dirichlet boundary's term, - int (g - u_h) . sigma(z_h) n ds.
    void
    add_dirichlet_term(
      const std::vector<const TrilinosWrappers::MPI::Vector *> &fields,
      std::vector<double>                                      &result,
      std::vector<Vector<float>>                               *shares) const;

    const DoFHandler<dim>         &dof_handler;
    const Enrichment<dim>         &enrichment;
    const Material                &material;
    const BoundaryConditions<dim> &boundary_conditions;
    const FEValuesOf               fe_values_of;
    std::vector<Front>             fronts;
    WilliamsField                  unit;
    /// Continuous Q1 fields, n_components of them, for the recovery.
    const FESystem<dim>       recovery_fe;
    DoFHandler<dim>           recovery_dof_handler;
    AffineConstraints<double> recovery_constraints;
    /// Per vertex of the triangulation: whether free enriched DoFs sit
    /// there (its support is cut by the crack).
    std::vector<bool> cut_at_vertex;
  };
} // namespace xcrack

#endif
