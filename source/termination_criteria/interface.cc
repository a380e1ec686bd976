#include <deal.II/base/utilities.h>

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.enter_subsection("Termination criteria");
      {
        prm.declare_entry("Termination criteria",
                          "",
                          Patterns::MultipleSelection(List::pattern()),
                          "What ends a propagation run before Propagation/"
                          "Number of steps, a comma-separated list of:" +
                            List::documentation());
        List::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    template <int dim>
    std::vector<std::unique_ptr<Interface<dim>>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      const Plugins::ScopedSubsection scope(prm, "Termination criteria");
      std::vector<std::unique_ptr<Interface<dim>>> criteria;
      for (const std::string &name :
           Utilities::split_string_list(prm.get("Termination criteria")))
        criteria.push_back(create_plugin<dim, Interface<dim>>(
          name, "Termination criteria/Termination criteria", prm, simulator));
      return criteria;
    }



    template std::vector<std::unique_ptr<Interface<2>>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::vector<std::unique_ptr<Interface<3>>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace TerminationCriteria
} // namespace xcrack
