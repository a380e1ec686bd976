#ifndef xcrack_propagation_h
#define xcrack_propagation_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/direction_criterion/interface.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/front_move.h>
#include <xcrack/growth_law/interface.h>
#include <xcrack/level_set_update/interface.h>
#include <xcrack/simulator_access.h>

#include <array>
#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The growth model of a fatigue run (`subsection Propagation`): from the
   * stress intensity factors along the fronts of a step to the move of
   * every front point, the load cycles that take, and the new level sets.
   *
   * Per point, from its K's at the maximum and the minimum of the load
   * cycle (LoadCycle), with K_I taken as max(K_I, 0) in each (a closed
   * crack does not open): the kink angle of the `Direction criterion` at
   * the maximum; the equivalent K at the maximum, sqrt(E' G) with Irwin's G
   * from the extracted K's (`Equivalent K = energy release rate`, mode III
   * included as the energy includes it; the interaction integral's K's are
   * more accurate than the G-theta integral, which stays a cross-check) or
   * the criterion's own (`criterion`, K_III added as K_III^2 / (1 - nu) to
   * K_eq^2 if `Mode III = added`, else ignored); its range Delta K, the same
   * equivalent K of the ranges of the three modes (for a proportional cycle
   * with R >= 0, (1 - R) K_eq; with R < 0 and no contact, the compressive
   * part of the cycle adds nothing to mode I, while K_II and K_III range
   * over the whole cycle); the rate da/dN of the `Growth law`, with the
   * point's ratio 1 - Delta K / K_max as its R. The cycle increment is the
   * one in which the fastest point of all fronts of all cracks advances
   * `Maximum advance`; every other point advances in proportion to its
   * rate.
   *
   * Mode III does not twist the front: the kink is a rotation about the
   * front's tangent. A kink below minimum_kink_angle is no kink (see
   * there).
   *
   * The cycles between two steps are integrated along the path of the
   * fastest point with K_eq^2 interpolated linearly in the advance between
   * the two solves (5-point Gauss-Legendre): exact when K grows like the
   * square root of the crack size (Griffith and penny cracks, doc/benchmarks.md
   * Case 9), second order in the advance otherwise. The plain cycle jump
   * Delta a / (da/dN) is first order.
   */
  template <int dim>
  class Propagation : public SimulatorAccess<dim>
  {
  public:
    enum class EquivalentK
    {
      energy_release_rate,
      criterion
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse the entries and create the plugins (after
    /// initialize_simulator()).
    void
    parse_parameters(ParameterHandler &prm);

    /// Whether the run propagates the cracks (Number of steps > 0).
    bool
    enabled() const;

    unsigned int
    n_steps() const;

    double
    maximum_advance() const;

    /// Whether the growth law counts load cycles (not quasi-static).
    bool
    counts_cycles() const;

    /**
     * The moves of the points of @p maximum (K at the points of every
     * front of every crack at the maximum of the load cycle, fronts
     * numbered crack after crack as in @p fronts_per_crack), whose K's at
     * the minimum are @p minimum (the same points), the fastest advancing
     * @p largest_advance.
     */
    std::vector<FrontMove<dim>>
    moves(const std::vector<FrontValues<dim>> &maximum,
          const std::vector<FrontValues<dim>> &minimum,
          const std::vector<unsigned int>     &fronts_per_crack,
          const double                         largest_advance) const;

    /// The equivalent K of the modes' K's (or ranges) @p k_I (>= 0 at a
    /// point that opens), @p k_II, @p k_III, as `Equivalent K` says.
    double
    equivalent_k(const double k_I, const double k_II, const double k_III) const;

    /// Why the growth law's rate at @p move is not finite (the growth
    /// law's words).
    std::string
    why_no_rate(const FrontMove<dim> &move) const;

    /// The load ratio a growth law sees at @p move: 1 - Delta K / K_max.
    static double
    load_ratio_of(const FrontMove<dim> &move);

    /// The binary exponent of the largest of |@p k| (0 if all are zero or
    /// one is not finite): K's scaled by 2^-exponent are near one, and
    /// their squares can be formed, however small or large the loads.
    static int
    binary_exponent(const std::array<double, 3> &k);

    /**
     * Kink angles below this (radians) are taken as zero. A symmetric
     * crack's K_II is not zero but 1e-8 to 1e-7 of K_I (round-off and the
     * tip rules' asymmetry), and its sign would tilt the tip's normal:
     * where the tip lands on a mesh line, that sign decides which vertices
     * lie ahead of it, hence the enrichment, and a run resumed on another
     * partition grew differently. 1e-5 rad moves a tip by 1e-5 of its
     * advance, far below what any K extraction resolves (its K_II carries
     * 1e-4 of K_I and more of discretisation error).
     */
    static constexpr double minimum_kink_angle = 1e-5;

    /// Scale the advances of @p moves so that the largest is @p largest.
    static void
    scale_advances(std::vector<FrontMove<dim>> &moves, const double largest);

    /// The fastest of @p moves (largest rate), or null if none moves.
    static const FrontMove<dim> *
    fastest(const std::vector<FrontMove<dim>> &moves);

    /**
     * The load cycles in which the fastest of @p before (the moves of the
     * previous step) advanced, given @p now, the moves computed at the next
     * step: along its path, from its K_eq then to that K_eq times the growth
     * of K_eq over the step. The growth is a weighted mean over the points
     * of its crack of K_eq now at a point's new position (interpolated
     * along the fronts) over its K_eq then, the weights the tenth power of
     * the points' advances relative to the fastest one's. The fastest
     * point's own ratio is biased low where K is noisy along a 3D front
     * (its K then is the largest of the noisy values, its K now is not),
     * which over-counts the cycles; the high power keeps the points whose K
     * differs by the front's shape out of the mean (on an ellipse b/a = 0.5
     * the mean is 0.25 % above the fastest point's ratio, 2.2 % with
     * weights linear in the advance).
     */
    double
    cycles(const std::vector<FrontMove<dim>> &before,
           const std::vector<FrontMove<dim>> &now) const;

    /**
     * Corrects the advances @p now of the cracks other than the fastest
     * one's by what their last advances @p before_moves missed or
     * overshot: their points advanced by the ratio of their rates to the
     * fastest point's at the start of the step (forward Euler), while the
     * step took @p delta_cycles, integrated along the fastest point's path;
     * a crack whose K grows more slowly than the fastest point's advanced
     * too far. Each point of such a crack gets, on top of its advance,
     * (delta_cycles / own - 1) times the last advance of the nearest
     * previous point (without that point's own catching up, which was owed
     * from the step before), where own is the cycles its crack's last
     * advances take at its own K's, integrated as cycles() does: the
     * cumulated growth of every crack follows its own rate, to the error of
     * the last step. The cracks of the fastest points of the last step (it
     * took those cycles) and of this one (it keeps the largest advance) are
     * left as they are.
     */
    void
    catch_up(const std::vector<FrontMove<dim>> &before_moves,
             const double                       delta_cycles,
             std::vector<FrontMove<dim>>       &now) const;

    /// Whether each step's kinks are corrected by a trial step
    /// (Direction integration = predictor-corrector).
    bool
    corrects_directions() const;

    /**
     * Predictor-corrector kinks: each point of @p moves that advances turns
     * by the mean of its own kink angle and the one that the point of
     * @p trial (the moves computed after a trial step along @p moves)
     * nearest to its new position asks for. A kink taken at the start of
     * a step lags the path (the crack's K_II changes along the segment:
     * the T-stress acts on the new direction); the mean is the trapezoidal
     * rule of the direction along the step.
     */
    static void
    correct_directions(std::vector<FrontMove<dim>>       &moves,
                       const std::vector<FrontMove<dim>> &trial);

    /// Move every crack's level sets in @p fields by @p moves.
    void
    update_level_sets(const std::vector<FrontMove<dim>> &moves,
                      LevelSetFields<dim>               &fields) const;

    /// The load factor K_Ic / max K_eq of a quasi-static step.
    double
    load_factor(const std::vector<FrontMove<dim>> &moves) const;

    /// The plugins of the growth model with their systems' names (for the
    /// checkpoint of their states); none in a static analysis.
    std::vector<std::pair<std::string, Plugins::InterfaceBase *>>
    plugins() const;

  private:
    /// The cycles in which the fastest point of crack @p crack in
    /// @p before_moves advanced, integrated as cycles() does.
    double
    crack_cycles(const std::vector<FrontMove<dim>> &before_moves,
                 const unsigned int                 crack,
                 const std::vector<FrontMove<dim>> &now) const;

    /// K_eq at @p x on the fronts of crack @p crack (moves of a step).
    double
    k_eq_at(const Point<dim>                  &x,
            const unsigned int                 crack,
            const std::vector<FrontMove<dim>> &moves) const;

    unsigned int steps               = 0;
    double       advance             = 0;
    EquivalentK  equivalent_k_type   = EquivalentK::energy_release_rate;
    bool         add_mode_III        = false;
    bool         predictor_corrector = false;
    std::unique_ptr<DirectionCriterion::Interface<dim>> direction_criterion;
    std::unique_ptr<GrowthLaw::Interface<dim>>          growth_law;
    std::unique_ptr<LevelSetUpdate::Interface<dim>>     level_set_update;
  };
} // namespace xcrack

#endif
