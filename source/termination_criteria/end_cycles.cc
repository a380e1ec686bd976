#include <xcrack/front_move.h>
#include <xcrack/input_error.h>
#include <xcrack/propagation.h>
#include <xcrack/termination_criteria/end_cycles.h>

#include <sstream>

namespace xcrack
{
  namespace TerminationCriteria
  {
    template <int dim>
    void
    EndCycles<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("End cycles");
      prm.declare_entry("Maximum cycles",
                        "0",
                        Patterns::Double(0),
                        "Load cycles at which the run ends (> 0).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    EndCycles<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "End cycles");
      maximum_cycles = prm.get_double("Maximum cycles");
      check_input(maximum_cycles > 0,
                  "Termination criteria/End cycles/Maximum cycles must be "
                  "positive with the criterion 'end cycles'.");
    }



    template <int dim>
    Verdict
    EndCycles<dim>::check()
    {
      Verdict verdict;
      if (this->get_cycles() >= maximum_cycles)
        {
          std::ostringstream reason;
          reason << "the load cycles reached Maximum cycles = "
                 << maximum_cycles;
          verdict.stop   = true;
          verdict.reason = reason.str();
        }
      return verdict;
    }



    template <int dim>
    double
    EndCycles<dim>::limit_advance(const double largest_advance) const
    {
      const FrontMove<dim> *f =
        Propagation<dim>::fastest(this->get_front_moves());
      if (!f || std::isinf(f->rate))
        return largest_advance;
      return std::min(largest_advance,
                      (maximum_cycles - this->get_cycles()) * f->rate);
    }

    template <int dim>
    double
    EndCycles<dim>::progress() const
    {
      return std::min(this->get_cycles() / maximum_cycles, 1.);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           EndCycles,
                           "end cycles",
                           "the load cycles reach Maximum cycles (subsection "
                           "End cycles).")
  } // namespace TerminationCriteria
} // namespace xcrack
