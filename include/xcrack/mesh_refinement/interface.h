#ifndef xcrack_mesh_refinement_interface_h
#define xcrack_mesh_refinement_interface_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <xcrack/plugins.h>

#include <memory>
#include <string>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * How the mesh changes between two solves (`subsection Mesh refinement`):
   * a strategy plugin marks cells, the Simulator caps the levels at
   * `Maximum level`, carries the state across and refines.
   */
  namespace MeshRefinement
  {
    /**
     * A refinement strategy: sets refine (and coarsen) flags on the locally
     * owned cells. It reads the solution, the cracks and the mesh through
     * SimulatorAccess.
     */
    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      virtual void
      mark(parallel::distributed::Triangulation<dim> &triangulation) const = 0;

      /**
       * Whether the strategy marks relative to the cracks' fronts and
       * reaches a fixed point when repeated: after the cracks move, the
       * Simulator then repeats it until the mesh no longer changes. Other
       * strategies leave the mesh of a growth step as the step before left
       * it (unless they have a goal, see has_goal()).
       */
      virtual bool
      follows_fronts() const
      {
        return false;
      }

      /// Whether the mesh of the last solve meets a strategy's goal, and a
      /// line that says how far it is from it.
      struct GoalStatus
      {
        bool        met = false;
        std::string text;
      };

      /**
       * Whether the strategy refines towards a goal (a tolerance): the
       * Simulator then solves each step on up to `Number of meshes` meshes
       * and stops refining as soon as check_goal() says the goal is met.
       * Strategies without a goal solve step 0 on exactly `Number of
       * meshes` meshes and every later step on one.
       */
      virtual bool
      has_goal() const
      {
        return false;
      }

      /// After a solve (for a strategy with a goal): is the goal met?
      virtual GoalStatus
      check_goal() const
      {
        return {};
      }
    };



    /**
     * The entries every strategy shares: on how many successively refined
     * meshes the initial crack is solved (step 0), which strategy marks the
     * cells, and the finest and coarsest levels allowed.
     */
    struct Parameters
    {
      /// Declare the whole subsection, the strategies' entries included.
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);

      unsigned int n_meshes  = 1;
      std::string  strategy  = "global";
      unsigned int max_level = 12;
      unsigned int min_level = 0;
      /// The level of the front cells during growth (0: step 0's finest).
      unsigned int growth_level = 0;
    };



    /// The strategy the parameters select, its own entries parsed.
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Parameters     &parameters,
           ParameterHandler     &prm,
           const Simulator<dim> &simulator);
  } // namespace MeshRefinement
} // namespace xcrack

#endif
