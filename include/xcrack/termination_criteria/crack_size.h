#ifndef xcrack_termination_criteria_crack_size_h
#define xcrack_termination_criteria_crack_size_h

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    /**
     * `crack size`: the run ends once a crack's size, its length in 2D or
     * the area of its lips in 3D (in the body), reaches `Maximum crack
     * size` (`subsection Crack size`). The last advance is shortened so
     * that the size lands on the target: the growth of the size per unit
     * of the largest advance is the sum of the tips' advances (2D) or of
     * the advances times the front length each point stands for (3D).
     */
    template <int dim>
    class CrackSize : public Interface<dim>, public SimulatorAccess<dim>
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

      /// The initial size (the progress is measured from it).
      void
      save(Plugins::State &state) const override;

      void
      load(const Plugins::State &state) override;

    private:
      double maximum_size = 0;
      /// The largest size at the first check (for progress()).
      double initial_size = -1;
    };
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
