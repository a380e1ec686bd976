#include <xcrack/growth_law/walker.h>
#include <xcrack/input_error.h>

#include <cmath>

namespace xcrack
{
  namespace GrowthLaw
  {
    template <int dim>
    void
    Walker<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Walker");
      {
        prm.declare_entry("C",
                          "1e-11",
                          Patterns::Double(),
                          "Coefficient C (> 0), in length per cycle over "
                          "(stress intensity)^m.");
        prm.declare_entry("m", "3", Patterns::Double(), "Exponent m (> 0).");
        prm.declare_entry("gamma",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Walker exponent gamma: 1 is the Paris law.");
        prm.declare_entry("Threshold",
                          "0",
                          Patterns::Double(0),
                          "Delta K_th: no growth at or below it.");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Walker<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Walker");
      c         = prm.get_double("C");
      m         = prm.get_double("m");
      gamma     = prm.get_double("gamma");
      threshold = prm.get_double("Threshold");
      check_input(c > 0,
                  "Propagation/Growth law/Walker/C = " + prm.get("C") +
                    ": must be positive.");
      check_input(m > 0,
                  "Propagation/Growth law/Walker/m = " + prm.get("m") +
                    ": must be positive.");
    }



    template <int dim>
    double
    Walker<dim>::rate(const double delta_k,
                      const double,
                      const double load_ratio) const
    {
      if (delta_k <= threshold)
        return 0.;
      // Compressive minima do not open the crack: R < 0 counts as R = 0.
      const double r = std::max(load_ratio, 0.);
      return c * std::pow(delta_k / std::pow(1 - r, 1 - gamma), m);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Walker,
                           "walker",
                           "da/dN = C [Delta K / (1 - R)^(1 - gamma)]^m "
                           "above a threshold (subsection Walker).")
  } // namespace GrowthLaw
} // namespace xcrack
