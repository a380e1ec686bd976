#ifndef xcrack_crack_level_set_fields_h
#define xcrack_crack_level_set_fields_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_set.h>

#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The level sets lsn and lst of every crack as Q1 fields on the mesh of
   * the elasticity problem (with ghost values). The enrichment reads them
   * to classify cells and the cut-cell quadrature integrates on their
   * zero sets; propagation will update them in place, which is why they
   * are fields and not just the analytic functions.
   */
  template <int dim>
  class LevelSetFields
  {
  public:
    explicit LevelSetFields(
      const parallel::distributed::Triangulation<dim> &triangulation);

    /**
     * Interpolate the level sets of @p cracks on the current mesh. With
     * @p lsn_shift (per crack, per vertex of the triangulation; empty: no
     * shift) lsn is lowered by it at the vertices: the crack the
     * enrichment fitted to the vertices (Enrichment::lsn_shift()), so that
     * the lips and front reported and written are those the solution has.
     */
    void
    update(const CrackSet<dim>                    &cracks,
           const std::vector<std::vector<double>> &lsn_shift = {});

    const DoFHandler<dim> &
    get_dof_handler() const;

    const TrilinosWrappers::MPI::Vector &
    lsn(const unsigned int crack) const;

    const TrilinosWrappers::MPI::Vector &
    lst(const unsigned int crack) const;

  private:
    FE_Q<dim>                                  fe;
    DoFHandler<dim>                            dof_handler;
    std::vector<TrilinosWrappers::MPI::Vector> normal, tangent;
  };
} // namespace xcrack

#endif
