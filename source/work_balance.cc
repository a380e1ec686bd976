#include <xcrack/work_balance.h>

#include <algorithm>
#include <boost/signals2/connection.hpp>

namespace xcrack
{
  template <int dim>
  void
  WorkBalance<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Parallel");
    {
      prm.declare_entry(
        "Partition",
        "work",
        Patterns::Selection("work|cells"),
        "How the mesh is shared among MPI ranks. cells: the same number of "
        "cells on every rank (p4est's split); work: the same work, counted "
        "as quadrature points times DoFs per cell, so that the cells along "
        "the fronts, whose rules hold hundreds of points, are spread over "
        "the ranks. Without cracks both are the same.");
      prm.declare_entry(
        "Imbalance tolerance",
        "0.05",
        Patterns::Double(0, 10),
        "Partition = work: split the mesh again only when the largest "
        "rank's work exceeds the mean by more than this fraction (a split "
        "moves cells between ranks and sets the space up again).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  WorkBalance<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Parallel");
    {
      by_work   = (prm.get("Partition") == "work");
      tolerance = prm.get_double("Imbalance tolerance");
    }
    prm.leave_subsection();
  }



  template <int dim>
  double
  WorkBalance<dim>::imbalance(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const std::vector<unsigned int>                 &work)
  {
    double local = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        local += work[cell->active_cell_index()];
    const MPI_Comm comm    = triangulation.get_communicator();
    const double   total   = Utilities::MPI::sum(local, comm);
    const double   largest = Utilities::MPI::max(local, comm);
    return total > 0 ? largest * Utilities::MPI::n_mpi_processes(comm) / total :
                       1.;
  }



  template <int dim>
  bool
  WorkBalance<dim>::balance(
    parallel::distributed::Triangulation<dim> &triangulation,
    const std::vector<unsigned int>           &work,
    const double                               measured,
    const std::function<void()>               &before,
    const std::function<void()>               &after) const
  {
    if (!by_work ||
        Utilities::MPI::n_mpi_processes(triangulation.get_communicator()) ==
          1 ||
        measured <= 1 + tolerance)
      return false;

    // Only for this split: a later refinement splits by cells again, and
    // the next set-up balances the work of the cells it classified.
    const boost::signals2::scoped_connection weights =
      triangulation.signals.weight.connect(
        [&work](const typename Triangulation<dim>::cell_iterator &cell,
                const typename Triangulation<dim>::CellStatus) {
          // Every cell weighs something: p4est splits by the prefix sums.
          return std::max(work[cell->active_cell_index()], 1u);
        });
    before();
    triangulation.repartition();
    after();
    return true;
  }



  template class WorkBalance<2>;
  template class WorkBalance<3>;
} // namespace xcrack
