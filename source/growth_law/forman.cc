#include <xcrack/growth_law/forman.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace xcrack
{
  namespace GrowthLaw
  {
    template <int dim>
    void
    Forman<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Forman");
      {
        PowerLawConstants::declare_parameters(prm,
                                              "1e-9",
                                              "(stress intensity)^(m - 1)");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Forman<dim>::parse_parameters(ParameterHandler &prm)
    {
      {
        const Plugins::ScopedSubsection scope(prm, "Forman");
        constants.parse_parameters(prm, "Forman");
      }
      toughness = this->get_material().fracture_toughness;
      check_input(toughness > 0,
                  "Propagation/Growth law/Model name = forman needs the "
                  "fracture toughness: set Material/Fracture toughness "
                  "(K_Ic > 0).");
    }



    template <int dim>
    double
    Forman<dim>::rate(const double delta_k,
                      const double,
                      const double load_ratio) const
    {
      if (delta_k <= constants.threshold)
        return 0.;
      const double r           = std::max(load_ratio, 0.);
      const double denominator = (1 - r) * toughness - delta_k;
      return (denominator <= 0 ?
                std::numeric_limits<double>::infinity() :
                constants.c * std::pow(delta_k, constants.m) / denominator);
    }

    template <int dim>
    std::string
    Forman<dim>::why_no_rate(const double delta_k,
                             const double k_max,
                             const double load_ratio) const
    {
      const double r = std::max(load_ratio, 0.);
      if (delta_k < (1 - r) * toughness)
        return Interface<dim>::why_no_rate(delta_k, k_max, load_ratio);
      std::ostringstream words;
      words << "Delta K reached (1 - R) K_Ic = " << (1 - r) * toughness
            << " (K_max reached the fracture toughness K_Ic = " << toughness
            << "): the part fails";
      return words.str();
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Forman,
                           "forman",
                           "da/dN = C Delta K^m / ((1 - R) K_Ic - Delta K) "
                           "above a threshold (subsection Forman; needs "
                           "Material/Fracture toughness).")
  } // namespace GrowthLaw
} // namespace xcrack
