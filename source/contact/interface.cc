#include <xcrack/contact/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace Contact
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.declare_entry("Formulation",
                        "none",
                        Patterns::Selection("none|" + List::pattern()),
                        "How the crack lips touch:\n`none`: they do not "
                        "(they may pass through each other under "
                        "compression)." +
                          List::documentation());
      List::declare_parameters(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      const std::string name = prm.get("Formulation");
      if (name == "none")
        return nullptr;
      return create_plugin<dim, Interface<dim>>(name,
                                                "Contact/Formulation",
                                                prm,
                                                simulator);
    }



    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace Contact
} // namespace xcrack
