#include <xcrack/simulator.h>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    mesh_refinement->mark(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell->level() >= int(refinement_parameters.max_level))
        cell->clear_refine_flag();
    triangulation.execute_coarsening_and_refinement();
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
