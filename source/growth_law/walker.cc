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
        PowerLawConstants::declare_parameters(prm,
                                              "1e-11",
                                              "(stress intensity)^m");
        prm.declare_entry("gamma",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Walker exponent gamma: 1 is the Paris law.");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Walker<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Walker");
      constants.parse_parameters(prm, "Walker");
      gamma = prm.get_double("gamma");
    }



    template <int dim>
    double
    Walker<dim>::rate(const double delta_k,
                      const double,
                      const double load_ratio) const
    {
      if (delta_k <= constants.threshold)
        return 0.;
      // Compressive minima do not open the crack: R < 0 counts as R = 0.
      const double r = std::max(load_ratio, 0.);
      return constants.c *
             std::pow(delta_k / std::pow(1 - r, 1 - gamma), constants.m);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Walker,
                           "walker",
                           "da/dN = C [Delta K / (1 - R)^(1 - gamma)]^m "
                           "above a threshold (subsection Walker).")
  } // namespace GrowthLaw
} // namespace xcrack
