#ifndef xcrack_direction_criterion_min_strain_energy_density_h
#define xcrack_direction_criterion_min_strain_energy_density_h

#include <xcrack/direction_criterion/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace DirectionCriterion
  {
    /**
     * `min strain energy density` (Sih 1974): the crack kinks where the
     * strain energy density factor S(theta) has its relative minimum
     * nearest the hoop-stress angle; the equivalent K is the mode-I K with
     * the same S. Depends on Poisson's ratio and the plane model (kappa),
     * which it reads from the material.
     */
    template <int dim>
    class MinStrainEnergyDensity : public Interface<dim>,
                                   public SimulatorAccess<dim>
    {
    public:
      void
      initialize() override;

      double
      kink_angle(const double k_I, const double k_II) const override;

      double
      equivalent_k(const double k_I, const double k_II) const override;

    private:
      double kappa = 1.8;
    };
  } // namespace DirectionCriterion
} // namespace xcrack

#endif
