#include <xcrack/simulator.h>

namespace xcrack
{
  template <int dim>
  bool
  Simulator<dim>::execute_refinement()
  {
    bool marked = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->refine_flag_set() &&
              cell->level() >= int(refinement_parameters.max_level))
            cell->clear_refine_flag();
          if (cell->coarsen_flag_set() &&
              cell->level() <= int(refinement_parameters.min_level))
            cell->clear_coarsen_flag();
          marked =
            marked || cell->refine_flag_set() || cell->coarsen_flag_set();
        }
    if (!Utilities::MPI::logical_or(marked, mpi_communicator))
      return false;
    // The cracks' fields follow the mesh (before the cracks move, the next
    // set-up interpolates their shapes again).
    triangulation.prepare_coarsening_and_refinement();
    if (enrichment)
      level_sets.prepare_for_coarsening_and_refinement();
    triangulation.execute_coarsening_and_refinement();
    if (enrichment)
      level_sets.interpolate();
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    mesh_refinement->mark(triangulation);
    execute_refinement();
  }



  template <int dim>
  void
  Simulator<dim>::adapt_mesh_to_fronts()
  {
    // A strategy that does not follow the fronts (global, kelly, region)
    // leaves the mesh as it is once the cracks grow.
    if (!mesh_refinement->follows_fronts())
      return;
    // One level per pass, until the marking reaches a fixed point.
    for (unsigned int pass = 0; pass <= refinement_parameters.max_level + 1;
         ++pass)
      {
        mesh_refinement->mark(triangulation);
        if (!execute_refinement())
          break;
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
