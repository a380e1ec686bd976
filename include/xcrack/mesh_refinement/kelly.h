#ifndef xcrack_mesh_refinement_kelly_h
#define xcrack_mesh_refinement_kelly_h

#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    /**
     * `kelly`: a fixed fraction of the cells with the largest Kelly error
     * indicator is refined, and a fraction coarsened (`subsection Kelly`).
     * The indicator reads the jumps of the gradient across faces, the
     * crack's own jump included: on a cracked body it refines the lips and
     * the energy error stops decreasing (measured on Case 1,
     * doc/verification.md), so a run with cracks says so and points to
     * `residual`, which treats the lips as boundaries. Kept for uncracked
     * bodies and for comparison.
     */
    template <int dim>
    class Kelly : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;

      /// Whether its warning was printed (once per run, resumed or not).
      void
      save(Plugins::State &state) const override;

      void
      load(const Plugins::State &state) override;

    private:
      double refine_fraction  = 0.3;
      double coarsen_fraction = 0.0;
      /// Whether the warning about cracks has been printed.
      mutable bool warned = false;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
