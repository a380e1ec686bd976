#include <xcrack/growth_law/interface.h>
#include <xcrack/input_error.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace GrowthLaw
  {
    void
    PowerLawConstants::declare_parameters(ParameterHandler  &prm,
                                          const std::string &default_c,
                                          const std::string &c_units)
    {
      prm.declare_entry("C",
                        default_c,
                        Patterns::Double(),
                        "Coefficient C (> 0), in length per cycle over " +
                          c_units + ".");
      prm.declare_entry("m", "3", Patterns::Double(), "Exponent m (> 0).");
      prm.declare_entry("Threshold",
                        "0",
                        Patterns::Double(0),
                        "Delta K_th: no growth at or below it.");
    }



    void
    PowerLawConstants::parse_parameters(ParameterHandler  &prm,
                                        const std::string &law)
    {
      c                       = prm.get_double("C");
      m                       = prm.get_double("m");
      threshold               = prm.get_double("Threshold");
      const std::string entry = "Propagation/Growth law/" + law + "/";
      check_input(c > 0, entry + "C = " + prm.get("C") + ": must be positive.");
      check_input(m > 0, entry + "m = " + prm.get("m") + ": must be positive.");
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.declare_entry("Model name",
                        "paris",
                        Patterns::Selection(List::pattern()),
                        "The growth rate of each front point:" +
                          List::documentation());
      List::declare_parameters(prm);
    }



    template <int dim>
    std::string
    Interface<dim>::why_no_rate(const double, const double, const double) const
    {
      return "the rate overflows (it is beyond the largest number a double "
             "holds, 1.8e308): the law's constants do not fit the scene's "
             "units";
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      return create_plugin<dim, Interface<dim>>(
        prm.get("Model name"),
        "Propagation/Growth law/Model name",
        prm,
        simulator);
    }



    template class Interface<2>;
    template class Interface<3>;
    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace GrowthLaw
} // namespace xcrack
