#ifndef xcrack_direction_criterion_max_hoop_stress_h
#define xcrack_direction_criterion_max_hoop_stress_h

#include <xcrack/direction_criterion/interface.h>

namespace xcrack
{
  namespace DirectionCriterion
  {
    /**
     * `max hoop stress` (Erdogan and Sih 1963): the crack kinks where the
     * tangential stress ahead of the tip is largest, in closed form; the
     * equivalent K is that stress's intensity. The usual choice, and the
     * one the seed and Code_Aster default to.
     */
    template <int dim>
    class MaxHoopStress : public Interface<dim>
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
