#include <xcrack/growth_law/quasi_static.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>

#include <cmath>

namespace xcrack
{
  namespace GrowthLaw
  {
    template <int dim>
    void
    QuasiStatic<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Quasi-static");
      prm.declare_entry("Exponent",
                        "2",
                        Patterns::Double(0),
                        "n: a point advances in proportion to (K_eq / "
                        "K_Ic)^n, the most loaded one by Maximum advance.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    QuasiStatic<dim>::parse_parameters(ParameterHandler &prm)
    {
      {
        const Plugins::ScopedSubsection scope(prm, "Quasi-static");
        exponent = prm.get_double("Exponent");
      }
      // The load factor K_Ic / max K_eq (Propagation) needs it.
      check_input(this->get_material().fracture_toughness > 0,
                  "Propagation/Growth law/Model name = quasi-static needs "
                  "the fracture toughness: set Material/Fracture toughness "
                  "(K_Ic > 0).");
    }



    template <int dim>
    double
    QuasiStatic<dim>::rate(const double, const double k_max, const double) const
    {
      // k_max relative to the step's largest (counts_cycles()).
      return std::pow(std::max(k_max, 0.), exponent);
    }



    template <int dim>
    bool
    QuasiStatic<dim>::counts_cycles() const
    {
      return false;
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           QuasiStatic,
                           "quasi-static",
                           "no cycles: the load at which the most loaded "
                           "point reaches K_Ic, advances in proportion to "
                           "(K_eq / K_Ic)^n (subsection Quasi-static; needs "
                           "Material/Fracture toughness).")
  } // namespace GrowthLaw
} // namespace xcrack
