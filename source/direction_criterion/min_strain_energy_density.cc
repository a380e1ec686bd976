#include <xcrack/direction_criterion/min_strain_energy_density.h>
#include <xcrack/fracture/kink_criteria.h>
#include <xcrack/material.h>

#include <cmath>

namespace xcrack
{
  namespace DirectionCriterion
  {
    template <int dim>
    void
    MinStrainEnergyDensity<dim>::initialize()
    {
      kappa = this->get_material().kappa(dim);
    }



    template <int dim>
    double
    MinStrainEnergyDensity<dim>::kink_angle(const double k_I,
                                            const double k_II) const
    {
      return KinkCriteria::min_strain_energy_density_angle(k_I, k_II, kappa);
    }



    template <int dim>
    double
    MinStrainEnergyDensity<dim>::equivalent_k(const double k_I,
                                              const double k_II) const
    {
      // Mode I alone: 16 mu S = 2 (kappa - 1) K_I^2 at theta = 0.
      return std::sqrt(KinkCriteria::strain_energy_density_factor(
                         kink_angle(k_I, k_II), k_I, k_II, kappa) /
                       (2 * (kappa - 1)));
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           MinStrainEnergyDensity,
                           "min strain energy density",
                           "the relative minimum of Sih's strain energy "
                           "density factor nearest the hoop-stress angle "
                           "(K_eq: the mode-I K of equal density).")
  } // namespace DirectionCriterion
} // namespace xcrack
