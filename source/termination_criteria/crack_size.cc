#include <xcrack/crack/crack_surface.h>
#include <xcrack/front_move.h>
#include <xcrack/input_error.h>
#include <xcrack/termination_criteria/crack_size.h>

#include <algorithm>
#include <sstream>

namespace xcrack
{
  namespace TerminationCriteria
  {
    template <int dim>
    void
    CrackSize<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Crack size");
      prm.declare_entry("Maximum crack size",
                        "0",
                        Patterns::Double(0),
                        "Length (2D) or lip area (3D) of a crack in the body "
                        "at which the run ends (> 0).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    CrackSize<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Crack size");
      maximum_size = prm.get_double("Maximum crack size");
      check_input(maximum_size > 0,
                  "Termination criteria/Crack size/Maximum crack size must "
                  "be positive with the criterion 'crack size'.");
    }



    template <int dim>
    Verdict
    CrackSize<dim>::check()
    {
      Verdict     verdict;
      const auto &surfaces = this->get_crack_surfaces();
      if (initial_size < 0)
        for (const auto &surface : surfaces)
          initial_size = std::max(initial_size, surface.measure());
      // Within 1e-6 counts as reached: the last step aims at the maximum,
      // but the measure of the moved fields misses it by round-off of the
      // level sets (a step of 5e-11 followed one that ended 2.6e-8 short).
      for (unsigned int c = 0; c < surfaces.size(); ++c)
        if (surfaces[c].measure() >= maximum_size * (1 - 1e-6))
          {
            std::ostringstream reason;
            reason << "crack " << c + 1 << " reached the Maximum crack size "
                   << maximum_size << " (" << (dim == 2 ? "length " : "area ")
                   << surfaces[c].measure() << ")";
            verdict.stop   = true;
            verdict.reason = reason.str();
            break;
          }
      return verdict;
    }



    template <int dim>
    double
    CrackSize<dim>::limit_advance(const double largest_advance) const
    {
      const auto &surfaces = this->get_crack_surfaces();
      const auto &moves    = this->get_front_moves();
      double      largest  = 0;
      for (const FrontMove<dim> &m : moves)
        largest = std::max(largest, m.advance);
      if (largest == 0)
        return largest_advance;
      double limit = largest_advance;
      for (unsigned int c = 0; c < surfaces.size(); ++c)
        {
          // d(size) / d(largest advance): each point's share of the front
          // (half the distance to its neighbours along it) in 3D.
          double growth = 0;
          for (unsigned int i = 0; i < moves.size(); ++i)
            {
              if (moves[i].crack != c)
                continue;
              double share = 1;
              if (dim == 3)
                {
                  share = 0;
                  for (const int j : {int(i) - 1, int(i) + 1})
                    if (j >= 0 && j < int(moves.size()) &&
                        moves[j].crack == c && moves[j].front == moves[i].front)
                      share +=
                        0.5 * std::abs(moves[j].point.s - moves[i].point.s);
                }
              growth += share * moves[i].advance / largest;
            }
          if (growth > 0)
            limit =
              std::min(limit, (maximum_size - surfaces[c].measure()) / growth);
        }
      return std::max(limit, 0.);
    }

    template <int dim>
    double
    CrackSize<dim>::progress() const
    {
      double size = 0;
      for (const auto &surface : this->get_crack_surfaces())
        size = std::max(size, surface.measure());
      if (initial_size < 0 || maximum_size <= initial_size)
        return 0;
      return std::clamp((size - initial_size) / (maximum_size - initial_size),
                        0.,
                        1.);
    }

    template <int dim>
    void
    CrackSize<dim>::save(Plugins::State &state) const
    {
      state["initial size"] = Plugins::pack(initial_size);
    }



    template <int dim>
    void
    CrackSize<dim>::load(const Plugins::State &state)
    {
      initial_size = Plugins::unpack(state, "initial size", initial_size);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           CrackSize,
                           "crack size",
                           "a crack's length (2D) or area (3D) reaches Maximum "
                           "crack size (subsection Crack size).")
  } // namespace TerminationCriteria
} // namespace xcrack
