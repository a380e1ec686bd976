#ifndef xcrack_crack_level_set_fields_h
#define xcrack_crack_level_set_fields_h

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_geometry.h>

#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The cracks of a run: for each, its level sets lsn and lst as Q1 fields
   * on the mesh of the elasticity problem (with ghost values).
   *
   * After initialisation these fields are the crack. The enrichment
   * classifies cells from their vertex values, the cut and tip rules
   * integrate on the zero sets of their interpolants, the jump and branch
   * functions evaluate those interpolants (CellLevelSets), CrackSurface
   * extracts lips and fronts from them, and propagation rewrites them. An
   * initial shape (CrackGeometry: analytic, or a crack surface mesh) only
   * gives their first values.
   *
   * Q1 on the mesh's vertices: the rules and the classification read the
   * d-linear interpolant of the vertex values anyway, so a higher degree
   * would describe a crack the integration does not see.
   *
   * The fields follow the mesh: prepare_for_coarsening_and_refinement()
   * before Triangulation::execute_coarsening_and_refinement() and
   * interpolate() after carry them across (on any number of ranks), and
   * prepare_for_serialization() / deserialize() store them with a
   * checkpoint of the mesh.
   */
  template <int dim>
  class LevelSetFields
  {
  public:
    explicit LevelSetFields(const Triangulation<dim> &triangulation);

    /**
     * Give every crack the interpolant of its initial shape on the current
     * mesh: one crack per entry of @p shapes.
     */
    void
    initialize(const std::vector<const CrackGeometry<dim> *> &shapes);

    unsigned int
    n_cracks() const;

    const DoFHandler<dim> &
    get_dof_handler() const;

    /// The normal level set of crack @p crack, with ghost values.
    const TrilinosWrappers::MPI::Vector &
    lsn(const unsigned int crack) const;

    /// The tangent level set of crack @p crack, with ghost values.
    const TrilinosWrappers::MPI::Vector &
    lst(const unsigned int crack) const;

    /**
     * The values of lsn (@p normal) or lst of crack @p crack at the vertices
     * of the mesh, by vertex index: set for the vertices of the owned and
     * ghost cells, NaN at the others.
     */
    std::vector<double>
    vertex_values(const unsigned int crack, const bool normal) const;

    /**
     * Per active cell (by active cell index; set on the locally owned
     * cells, the largest double elsewhere): the distance of its centre to
     * the nearest front, read as hypot(lsn, lst) of the nearest crack's
     * interpolants there (the means of the vertex values). What the
     * refinement strategies that follow the fronts measure.
     */
    std::vector<double>
    cell_front_distances() const;

    /**
     * Replace the fields of crack @p crack (vectors of the layout of
     * get_dof_handler(), owned entries read; the ghosts are updated here).
     */
    void
    set(const unsigned int                   crack,
        const TrilinosWrappers::MPI::Vector &lsn,
        const TrilinosWrappers::MPI::Vector &lst);

    /**
     * Lower lsn of each crack c by @p shift[c][v] at vertex v (by vertex
     * index; an empty vector leaves the crack alone): fit to vertex moves
     * the crack through the vertices the enrichment chose, and the fields
     * keep the crack the solution sees. Collective.
     */
    void
    subtract_from_lsn(const std::vector<std::vector<double>> &shift);

    /// Before the mesh is refined or coarsened (collective).
    void
    prepare_for_coarsening_and_refinement();

    /// After the mesh was refined or coarsened: the interpolated fields.
    void
    interpolate();

    /// Attach the fields to the mesh before Triangulation::save().
    void
    prepare_for_serialization();

    /// After Triangulation::load(): read the fields of @p n_cracks cracks.
    void
    deserialize(const unsigned int n_cracks);

  private:
    /// The vectors of the current layout: owned, ghosted.
    void
    reinit_vector(TrilinosWrappers::MPI::Vector &vector,
                  const bool                     ghosted) const;

    /// The fields as one list: lsn of every crack, then lst.
    std::vector<const TrilinosWrappers::MPI::Vector *>
    all_fields() const;

    /// Rebuild the ghosted fields from @p owned (all lsn, then all lst),
    /// their round-off zeros made exact first (zero_round_off()).
    void
    set_all(std::vector<TrilinosWrappers::MPI::Vector> &owned);

    /**
     * Set to zero the values of @p owned (a field, owned entries) within
     * 1e-10 of the shortest edge at their vertex. A crack whose front or
     * surface passes through vertices (a tip placed, or grown, onto a mesh
     * line: a = 10 mm on a 1 mm grid) has there values that are zero up to
     * the round-off of its geometry, and the sign of that round-off would
     * decide which cells are cut or hold the front: two mirror tips of one
     * crack enriched differently, and results that change with the
     * machine. Exact zeros take the path the classification has for a
     * surface through a node, the same on every machine.
     */
    void
    zero_round_off(TrilinosWrappers::MPI::Vector &owned) const;

    FE_Q<dim>                                  fe;
    DoFHandler<dim>                            dof_handler;
    std::vector<TrilinosWrappers::MPI::Vector> normal, tangent;
    std::unique_ptr<parallel::distributed::
                      SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>
      transfer;
  };
} // namespace xcrack

#endif
