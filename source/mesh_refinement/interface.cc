#include <xcrack/input_error.h>
#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.enter_subsection("Mesh refinement");
      {
        prm.declare_entry(
          "Number of meshes",
          "1",
          Patterns::Integer(1, 50),
          "The initial crack (step 0) is solved on this many meshes, each "
          "refined from the previous one by the Strategy: a convergence "
          "study, or a mesh fitted to the front before the cracks grow. "
          "With a Strategy that has a goal (k tolerance): the most meshes "
          "of each step, fewer once the goal is met.");
        prm.declare_entry(
          "Strategy",
          "global",
          Patterns::Selection(List::pattern()),
          "How the mesh is refined between the meshes of step 0, and after "
          "each propagation step:" +
            List::documentation());
        prm.declare_entry("Maximum level",
                          "12",
                          Patterns::Integer(0, 30),
                          "Cells at this refinement level are not refined "
                          "further.");
        prm.declare_entry(
          "Growth level",
          "0",
          Patterns::Integer(0, 30),
          "While the cracks grow, with a Strategy that follows the fronts "
          "without a goal (front): the refinement level of the cells at the "
          "fronts. 0: the finest level of step 0's last mesh, so that the "
          "fronts keep the resolution the initial crack was solved with; a "
          "larger level refines the fronts to it (at most Maximum level).");
        prm.declare_entry("Minimum level",
                          "0",
                          Patterns::Integer(0, 30),
                          "Cells at this refinement level are not coarsened "
                          "further.");
        List::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh refinement");
      {
        n_meshes     = prm.get_integer("Number of meshes");
        strategy     = prm.get("Strategy");
        max_level    = prm.get_integer("Maximum level");
        growth_level = prm.get_integer("Growth level");
        min_level    = prm.get_integer("Minimum level");
      }
      prm.leave_subsection();
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Parameters     &parameters,
           ParameterHandler     &prm,
           const Simulator<dim> &simulator)
    {
      const Plugins::ScopedSubsection scope(prm, "Mesh refinement");
      std::unique_ptr<Interface<dim>> strategy =
        create_plugin<dim, Interface<dim>>(parameters.strategy,
                                           "Mesh refinement/Strategy",
                                           prm,
                                           simulator);
      return strategy;
    }



    template std::unique_ptr<Interface<2>>
    create(const Parameters &, ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(const Parameters &, ParameterHandler &, const Simulator<3> &);
  } // namespace MeshRefinement
} // namespace xcrack
