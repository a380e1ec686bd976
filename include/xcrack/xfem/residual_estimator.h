#ifndef xcrack_xfem_residual_estimator_h
#define xcrack_xfem_residual_estimator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/xfem/enrichment.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * An error indicator for the enriched displacement that treats the cracks
   * as boundaries: the face residuals of the explicit residual estimator of
   * linear elasticity (Kelly-type, no cell residual),
   *
   *   eta_K^2 = 1/(2 mu) [ sum_{interior faces F of K} h_F/2 |[sigma_h n]|_F^2
   *                       + sum_{boundary faces F} h_F |sigma_h n - t|_F^2
   *                       + h_K |sigma_h^+- n + p n|^2 on the lips in K ],
   *
   * with t the Neumann traction (zero on free faces, no residual in held
   * components) and p the lip pressure.
   *
   * Why not deal.II's KellyErrorEstimator: it integrates the jump of the
   * normal derivative over every face, and on an X-FEM mesh reads the
   * crack's own opening as error where the crack runs along faces; the
   * measured effect on Case 1 is a mesh refined on the lips while the tip
   * stays coarse, and an energy error that stops decreasing. Here:
   *
   * - a face the crack lies in (lsn = 0 at its corners) is two lips: each
   *   side has the residual of a boundary, sigma_h n + p n, on its part
   *   with lst < 0 (ahead of the front the face keeps its jump);
   * - a face the crack crosses is integrated on each side of the crack
   *   separately (CellQuadrature::face_rule), and each side is read a
   *   hair's breadth inside its cell, where the jump function takes that
   *   cell's sign;
   * - the lips inside split and tip cells (Enrichment::lip_quadrature())
   *   add their traction residuals on both sides.
   *
   * The enriched gradient is the same on both sides of a face wherever
   * both cells carry the same enriched DoFs, so the singular part of the
   * branch functions cancels from the jumps: the indicators stay finite at
   * the front. The cell residual div sigma_h + f is left out as in Kelly's
   * indicator (the enriched functions' second derivatives are singular at
   * the front).
   */
  template <int dim>
  class ResidualEstimator
  {
  public:
    /**
     * @p enrichment may be null (no crack). @p lambda and @p mu are the
     * Lame constants of the model (plane stress folded in).
     */
    ResidualEstimator(const Enrichment<dim>         *enrichment,
                      const BoundaryConditions<dim> &boundary_conditions,
                      const double                   lambda,
                      const double                   mu);

    /**
     * The indicators eta_K of the locally owned cells of @p dof_handler's
     * mesh (by active cell index; 0 elsewhere) for the displacement
     * @p solution (with ghost entries).
     */
    void
    estimate(const DoFHandler<dim>               &dof_handler,
             const TrilinosWrappers::MPI::Vector &solution,
             Vector<float>                       &indicators) const;

  private:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /// sigma_h from the displacement gradient.
    SymmetricTensor<2, dim>
    stress(const Tensor<2, dim> &gradient) const;

    /// Whether the crack makes the faces of @p cell special: split or tip.
    bool
    is_cut(const CellIterator &cell) const;

    /**
     * The residual integrals of face @p face_no of @p cell (its part
     * shared with @p neighbor, the box @p box of the cell's reference
     * cell, of diameter @p h; @p neighbor invalid at the boundary) on the
     * points of CellQuadrature::face_rule(), weighted as eta_K^2 wants
     * them.
     */
    double
    cut_face_term(const CellIterator                  &cell,
                  const unsigned int                   face_no,
                  const CellIterator                  &neighbor,
                  const BoundingBox<dim>              &box,
                  const double                         h,
                  const TrilinosWrappers::MPI::Vector &solution) const;

    /// The residuals on the lips inside @p cell, weighted.
    double
    lip_term(const CellIterator                  &cell,
             const TrilinosWrappers::MPI::Vector &solution) const;

    /**
     * The residual of the traction on a boundary face with boundary id
     * @p id at @p x: sigma n - t in the components that are not held.
     */
    Tensor<1, dim>
    boundary_residual(const types::boundary_id id,
                      const Point<dim>        &x,
                      const Tensor<1, dim>    &traction) const;

    const Enrichment<dim>         *enrichment;
    const BoundaryConditions<dim> &boundary_conditions;
    const double                   lambda;
    const double                   mu;
    /// The d-linear map of the cells (where a neighbour sees a point).
    const MappingQ<dim> mapping{1};
  };
} // namespace xcrack

#endif
