#include <xcrack/mesh_refinement/global.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    Global<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_refine_flag();
    }

    XCRACK_REGISTER_PLUGIN(Interface, Global, "global", "every cell is split.")
  } // namespace MeshRefinement
} // namespace xcrack
