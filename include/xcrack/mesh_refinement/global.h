#ifndef xcrack_mesh_refinement_global_h
#define xcrack_mesh_refinement_global_h

#include <xcrack/mesh_refinement/interface.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    /// `global`: every cell is split (uniform refinement, for convergence
    /// studies).
    template <int dim>
    class Global : public Interface<dim>
    {
    public:
      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
