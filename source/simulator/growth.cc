#include <xcrack/simulator.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>

namespace xcrack
{
  template <int dim>
  std::vector<unsigned int>
  Simulator<dim>::fronts_per_crack() const
  {
    std::vector<unsigned int> n;
    for (const auto &surface : crack_surfaces)
      n.push_back(surface.fronts().size());
    return n;
  }



  template <int dim>
  bool
  Simulator<dim>::grow()
  {
    // The moves at the nominal advance, and the cycles the last advance
    // took (known now that K at its end is).
    front_moves = propagation.moves(front_values,
                                    minimum_front_values(),
                                    fronts_per_crack(),
                                    propagation.maximum_advance());
    // A tip or front that vanished in the last advance (it ran out of the
    // body or into a hole) ends the run whatever the criteria: the cycles
    // of that advance cannot be told without K at its end.
    TerminationCriteria::Verdict verdict      = check_vanished_fronts();
    double                       delta_cycles = 0;
    if (!previous_moves.empty() && !verdict.stop)
      {
        delta_cycles = propagation.cycles(previous_moves, front_moves);
        cycles += delta_cycles;
      }
    statistics.add_value("cycles", cycles);
    count_unreliable_cycles(delta_cycles);

    // What ends the run, if anything; else how far the next step may go.
    double largest = propagation.maximum_advance();
    if (!verdict.stop)
      verdict = step_verdict(largest);
    Propagation<dim>::scale_advances(front_moves, verdict.stop ? 0. : largest);
    if (!verdict.stop)
      {
        propagation.catch_up(previous_moves, delta_cycles, front_moves);
        previous_moves = front_moves;
      }
    report_step(verdict, delta_cycles, largest);
    return verdict.stop;
  }



  template <int dim>
  void
  Simulator<dim>::count_unreliable_cycles(const double delta_cycles)
  {
    // The cycles of an advance rest on the K's at both of its ends: this
    // step's last solve (this row) and the previous step's.
    const auto flagged = [&](const unsigned int row) {
      return statistics.get("unreliable_points", row) > 0;
    };
    const unsigned int this_row         = statistics.n_rows() - 1;
    double             before           = 0;
    bool               rests_on_flagged = flagged(this_row);
    for (unsigned int row = this_row; row-- > 0;)
      if (statistics.get("step", row) + 1 == step)
        {
          before           = statistics.get("unreliable_cycles", row);
          before           = (std::isnan(before) ? 0. : before);
          rests_on_flagged = rests_on_flagged || flagged(row);
          break;
        }
    statistics.add_value("unreliable_cycles",
                         before + (rests_on_flagged ? delta_cycles : 0.));
  }



  template <int dim>
  void
  Simulator<dim>::report_unreliable()
  {
    // Which solves have flagged points (their keys, as the files name
    // them) and why.
    std::vector<std::string> keys, reasons;
    unsigned long long       n_points = 0;
    for (unsigned int row = 0; row < statistics.n_rows(); ++row)
      if (statistics.get("unreliable_points", row) > 0)
        {
          keys.push_back(solve_key((unsigned int)statistics.get("step", row),
                                   (unsigned int)statistics.get("mesh", row)));
          n_points +=
            (unsigned long long)statistics.get("unreliable_points", row);
          for (const std::string &why :
               Utilities::split_string_list(statistics.text("reason", row),
                                            ';'))
            if (std::find(reasons.begin(), reasons.end(), why) == reasons.end())
              reasons.push_back(why);
        }
    double unreliable_cycles = 0;
    if (propagation.enabled() && propagation.counts_cycles() &&
        statistics.n_rows() > 0)
      {
        unreliable_cycles =
          statistics.get("unreliable_cycles", statistics.n_rows() - 1);
        unreliable_cycles =
          (std::isnan(unreliable_cycles) ? 0. : unreliable_cycles);
      }
    run_record->set_unreliable(keys, n_points, reasons, unreliable_cycles);
    if (propagation.enabled() && propagation.counts_cycles())
      run_record->set_cycles(cycles);
    if (keys.empty())
      return;

    std::ostringstream text;
    text << "Unreliable: " << n_points << " front point"
         << (n_points > 1 ? "s" : "") << " in " << keys.size() << " of "
         << statistics.n_rows() << " solves (";
    for (unsigned int k = 0; k < keys.size(); ++k)
      text << (k > 0 ? ", " : "") << keys[k];
    text << "):";
    for (unsigned int r = 0; r < reasons.size(); ++r)
      text << (r > 0 ? ";" : "") << " " << reasons[r];
    text << " (`unreliable` and `reason` in the front files and "
            "statistics.csv).";
    if (unreliable_cycles > 0)
      text << std::scientific << std::setprecision(4) << " Of the " << cycles
           << " cycles, " << unreliable_cycles << " (" << std::fixed
           << std::setprecision(1) << 100 * unreliable_cycles / cycles
           << " %) rest on the K of these steps.";
    pcout << text.str() << std::endl;
  }



  template <int dim>
  TerminationCriteria::Verdict
  Simulator<dim>::step_verdict(double &largest) const
  {
    TerminationCriteria::Verdict verdict = check_rates();
    for (const auto &criterion : termination_criteria)
      if (!verdict.stop)
        verdict = criterion->check();
    if (!verdict.stop && step >= propagation.n_steps())
      {
        verdict.stop   = true;
        verdict.reason = "the last step (Propagation/Number of steps = " +
                         std::to_string(propagation.n_steps()) + ")";
      }
    if (verdict.stop)
      return verdict;
    for (const auto &criterion : termination_criteria)
      largest = std::min(largest, criterion->limit_advance(largest));
    unsigned int n_closed = 0, n_loaded = 0;
    for (const FrontMove<dim> &m : front_moves)
      {
        n_closed += m.closed;
        n_loaded += (m.k_eq > 0);
      }
    if (!Propagation<dim>::fastest(front_moves))
      {
        verdict.stop   = true;
        verdict.reason = "no front point grows any more";
        if (n_closed > 0 && n_closed == front_moves.size())
          verdict.reason += " (K_I < 0 everywhere: the lips are closed; set "
                            "Contact/Formulation to let them touch)";
        else if (n_loaded > 0)
          verdict.reason += " (every rate is zero: Delta K is below the "
                            "growth law's threshold, or the rate below the "
                            "smallest number a double holds)";
      }
    else if (!(largest > 0))
      {
        verdict.stop   = true;
        verdict.reason = "no front point grows any more";
      }
    return verdict;
  }



  template <int dim>
  void
  Simulator<dim>::report_step(const TerminationCriteria::Verdict &verdict,
                              const double                        delta_cycles,
                              const double                        largest)
  {
    double size = 0, k_max = 0, delta_k = 0;
    for (const auto &surface : crack_surfaces)
      size += surface.measure();
    for (const FrontMove<dim> &m : front_moves)
      {
        k_max   = std::max(k_max, m.k_eq);
        delta_k = std::max(delta_k, m.delta_k);
      }
    statistics.add_value("K_max", k_max);
    statistics.add_value("delta_K", delta_k);
    statistics.add_value("delta_cycles", delta_cycles);
    statistics.add_value("advance", verdict.stop ? 0. : largest);
    if (!propagation.counts_cycles())
      statistics.add_value("load_factor", propagation.load_factor(front_moves));

    // One line per step.
    std::ostringstream line;
    line << "Step " << step << ": " << std::scientific << std::setprecision(4);
    if (propagation.counts_cycles())
      line << "N = " << cycles << " (+" << std::setprecision(3) << delta_cycles
           << "), ";
    else
      line << "load factor " << propagation.load_factor(front_moves) << ", ";
    line << std::setprecision(4) << (dim == 2 ? "length " : "area ") << size
         << ", K_max " << k_max;
    if (!verdict.stop)
      line << ", next advance " << std::setprecision(3) << largest;
    line << std::defaultfloat << ", " << triangulation.n_global_active_cells()
         << " cells";
    // The wall time so far, and what remains if the run goes on as it went:
    // by the step count or the criterion nearest to its target.
    if (run_parameters.timing_summary)
      {
        const double elapsed = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start_time)
                                 .count();
        double progress = double(step) / std::max(propagation.n_steps(), 1u);
        for (const auto &criterion : termination_criteria)
          progress = std::max(progress, criterion->progress());
        line << ", " << std::fixed << std::setprecision(1) << elapsed << " s";
        if (!verdict.stop && progress > 0)
          line << " (about " << elapsed * (1 - progress) / progress
               << " s left)";
        line << std::defaultfloat;
      }
    pcout << line.str() << std::endl;
    unsigned int n_closed = 0;
    for (const FrontMove<dim> &m : front_moves)
      n_closed += m.closed;
    if (n_closed > 0)
      pcout << "  Warning: K_I < 0 at " << n_closed << " of "
            << front_moves.size() << " front points: the lips pass through "
            << "each other there (Contact/Formulation = none); they are "
            << "closed and do not grow (`closed` in the front file)."
            << std::endl;
    for (const FrontValues<dim> &v : front_values)
      if (!v.crown_clear)
        {
          pcout << "  Warning: a crown reaches the boundary or another front "
                   "at ("
                << v.point.position
                << "): its K, and the growth there, are unreliable."
                << std::endl;
          break;
        }
    if (verdict.stop)
      {
        end_reason =
          (verdict.failure ? "Failure: " : "End: ") + verdict.reason + ".";
        pcout << end_reason << std::endl;
      }
  }



  template <int dim>
  TerminationCriteria::Verdict
  Simulator<dim>::check_vanished_fronts() const
  {
    TerminationCriteria::Verdict    verdict;
    const std::vector<unsigned int> now = fronts_per_crack();
    std::vector<unsigned int>       before(now.size(), 0);
    for (const FrontMove<dim> &m : previous_moves)
      if (m.crack < before.size())
        before[m.crack] = std::max(before[m.crack], m.front + 1);
    for (unsigned int c = 0; c < now.size(); ++c)
      if (now[c] < before[c])
        {
          std::ostringstream reason;
          reason << "crack " << c + 1 << " has " << now[c]
                 << (dim == 2 ? " tips" : " fronts") << " after the last "
                 << "advance instead of " << before[c] << ": one ran out of "
                 << "the body or into a hole (its cycles are not counted: "
                 << "they need K at the advance's end)";
          verdict.stop   = true;
          verdict.reason = reason.str();
          break;
        }
    return verdict;
  }



  template <int dim>
  TerminationCriteria::Verdict
  Simulator<dim>::check_rates() const
  {
    TerminationCriteria::Verdict verdict;
    for (const FrontMove<dim> &m : front_moves)
      if (!std::isfinite(m.rate))
        {
          std::ostringstream reason;
          reason << "the growth law gives no finite rate at ("
                 << m.point.position << "), Delta K = " << m.delta_k
                 << ", K_max = " << m.k_eq << ": "
                 << propagation.why_no_rate(m);
          verdict.stop    = true;
          verdict.failure = true;
          verdict.reason  = reason.str();
          break;
        }
    return verdict;
  }



  template <int dim>
  void
  Simulator<dim>::advance_cracks()
  {
    {
      TimerOutput::Scope t(*timer, "levelset");
      propagation.update_level_sets(front_moves, level_sets);
      cracks_moved = true;
    }
    // The estimate's wide crown around the moved tips, for a strategy that
    // refines it before the next solve (k tolerance). Along a 3D front the
    // last estimate's radii stay: they follow the front's curvature and
    // clearance, which one step changes little.
    if (fracture_parameters.error_estimate && dim == 2)
      {
        std::vector<std::vector<FrontPoint<dim>>> tips;
        for (const FrontMove<dim> &move : front_moves)
          {
            tips.emplace_back(1);
            tips.back()[0].position = move.new_position();
          }
        expect_wide_crown(tips);
      }
    {
      TimerOutput::Scope t(*timer, "refine");
      adapt_mesh_to_fronts();
    }
    {
      TimerOutput::Scope t(*timer, "checkpoint");
      write_checkpoint();
      run_record->add_file("checkpoint");
      // Continue from the mesh just written, as a resumed run does: the
      // order of its cells (and so the numbering of the DoFs and the order
      // of the sums of assembly) is that of a loaded mesh, which differs
      // from that of a mesh refined and coarsened in place. A run killed
      // and resumed then reaches the same results to the last digit.
      load_mesh(run_parameters.output_directory + "/checkpoint");
    }
  }



  template <int dim>
  void
  Simulator<dim>::correct_directions(const std::string &key)
  {
    // What the trial step changes, to be restored after it: the fields
    // (fit to vertex shifts them too), the fronts and their K's.
    std::vector<TrilinosWrappers::MPI::Vector> lsn, lst;
    for (unsigned int c = 0; c < level_sets.n_cracks(); ++c)
      {
        lsn.push_back(level_sets.lsn(c));
        lst.push_back(level_sets.lst(c));
      }
    const std::vector<FrontValues<dim>>  values    = front_values;
    const std::vector<CrackSurface<dim>> surfaces  = crack_surfaces;
    const bool                           moved     = cracks_moved;
    const std::vector<FrontMove<dim>>    predictor = front_moves;
    // Plugins that keep state across steps (a crack surface) forget the
    // trial as the fields do.
    std::map<std::string, Plugins::State> plugin_states;
    for (const auto &[key, plugin] : plugins())
      plugin->save(plugin_states[key]);
    {
      TimerOutput::Scope t(*timer, "levelset");
      propagation.update_level_sets(front_moves, level_sets);
      cracks_moved = true;
    }
    // On the same split of the mesh: the fields are restored below as
    // they are, owned by the same ranks.
    setup_system(false);
    solve_load_state(load_cycle.maximum());
    // A trial solve reports no error estimate.
    linear_solver->release();
    for (unsigned int c = 0; c < crack_surfaces.size(); ++c)
      crack_surfaces[c].extract(level_sets, c);
    compute_fracture_parameters(load_cycle.maximum(), false);
    // Only the trial's kinks are used, which the maximum gives.
    const std::vector<FrontMove<dim>> trial =
      propagation.moves(front_values,
                        front_values,
                        fronts_per_crack(),
                        propagation.maximum_advance());
    Propagation<dim>::correct_directions(front_moves, trial);
    previous_moves = front_moves;

    for (unsigned int c = 0; c < level_sets.n_cracks(); ++c)
      level_sets.set(c, lsn[c], lst[c]);
    for (const auto &[key, plugin] : plugins())
      plugin->load(plugin_states[key]);
    front_values   = values;
    crack_surfaces = surfaces;
    cracks_moved   = moved;
    if (detailed_screen)
      {
        double largest = 0;
        for (unsigned int k = 0; k < front_moves.size(); ++k)
          largest =
            std::max(largest,
                     std::abs(front_moves[k].angle - predictor[k].angle));
        pcout << "  trial step: kinks corrected by up to "
              << largest * 180 / numbers::PI << " degrees" << std::endl;
      }
    if (enrichment && fracture_parameters.compute &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      write_front_file(key);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
