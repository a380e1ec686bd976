#include <xcrack/contact/interface.h>
#include <xcrack/input_error.h>
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
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(),
                        "Coulomb's mu on the lips (>= 0; 0: frictionless): "
                        "closed lips stick while their tangential traction "
                        "is below mu times their pressure, and slip against "
                        "it at that value. The systems of slipping lips are "
                        "not symmetric (Linear solver/Type = direct or "
                        "gmres amg).");
      List::declare_parameters(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      const std::string name     = prm.get("Formulation");
      const double      friction = prm.get_double("Friction coefficient");
      check_input(friction >= 0,
                  "Contact/Friction coefficient = " +
                    prm.get("Friction coefficient") +
                    ": must be zero (frictionless) or positive.");
      check_input(friction == 0 || name != "none",
                  "Contact/Friction coefficient = " +
                    prm.get("Friction coefficient") +
                    " with Contact/Formulation = none: lips that do not "
                    "touch cannot rub; choose a formulation.");
      if (name == "none")
        return nullptr;
      std::unique_ptr<Interface<dim>> formulation =
        create_plugin<dim, Interface<dim>>(name,
                                           "Contact/Formulation",
                                           prm,
                                           simulator);
      formulation->friction = friction;
      return formulation;
    }



    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace Contact
} // namespace xcrack
