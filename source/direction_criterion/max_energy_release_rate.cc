#include <xcrack/direction_criterion/max_energy_release_rate.h>
#include <xcrack/fracture/kink_criteria.h>

#include <cmath>

namespace xcrack
{
  namespace DirectionCriterion
  {
    template <int dim>
    double
    MaxEnergyReleaseRate<dim>::kink_angle(const double k_I,
                                          const double k_II) const
    {
      return KinkCriteria::max_energy_release_rate_angle(k_I, k_II);
    }



    template <int dim>
    double
    MaxEnergyReleaseRate<dim>::equivalent_k(const double k_I,
                                            const double k_II) const
    {
      return std::sqrt(KinkCriteria::kinked_energy_release_rate(
        kink_angle(k_I, k_II), k_I, k_II));
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           MaxEnergyReleaseRate,
                           "max energy release rate",
                           "the largest energy release rate of a kinked "
                           "extension (Hussain, Pu and Underwood; K_eq = "
                           "sqrt(E' G)).")
  } // namespace DirectionCriterion
} // namespace xcrack
