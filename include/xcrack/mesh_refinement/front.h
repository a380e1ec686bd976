#ifndef xcrack_mesh_refinement_front_h
#define xcrack_mesh_refinement_front_h

#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    /**
     * `front`: every cell whose centre lies within `Front band` of its own
     * diameters of a crack front is refined (`subsection Front`). The
     * refined zone shrinks with the cells, so each refinement adds cells
     * along the front only (a 3D front gets about twice as many, not eight
     * times), and the mesh grades from the front outwards. With `Coarsening
     * band` > 0 the cells farther than that many of their diameters from
     * every front are coarsened: as the cracks grow, the fine cells follow
     * the fronts and the number of cells stays bounded.
     */
    template <int dim>
    class Front : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;

      bool
      follows_fronts() const override;

    private:
      double band = 2, coarsening_band = 0;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
