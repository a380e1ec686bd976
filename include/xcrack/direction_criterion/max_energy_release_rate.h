#ifndef xcrack_direction_criterion_max_energy_release_rate_h
#define xcrack_direction_criterion_max_energy_release_rate_h

#include <xcrack/direction_criterion/interface.h>

namespace xcrack
{
  namespace DirectionCriterion
  {
    /**
     * `max energy release rate` (Hussain, Pu and Underwood 1974): the crack
     * kinks where the energy release rate of a kinked extension is
     * largest (found numerically to round-off); the equivalent K is
     * sqrt(E' G) of that extension.
     */
    template <int dim>
    class MaxEnergyReleaseRate : public Interface<dim>
    {
    public:
      double
      kink_angle(const double k_I, const double k_II) const override;

      double
      equivalent_k(const double k_I, const double k_II) const override;
    };
  } // namespace DirectionCriterion
} // namespace xcrack

#endif
