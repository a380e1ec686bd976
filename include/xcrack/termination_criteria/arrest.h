#ifndef xcrack_termination_criteria_arrest_h
#define xcrack_termination_criteria_arrest_h

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    /**
     * `arrest`: the run ends when no front point grows any more (Delta K at
     * or below the growth law's threshold everywhere).
     */
    template <int dim>
    class Arrest : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      Verdict
      check() override;
    };
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
