#include <xcrack/front_move.h>
#include <xcrack/termination_criteria/arrest.h>

namespace xcrack
{
  namespace TerminationCriteria
  {
    template <int dim>
    Verdict
    Arrest<dim>::check()
    {
      Verdict     verdict;
      const auto &moves = this->get_front_moves();
      bool        grows = false;
      for (const FrontMove<dim> &m : moves)
        grows = grows || m.rate > 0;
      if (!moves.empty() && !grows)
        {
          verdict.stop   = true;
          verdict.reason = "arrest: Delta K is at or below the growth law's "
                           "threshold at every front point";
        }
      return verdict;
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Arrest,
                           "arrest",
                           "no front point grows any more (Delta K at or "
                           "below the threshold everywhere).")
  } // namespace TerminationCriteria
} // namespace xcrack
