#include <xcrack/input_error.h>
#include <xcrack/load_cycle.h>
#include <xcrack/material.h>
#include <xcrack/propagation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  template <int dim>
  void
  Propagation<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Propagation");
    {
      prm.declare_entry(
        "Number of steps",
        "0",
        Patterns::Integer(0),
        "Propagation steps after the first solve (0: a static analysis). A "
        "termination criterion may stop the run earlier.");
      prm.declare_entry(
        "Maximum advance",
        "0",
        Patterns::Double(),
        "The advance of the fastest point of all fronts in one step, in "
        "length units (> 0 with Number of steps > 0). The cycles and the "
        "path converge as it shrinks; where the crack turns, keep it at "
        "least the crowns' outer radius (Fracture parameters/Crown radii): "
        "a kink shorter than the crowns is read wrong.");
      LoadCycle<dim>::declare_parameters(prm);
      prm.declare_entry(
        "Equivalent K",
        "energy release rate",
        Patterns::Selection("energy release rate|criterion"),
        "K_eq of a front point: sqrt(E' G), G = (K_I^2 + K_II^2) / E' + "
        "K_III^2 / (2 mu) from the extracted K's (all three modes), or the "
        "direction criterion's own (with Mode III).");
      prm.declare_entry("Mode III",
                        "ignored",
                        Patterns::Selection("ignored|added"),
                        "With Equivalent K = criterion: whether K_III adds "
                        "K_III^2 / (1 - nu) to K_eq^2 (as the energy "
                        "release rate does). Mode III never twists the "
                        "front.");
      prm.declare_entry(
        "Direction integration",
        "explicit",
        Patterns::Selection("explicit|predictor-corrector"),
        "explicit: each step kinks by the direction criterion's angle at "
        "its start; the path converges slowly as the advance shrinks where "
        "the crack turns. predictor-corrector: a trial step is solved, and "
        "the kink is the mean of the angle at the start and the one the "
        "trial front asks for (trapezoidal rule; one more solve and K "
        "extraction per step).");
      prm.enter_subsection("Direction criterion");
      DirectionCriterion::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Growth law");
      GrowthLaw::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Level set update");
      LevelSetUpdate::declare_parameters(prm);
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Propagation<dim>::parse_parameters(ParameterHandler &prm)
  {
    const Plugins::ScopedSubsection scope(prm, "Propagation");
    steps             = prm.get_integer("Number of steps");
    advance           = prm.get_double("Maximum advance");
    equivalent_k_type = (prm.get("Equivalent K") == "criterion" ?
                           EquivalentK::criterion :
                           EquivalentK::energy_release_rate);
    add_mode_III      = (prm.get("Mode III") == "added");
    predictor_corrector =
      (prm.get("Direction integration") == "predictor-corrector");
    check_input(steps == 0 || advance > 0,
                "Propagation/Maximum advance = " + prm.get("Maximum advance") +
                  ": must be positive when Number of steps > 0.");
    // The plugins only when the cracks grow: a static analysis need not
    // give a growth law its constants.
    if (steps == 0)
      return;
    const Simulator<dim> &simulator = this->get_simulator();
    {
      const Plugins::ScopedSubsection s(prm, "Direction criterion");
      direction_criterion = DirectionCriterion::create<dim>(prm, simulator);
    }
    {
      const Plugins::ScopedSubsection s(prm, "Growth law");
      growth_law = GrowthLaw::create<dim>(prm, simulator);
    }
    {
      const Plugins::ScopedSubsection s(prm, "Level set update");
      level_set_update = LevelSetUpdate::create<dim>(prm, simulator);
      level_set_update->check_advance(advance);
    }
  }



  template <int dim>
  bool
  Propagation<dim>::enabled() const
  {
    return steps > 0;
  }



  template <int dim>
  unsigned int
  Propagation<dim>::n_steps() const
  {
    return steps;
  }



  template <int dim>
  double
  Propagation<dim>::maximum_advance() const
  {
    return advance;
  }



  template <int dim>
  bool
  Propagation<dim>::counts_cycles() const
  {
    return growth_law && growth_law->counts_cycles();
  }



  template <int dim>
  double
  Propagation<dim>::equivalent_k(const double k_I,
                                 const double k_II,
                                 const double k_III) const
  {
    // Of degree one in the K's: computed on K's scaled by a power of two
    // (exact), so that their squares neither underflow nor overflow.
    const int    e  = binary_exponent({{k_I, k_II, k_III}});
    const double kI = std::scalbn(k_I, -e), kII = std::scalbn(k_II, -e),
                 kIII        = std::scalbn(k_III, -e);
    const Material &material = this->get_material();
    if (equivalent_k_type == EquivalentK::energy_release_rate)
      // sqrt(E' G), G by Irwin's relation (E' / (2 mu) = 1 / (1 - nu) in
      // plane strain and 3D).
      return std::scalbn(std::sqrt(kI * kI + kII * kII +
                                   material.e_prime(dim) / (2 * material.mu()) *
                                     kIII * kIII),
                         e);
    const double k = direction_criterion->equivalent_k(kI, kII);
    return std::scalbn(add_mode_III ?
                         std::sqrt(k * k +
                                   kIII * kIII / (1 - material.poisson_ratio)) :
                         k,
                       e);
  }



  template <int dim>
  int
  Propagation<dim>::binary_exponent(const std::array<double, 3> &k)
  {
    const double largest =
      std::max({std::abs(k[0]), std::abs(k[1]), std::abs(k[2])});
    return (largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0);
  }



  template <int dim>
  std::vector<FrontMove<dim>>
  Propagation<dim>::moves(const std::vector<FrontValues<dim>> &maximum,
                          const std::vector<FrontValues<dim>> &minimum,
                          const std::vector<unsigned int>     &fronts_per_crack,
                          const double largest_advance) const
  {
    Assert(enabled(), ExcInternalError());
    AssertDimension(maximum.size(), minimum.size());
    std::vector<FrontMove<dim>> result;
    for (unsigned int i = 0; i < maximum.size(); ++i)
      {
        const FrontValues<dim> &v = maximum[i];
        const FrontValues<dim> &w = minimum[i];
        FrontMove<dim>          m;
        m.front = v.front;
        while (m.crack < fronts_per_crack.size() &&
               m.front >= fronts_per_crack[m.crack])
          m.front -= fronts_per_crack[m.crack++];
        m.point = v.point;
        // A closed crack carries no K_I (without contact, a negative K_I
        // is lips passing through each other; with contact, a closed
        // point's K_I is the error of its lip term).
        const auto k_I_of = [](const FrontValues<dim> &values) {
          return (values.closed ? 0. : std::max(values.k_I, 0.));
        };
        const double kI = k_I_of(v);
        // The kink angle is of degree zero in the K's: on scaled ones.
        const int e = binary_exponent({{kI, v.k_II, 0.}});
        m.angle     = direction_criterion->kink_angle(std::scalbn(kI, -e),
                                                  std::scalbn(v.k_II, -e));
        if (std::abs(m.angle) < minimum_kink_angle)
          m.angle = 0;
        m.k_minimum = {{w.k_I, w.k_II, w.k_III}};
        m.k_eq      = equivalent_k(kI, v.k_II, v.k_III);
        // The range over the cycle, mode by mode: of a proportional cycle
        // with R >= 0 it is (1 - R) K_eq, as the equivalent K is of
        // degree one in the K's.
        m.delta_k = std::abs(
          equivalent_k(kI - k_I_of(w), v.k_II - w.k_II, v.k_III - w.k_III));
        // Without contact, closed lips have passed through each other:
        // the K's there are those of a body that does not exist, and the
        // point does not grow (contact computes such points properly).
        m.closed = v.closed && !this->lips_in_contact();
        if (m.closed)
          m.angle = 0;
        result.push_back(m);
      }
    // Speeds relative to the most loaded point's, when they are only that
    // (a law that does not count cycles): on K's relative to the largest,
    // so that a large exponent does not underflow everywhere.
    double k_scale = 0;
    for (const FrontMove<dim> &m : result)
      if (!m.closed)
        k_scale = std::max(k_scale, m.k_eq);
    const double scale = (counts_cycles() || k_scale == 0 ? 1. : k_scale);
    for (FrontMove<dim> &m : result)
      m.rate = (m.closed ? 0. :
                           growth_law->rate(m.delta_k / scale,
                                            m.k_eq / scale,
                                            load_ratio_of(m)));
    scale_advances(result, largest_advance);
    return result;
  }



  template <int dim>
  std::string
  Propagation<dim>::why_no_rate(const FrontMove<dim> &move) const
  {
    return growth_law->why_no_rate(move.delta_k,
                                   move.k_eq,
                                   load_ratio_of(move));
  }



  template <int dim>
  double
  Propagation<dim>::load_ratio_of(const FrontMove<dim> &move)
  {
    return (move.k_eq > 0 ? 1 - move.delta_k / move.k_eq : 0.);
  }



  template <int dim>
  void
  Propagation<dim>::scale_advances(std::vector<FrontMove<dim>> &moves,
                                   const double                 largest)
  {
    const FrontMove<dim> *f        = fastest(moves);
    const double          rate_max = (f ? f->rate : 0.);
    for (FrontMove<dim> &m : moves)
      m.advance = (rate_max == 0        ? 0. :
                   std::isinf(rate_max) ? (std::isinf(m.rate) ? largest : 0.) :
                                          largest * m.rate / rate_max);
  }



  template <int dim>
  const FrontMove<dim> *
  Propagation<dim>::fastest(const std::vector<FrontMove<dim>> &moves)
  {
    const FrontMove<dim> *f = nullptr;
    for (const FrontMove<dim> &m : moves)
      if (m.rate > 0 && (!f || m.rate > f->rate))
        f = &m;
    return f;
  }



  template <int dim>
  double
  Propagation<dim>::k_eq_at(const Point<dim>                  &x,
                            const unsigned int                 crack,
                            const std::vector<FrontMove<dim>> &moves) const
  {
    // The nearest point of the polylines through the K points of each
    // front of the crack, K_eq linear between them.
    double distance = std::numeric_limits<double>::max(), k = 0;
    for (unsigned int i = 0; i < moves.size(); ++i)
      {
        if (moves[i].crack != crack)
          continue;
        const Point<dim> &a = moves[i].point.position;
        if (x.distance(a) < distance)
          {
            distance = x.distance(a);
            k        = moves[i].k_eq;
          }
        if (i + 1 < moves.size() && moves[i + 1].crack == crack &&
            moves[i + 1].front == moves[i].front)
          {
            const Point<dim>    &b    = moves[i + 1].point.position;
            const Tensor<1, dim> edge = b - a;
            if (edge.norm_square() == 0)
              continue;
            const double w =
              std::clamp((x - a) * edge / edge.norm_square(), 0., 1.);
            const Point<dim> y = a + w * edge;
            if (x.distance(y) < distance)
              {
                distance = x.distance(y);
                k        = (1 - w) * moves[i].k_eq + w * moves[i + 1].k_eq;
              }
          }
      }
    return k;
  }



  template <int dim>
  double
  Propagation<dim>::crack_cycles(
    const std::vector<FrontMove<dim>> &before_moves,
    const unsigned int                 crack,
    const std::vector<FrontMove<dim>> &now) const
  {
    const FrontMove<dim> *fast = nullptr;
    for (const FrontMove<dim> &m : before_moves)
      if (m.crack == crack && m.rate > 0 && (!fast || m.rate > fast->rate))
        fast = &m;
    if (!fast || fast->advance == 0)
      return 0;
    const FrontMove<dim> &before  = *fast;
    double                weights = 0, growth = 0;
    for (const FrontMove<dim> &m : before_moves)
      if (m.crack == crack && m.advance > 0 && m.k_eq > 0)
        {
          const double w = std::pow(m.advance / before.advance, 10);
          weights += w;
          growth += w * k_eq_at(m.new_position(), m.crack, now) / m.k_eq;
        }
    // The ratio of Delta K to K_max stays that of the step's start.
    const double r            = load_ratio_of(before);
    const double k0           = before.k_eq;
    const double k1           = k0 * growth / weights;
    const auto   inverse_rate = [&](const double t) {
      const double k    = std::sqrt((1 - t) * k0 * k0 + t * k1 * k1);
      const double rate = growth_law->rate((1 - r) * k, k, r);
      return (rate > 0 ? 1 / rate : std::numeric_limits<double>::infinity());
    };
    // 5-point Gauss-Legendre on [0, 1].
    const double x[5]     = {0.04691007703066800,
                             0.23076534494715845,
                             0.5,
                             0.76923465505284155,
                             0.95308992296933200};
    const double w[5]     = {0.11846344252809454,
                             0.23931433524968324,
                             0.28444444444444444,
                             0.23931433524968324,
                             0.11846344252809454};
    double       integral = 0;
    for (unsigned int q = 0; q < 5; ++q)
      integral += w[q] * inverse_rate(x[q]);
    // Arrest within the step (a rate of zero on the way): the cycle jump
    // of the step's start is all that can be said.
    if (std::isinf(integral))
      return before.advance / before.rate;
    return before.advance * integral;
  }



  template <int dim>
  double
  Propagation<dim>::cycles(const std::vector<FrontMove<dim>> &before_moves,
                           const std::vector<FrontMove<dim>> &now) const
  {
    const FrontMove<dim> *fast = fastest(before_moves);
    if (!counts_cycles() || !fast)
      return 0;
    return crack_cycles(before_moves, fast->crack, now);
  }



  template <int dim>
  void
  Propagation<dim>::catch_up(const std::vector<FrontMove<dim>> &before_moves,
                             const double                       delta_cycles,
                             std::vector<FrontMove<dim>>       &now) const
  {
    const FrontMove<dim> *fast_before = fastest(before_moves);
    const FrontMove<dim> *fast_now    = fastest(now);
    if (!counts_cycles() || !(delta_cycles > 0) || !fast_before)
      return;
    // The previous advances without their own catching up: that part was
    // owed from the step before and is not counted twice.
    std::vector<FrontMove<dim>> own_moves = before_moves;
    unsigned int                n_cracks  = 0;
    for (FrontMove<dim> &m : own_moves)
      {
        m.advance -= m.catch_up;
        n_cracks = std::max(n_cracks, m.crack + 1);
      }
    for (unsigned int c = 0; c < n_cracks; ++c)
      {
        // The crack of the last step's fastest point took the step's cycles
        // by definition; the one of this step's keeps the largest advance.
        if (c == fast_before->crack || (fast_now && c == fast_now->crack))
          continue;
        // The cycles crack c took for its advances, at its own rates.
        const double own = crack_cycles(own_moves, c, now);
        if (!(own > 0))
          continue;
        const double behind = delta_cycles / own - 1;
        for (FrontMove<dim> &m : now)
          {
            if (m.crack != c || m.advance == 0)
              continue;
            // The last advance of the previous point nearest to this one.
            double distance = std::numeric_limits<double>::max(), last = 0;
            for (const FrontMove<dim> &p : own_moves)
              if (p.crack == c &&
                  p.new_position().distance(m.point.position) < distance)
                {
                  distance = p.new_position().distance(m.point.position);
                  last     = p.advance;
                }
            m.catch_up = std::max(behind * last, -m.advance);
            m.advance += m.catch_up;
          }
      }
  }



  template <int dim>
  void
  Propagation<dim>::update_level_sets(const std::vector<FrontMove<dim>> &moves,
                                      LevelSetFields<dim> &fields) const
  {
    for (unsigned int c = 0; c < fields.n_cracks(); ++c)
      level_set_update->update(c, moves, fields);
  }



  template <int dim>
  bool
  Propagation<dim>::corrects_directions() const
  {
    return predictor_corrector;
  }



  template <int dim>
  void
  Propagation<dim>::correct_directions(std::vector<FrontMove<dim>>       &moves,
                                       const std::vector<FrontMove<dim>> &trial)
  {
    for (FrontMove<dim> &m : moves)
      {
        if (!(m.advance > 0))
          continue;
        const Point<dim>      x       = m.new_position();
        const FrontMove<dim> *nearest = nullptr;
        for (const FrontMove<dim> &t : trial)
          if (t.crack == m.crack &&
              (nearest == nullptr || x.distance(t.point.position) <
                                       x.distance(nearest->point.position)))
            nearest = &t;
        if (nearest != nullptr)
          m.angle += 0.5 * nearest->angle;
      }
  }



  template <int dim>
  double
  Propagation<dim>::load_factor(const std::vector<FrontMove<dim>> &moves) const
  {
    double k_max = 0;
    for (const FrontMove<dim> &m : moves)
      k_max = std::max(k_max, m.k_eq);
    const double toughness = this->get_material().fracture_toughness;
    return (k_max > 0 && toughness > 0 ? toughness / k_max : 0.);
  }



  template <int dim>
  std::vector<std::pair<std::string, Plugins::InterfaceBase *>>
  Propagation<dim>::plugins() const
  {
    if (!enabled())
      return {};
    return {{"Direction criterion", direction_criterion.get()},
            {"Growth law", growth_law.get()},
            {"Level set update", level_set_update.get()}};
  }



  template class Propagation<2>;
  template class Propagation<3>;
} // namespace xcrack
