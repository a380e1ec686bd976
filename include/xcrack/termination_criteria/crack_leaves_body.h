#ifndef xcrack_termination_criteria_crack_leaves_body_h
#define xcrack_termination_criteria_crack_leaves_body_h

#include <xcrack/simulator_access.h>
#include <xcrack/termination_criteria/interface.h>

#include <vector>

namespace xcrack
{
  namespace TerminationCriteria
  {
    /**
     * `crack leaves body`: the run ends when a 2D tip would be moved out of
     * the body by the next advance, or to within its cell of the body's
     * surface along its direction (a ligament the Q1 level sets cut
     * through: the piece it holds would come loose and the system be
     * singular), or when a crack's fronts change in number (a tip or a
     * piece of front reached the surface and the body is split; or, in 2D,
     * the crack gained a piece that the level sets made inside the body).
     *
     * One change in number goes on by default: a 3D front that splits
     * into open fronts, each ending on the body's surface, is a surface
     * crack that broke through the back wall; it grows on as a through
     * crack, K at every front (`Through crack = stop` ends the run there,
     * as a leak-before-break assessment does). A new closed front would be
     * a piece of crack inside the body, and more than two fronts from each
     * the crack started with the fields losing it: both end the run.
     */
    template <int dim>
    class CrackLeavesBody : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      Verdict
      check() override;

      /// The fronts counted at the first check: a resumed run compares
      /// with the run's start, not with the step it resumes at.
      void
      save(Plugins::State &state) const override;

      void
      load(const Plugins::State &state) override;

      /**
       * The steps done against those done plus those left until the first
       * front point reaches the boundary (holes included), if each point
       * keeps its direction and its advance per step (points already on
       * the boundary, such as the ends of a surface crack's front, are
       * left out). Collective.
       */
      double
      progress() const override;

    private:
      /// The number of fronts of each crack at the first check, and after
      /// each break-through.
      std::vector<unsigned int> n_fronts;

      /// The number of fronts of each crack at the first check.
      std::vector<unsigned int> initial_fronts;

      /// `Through crack = stop`.
      bool stop_at_through_crack = false;
    };
  } // namespace TerminationCriteria
} // namespace xcrack

#endif
