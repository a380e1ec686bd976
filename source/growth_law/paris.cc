#include <xcrack/growth_law/paris.h>
#include <xcrack/input_error.h>

#include <cmath>

namespace xcrack
{
  namespace GrowthLaw
  {
    template <int dim>
    void
    Paris<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Paris");
      {
        prm.declare_entry("C",
                          "1e-11",
                          Patterns::Double(),
                          "Coefficient C (> 0), in length per cycle over "
                          "(stress intensity)^m.");
        prm.declare_entry("m", "3", Patterns::Double(), "Exponent m (> 0).");
        prm.declare_entry("Threshold",
                          "0",
                          Patterns::Double(0),
                          "Delta K_th: no growth at or below it.");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Paris<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Paris");
      c         = prm.get_double("C");
      m         = prm.get_double("m");
      threshold = prm.get_double("Threshold");
      check_input(c > 0,
                  "Propagation/Growth law/Paris/C = " + prm.get("C") +
                    ": must be positive.");
      check_input(m > 0,
                  "Propagation/Growth law/Paris/m = " + prm.get("m") +
                    ": must be positive.");
    }



    template <int dim>
    double
    Paris<dim>::rate(const double delta_k, const double, const double) const
    {
      return (delta_k <= threshold ? 0. : c * std::pow(delta_k, m));
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Paris,
                           "paris",
                           "da/dN = C Delta K^m above a threshold "
                           "(subsection Paris).")
  } // namespace GrowthLaw
} // namespace xcrack
