#include <xcrack/direction_criterion/max_hoop_stress.h>
#include <xcrack/fracture/kink_criteria.h>

namespace xcrack
{
  namespace DirectionCriterion
  {
    template <int dim>
    double
    MaxHoopStress<dim>::kink_angle(const double k_I, const double k_II) const
    {
      return KinkCriteria::max_hoop_stress_angle(k_I, k_II);
    }



    template <int dim>
    double
    MaxHoopStress<dim>::equivalent_k(const double k_I, const double k_II) const
    {
      return KinkCriteria::hoop_stress_factor(kink_angle(k_I, k_II), k_I, k_II);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           MaxHoopStress,
                           "max hoop stress",
                           "the maximum tangential stress of Erdogan and Sih "
                           "(closed form; K_eq its intensity).")
  } // namespace DirectionCriterion
} // namespace xcrack
