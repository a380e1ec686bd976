#ifndef xcrack_termination_criteria_fracture_toughness_h
#define xcrack_termination_criteria_fracture_toughness_h

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    /**
     * `fracture toughness`: the part fails once the equivalent K at the
     * maximum of the load cycle reaches the fracture toughness K_Ic
     * (Material/Fracture toughness) at some front point. Reported as a
     * failure.
     */
    template <int dim>
    class FractureToughness : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      void
      parse_parameters(ParameterHandler &prm) override;

      Verdict
      check() override;
    };
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
