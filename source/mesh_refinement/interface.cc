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
        prm.declare_entry("Number of cycles",
                          "1",
                          Patterns::Integer(1, 50),
                          "Number of solves; the mesh is refined between two "
                          "of them.");
        prm.declare_entry("Strategy",
                          "global",
                          Patterns::Selection(List::pattern()),
                          "How the mesh is refined between cycles:" +
                            List::documentation());
        prm.declare_entry("Maximum level",
                          "12",
                          Patterns::Integer(0, 30),
                          "Cells at this refinement level are not refined "
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
        n_cycles  = prm.get_integer("Number of cycles");
        strategy  = prm.get("Strategy");
        max_level = prm.get_integer("Maximum level");
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
