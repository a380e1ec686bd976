#ifndef xcrack_mesh_refinement_residual_h
#define xcrack_mesh_refinement_residual_h

#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    /**
     * `residual`: refine where the error indicator of ResidualEstimator is
     * largest (`subsection Residual`). That indicator reads the traction
     * jumps across faces and treats the cracks as boundaries, so, unlike
     * `kelly`, it does not take the crack's opening for error: on a cracked
     * body it refines towards the fronts, and also wherever else the mesh
     * is too coarse (holes, loads, corners).
     *
     * Marking: a fixed number of cells (`fixed number`: the fractions are
     * fractions of the cells), or the fewest cells that hold the fraction
     * of the estimated squared error (`fixed fraction`, Doerfler's bulk
     * criterion, which the convergence proofs of adaptive FEM use).
     */
    template <int dim>
    class Residual : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;

    private:
      bool   fixed_fraction   = false;
      double refine_fraction  = 0.3;
      double coarsen_fraction = 0.0;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
