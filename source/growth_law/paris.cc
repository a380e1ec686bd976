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
        PowerLawConstants::declare_parameters(prm,
                                              "1e-11",
                                              "(stress intensity)^m");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Paris<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Paris");
      constants.parse_parameters(prm, "Paris");
    }



    template <int dim>
    double
    Paris<dim>::rate(const double delta_k, const double, const double) const
    {
      return (delta_k <= constants.threshold ?
                0. :
                constants.c * std::pow(delta_k, constants.m));
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Paris,
                           "paris",
                           "da/dN = C Delta K^m above a threshold "
                           "(subsection Paris).")
  } // namespace GrowthLaw
} // namespace xcrack
