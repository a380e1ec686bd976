#ifndef xcrack_termination_criteria_interface_h
#define xcrack_termination_criteria_interface_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/plugins.h>

#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * When a fatigue run ends (`subsection Termination criteria`, a list of
   * criteria, each with its entries in its own subsection), besides
   * `Propagation/Number of steps`. Each criterion looks at the state after
   * the solve of a step, K and the moves computed (SimulatorAccess), and
   * may shorten the next advance so that the run ends on its target
   * rather than beyond it.
   */
  namespace TerminationCriteria
  {
    /// What a criterion concludes.
    struct Verdict
    {
      bool stop = false;
      /// The part fails (K_max reached K_Ic): reported as such.
      bool        failure = false;
      std::string reason;
    };



    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      /// Whether the run stops after this step, and why (collective).
      virtual Verdict
      check() = 0;

      /**
       * The largest advance of the next step, at most @p largest_advance,
       * such that the run does not overshoot the criterion's target.
       */
      virtual double
      limit_advance(const double largest_advance) const
      {
        return largest_advance;
      }

      /// How far the run is towards the criterion's target, in [0, 1] (0
      /// if it cannot tell): for the estimate of the remaining time.
      virtual double
      progress() const
      {
        return 0;
      }
    };



    /**
     * Declare the subsection `Termination criteria`: the list of criteria
     * by name and each criterion's entries.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /// The criteria the list names.
    template <int dim>
    std::vector<std::unique_ptr<Interface<dim>>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
