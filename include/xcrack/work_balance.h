#ifndef xcrack_work_balance_h
#define xcrack_work_balance_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <functional>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * How the mesh is shared among the MPI ranks (`subsection Parallel`).
   *
   * p4est gives every rank the same number of cells. In an X-FEM run the
   * work is not spread like the cells: a cell the front crosses or passes
   * near integrates a fan rule of several hundred to a few thousand points
   * with five times the DoFs of a plain cell, and the K extraction visits
   * the same cells again, so the rank that holds the front computes while
   * the others wait (the 3D assembly gained 1.3x on two ranks instead of
   * 2x, doc/performance.md). With `Partition = work` the mesh is split
   * again once the enrichment has classified its cells, so that the ranks
   * share the work evenly. A cell's work is its number of quadrature points
   * times its number of DoFs, the cost of its FEValues and of its cell
   * matrix; on the penny's fifth mesh that model is within a factor two of
   * the measured time of every kind of cell (doc/performance.md, "Where the
   * points are").
   */
  template <int dim>
  class WorkBalance
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The largest rank's share of the sum of @p work over the ranks,
     * divided by the mean share: 1 for a perfect balance. @p work is
     * indexed by active cell index and read on the locally owned cells.
     */
    static double
    imbalance(const parallel::distributed::Triangulation<dim> &triangulation,
              const std::vector<unsigned int>                 &work);

    /**
     * With `Partition = work` on more than one rank, and if @p measured
     * (imbalance() of @p work) exceeds `Imbalance tolerance`: split
     * @p triangulation again so that the ranks share @p work evenly.
     * @p before is called before the split and @p after after it: they
     * carry the data attached to the mesh (the cracks' fields). Returns whether
     * the mesh was split again; the caller then rebuilds what depends on the
     * partition. Collective.
     */
    bool
    balance(parallel::distributed::Triangulation<dim> &triangulation,
            const std::vector<unsigned int>           &work,
            const double                               measured,
            const std::function<void()>               &before,
            const std::function<void()>               &after) const;

  private:
    bool   by_work   = true;
    double tolerance = 0.05;
  };
} // namespace xcrack

#endif
