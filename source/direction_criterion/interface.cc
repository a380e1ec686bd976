#include <xcrack/direction_criterion/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace DirectionCriterion
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.declare_entry("Model name",
                        "max hoop stress",
                        Patterns::Selection(List::pattern()),
                        "The direction in which each front point kinks:" +
                          List::documentation());
      List::declare_parameters(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      return create_plugin<dim, Interface<dim>>(
        prm.get("Model name"),
        "Propagation/Direction criterion/Model name",
        prm,
        simulator);
    }



    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace DirectionCriterion
} // namespace xcrack
