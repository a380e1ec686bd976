#ifndef xcrack_termination_criteria_end_cycles_h
#define xcrack_termination_criteria_end_cycles_h

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    /**
     * `end cycles`: the run ends once the load cycles reach `Maximum
     * cycles` (`subsection End cycles`); the last advance is shortened so
     * that its cycle jump lands about there (the cycles are integrated
     * more accurately afterwards).
     */
    template <int dim>
    class EndCycles : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      Verdict
      check() override;

      double
      limit_advance(const double largest_advance) const override;

      double
      progress() const override;

    private:
      double maximum_cycles = 0;
    };
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
