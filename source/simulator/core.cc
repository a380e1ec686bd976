#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <xcrack/condition_number.h>
#include <xcrack/exact_solution.h>
#include <xcrack/input_error.h>
#include <xcrack/output_file.h>
#include <xcrack/simulator.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the displacement (Q1 or Q2).");
    }
    prm.leave_subsection();

    NonlinearSolver::declare_parameters(prm);
    prm.enter_subsection("Contact");
    Contact::declare_parameters(prm);
    prm.leave_subsection();
    EnrichmentParameters::declare_parameters(prm);
    WorkBalance<dim>::declare_parameters(prm);
    FractureParameters::declare_parameters(prm);
    MeshRefinement::Parameters::declare_parameters(prm);
    Propagation<dim>::declare_parameters(prm);
    TerminationCriteria::declare_parameters(prm);
  }



  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler  &prm,
                            const MPI_Comm     mpi_communicator,
                            const std::string &resume_directory,
                            const bool         check_only)
    : mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , prm(prm)
    // Only the 2:1 balance, which p4est enforces globally: the other
    // smoothing flags act on each rank's part of the mesh (with them, a
    // cell near a partition boundary was refined on one rank and not on
    // two, and K differed in the sixth digit: two collinear cracks, fifth
    // mesh).
    , triangulation(mpi_communicator,
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , level_sets(triangulation)
    , resume_directory(resume_directory)
    , check_only(check_only)
  {
    run_parameters.parse_parameters(prm);
    check_input(run_parameters.dimension == dim,
                "Dimension = " + std::to_string(run_parameters.dimension) +
                  " but this is a " + std::to_string(dim) + "D problem.");
    material.parse_parameters(prm);
    mesh_description.parse_parameters(prm);
    {
      const Plugins::ScopedSubsection scope(prm, "Linear solver");
      linear_solver_type = prm.get("Type");
      linear_solver      = LinearSolver::create<dim>(prm, *this);
    }
    work_balance.parse_parameters(prm);

    FunctionConstants &constants = function_constants;
    constants                    = material.constants(dim);
    constants["pi"]              = numbers::PI;
    for (const auto &[name, value] : run_parameters.user_constants)
      {
        check_input(constants.count(name) == 0,
                    "Function constants: '" + name +
                      "' is a reserved name (E, nu, mu, lambda, pi).");
        constants[name] = value;
      }
    exact_solution = ExactSolution::create<dim>(prm, constants, material);
    boundary_conditions.parse_parameters(prm, constants, exact_solution);
    {
      const Plugins::ScopedSubsection scope(prm, "Propagation");
      load_cycle.parse_parameters(prm, boundary_conditions, constants);
    }
    nonlinear_solver.parse_parameters(prm);
    cracks.parse_parameters(prm);
    fracture_parameters.parse_parameters(prm, constants);
    // (A strategy may read the fracture parameters: k tolerance needs the
    // K error estimate.)
    refinement_parameters.parse_parameters(prm);
    mesh_refinement =
      MeshRefinement::create<dim>(refinement_parameters, prm, *this);
    check_input(dim == 2 ? !fracture_parameters.reference_3d :
                           !fracture_parameters.reference_2d,
                "Fracture parameters/Reference K: give " +
                  std::string(dim == 2 ? "'K_I; K_II'" : "'K_I; K_II; K_III'") +
                  " in " + std::to_string(dim) + "D.");

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Degree");
    prm.leave_subsection();

    // The growth model and what ends it (their plugins read the material).
    propagation.initialize_simulator(*this);
    propagation.parse_parameters(prm);
    if (propagation.enabled())
      {
        check_input(cracks.size() > 0,
                    "Propagation/Number of steps > 0 but there is no crack "
                    "to grow (Cracks/Number of cracks = 0).");
        check_input(fracture_parameters.compute,
                    "Propagation/Number of steps > 0 needs the stress "
                    "intensity factors: set Fracture parameters/Compute = "
                    "true.");
        termination_criteria = TerminationCriteria::create<dim>(prm, *this);
      }
    detailed_screen = !propagation.enabled() || run_parameters.detailed_screen;

    // A resumed run loads its refined mesh onto the coarse one.
    mesh_description.create(triangulation, resume_directory.empty());
    boundary_conditions.check_against(triangulation);
    if (!load_cycle.proportional())
      load_cycle.minimum_loads().check_against(triangulation);
    cracks.check_against(triangulation);
    // Refinement capped at the initial level repeats one mesh: a study of
    // several meshes would print rates of 0/0.
    if (resume_directory.empty() && refinement_parameters.n_meshes > 1)
      check_input(triangulation.n_global_levels() - 1 <
                    refinement_parameters.max_level,
                  "Mesh refinement/Maximum level = " +
                    std::to_string(refinement_parameters.max_level) +
                    ": the initial mesh already reaches level " +
                    std::to_string(triangulation.n_global_levels() - 1) +
                    ", so the " +
                    std::to_string(refinement_parameters.n_meshes) +
                    " meshes (Number of meshes) would all be the same.");
    check_input(refinement_parameters.min_level <=
                  refinement_parameters.max_level,
                "Mesh refinement/Minimum level = " +
                  std::to_string(refinement_parameters.min_level) +
                  " is above Maximum level = " +
                  std::to_string(refinement_parameters.max_level) + ".");
    check_loads();
    check_cracks_seen();
    check_crowns();
    create_finite_elements(prm);
    create_terms(prm);
    check_output_directory();
  }



  template <int dim>
  void
  Simulator<dim>::record_overrides(const std::vector<std::string> &overrides)
  {
    command_line_overrides = overrides;
  }



  template <int dim>
  const Statistics &
  Simulator<dim>::get_statistics() const
  {
    return statistics;
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    // All input was checked in the constructor: from here on results are
    // written.
    timer      = std::make_unique<TimerOutput>(mpi_communicator,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    start_time = std::chrono::steady_clock::now();
    std::filesystem::create_directories(run_parameters.output_directory);
    run_record = std::make_unique<RunRecord>(run_parameters.output_directory,
                                             mpi_communicator);
    run_record->set_overrides(command_line_overrides);
    run_record->start(!resume_directory.empty());
    try
      {
        run_steps();
      }
    catch (const std::bad_alloc &)
      {
        // Say how big the problem was when memory ran out.
        const std::string message =
          "out of memory with " + std::to_string(dof_handler.n_dofs()) +
          " DoFs (" +
          std::to_string(
            system_matrix.m() > 0 ? system_matrix.n_nonzero_elements() : 0) +
          " matrix entries). A direct solver's factors need far more than "
          "the matrix: use Linear solver/Type = cg amg, fewer meshes or a "
          "lower Mesh refinement/Maximum level.";
        run_record->finish("failed", message);
        timer.reset();
        throw std::runtime_error(message);
      }
    catch (const InputError &e)
      {
        // Bad input met in the first solve (crowns without a vertex): the
        // earlier run's results come back, as if the run had not started.
        if (!results_written)
          run_record->restore_earlier();
        else
          run_record->finish("failed", message_of(e));
        timer.reset();
        throw;
      }
    catch (const std::exception &e)
      {
        // The files written so far stay; run.json says they are a failed
        // run's. The timer goes here, where no exception is in flight (its
        // destructor would warn about one).
        run_record->finish("failed", message_of(e));
        timer.reset();
        throw;
      }
    run_record->finish("completed", end_reason);
  }



  template <int dim>
  void
  Simulator<dim>::run_steps()
  {
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      parameters_text = text.str();
    }
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      write_file(run_parameters.output_directory + "/parameters.prm",
                 [&](std::ostream &out) { out << parameters_text; });
    run_record->add_file("parameters.prm");

    pcout << "xcrack: " << dim << "D linear elasticity, Q" << degree
          << " elements, " << linear_solver_type << " solver" << std::endl;
    // Bilinear elements lock as the material becomes incompressible: the
    // answer stays finite but can be far off (Case 1 at nu = 0.499: 22 %
    // energy error with Q1 on 10,772 DoFs, 0.4 % with Q2 on 35,944).
    if (degree == 1 && material.poisson_ratio > 0.45)
      pcout << "Warning: Poisson's ratio = " << material.poisson_ratio
            << " with Degree = 1: bilinear elements lock when the material "
               "is nearly incompressible; use Discretization/Degree = 2."
            << std::endl;
    if (enrichment)
      {
        const auto &e = enrichment->get_parameters();
        pcout << "X-FEM: jump enrichment";
        if (e.tip_zone == EnrichmentParameters::TipZone::topological)
          pcout << ", branch functions on the nodes of the cells the front "
                   "touches";
        else if (e.tip_zone == EnrichmentParameters::TipZone::geometric)
          pcout << ", branch functions within " << e.radius << " of the front"
                << (e.gather ? ", gathered" : "");
        else
          pcout << " only (no branch functions)";
        pcout << std::endl;
      }
    if (propagation.enabled())
      pcout << "Propagation: at most " << propagation.n_steps()
            << " steps, the fastest point advancing "
            << propagation.maximum_advance() << " per step" << std::endl;

    if (!resume_directory.empty())
      {
        read_checkpoint(resume_directory);
        pcout << "Resumed at step " << step << " (" << cycles
              << " cycles) from " << resume_directory << std::endl;
        results_written = true;
      }

    std::string key;
    const bool  goal = mesh_refinement->has_goal();
    if (goal && resume_directory.empty())
      {
        TimerOutput::Scope t(*timer, "refine");
        refine_before_first_solve();
      }
    for (bool stop = false; !stop;)
      {
        // A check on the input that fails once results are written (two
        // cracks grown into each other, a crown left without a vertex) is
        // not bad input: it is where the run got to. It ends the run with
        // what it met; the results so far stand.
        try
          {
            stop = run_step(key);
          }
        catch (const InputError &e)
          {
            if (!results_written)
              throw;
            end_reason = "End: step " + std::to_string(step) +
                         " cannot be solved: " + e.what();
            pcout << end_reason << std::endl;
            break;
          }
      }

    report_unreliable();
    if (exact_solution && statistics.n_rows() > 1 && !propagation.enabled())
      print_convergence_table();
    if (run_parameters.timing_summary)
      timer->print_summary();
  }



  template <int dim>
  bool
  Simulator<dim>::run_step(std::string &key)
  {
    const bool         goal     = mesh_refinement->has_goal();
    const unsigned int n_meshes = n_meshes_of(step);
    bool               stop     = false;
    for (unsigned int mesh = 0; mesh < n_meshes; ++mesh)
      {
        if (mesh > 0)
          {
            TimerOutput::Scope t(*timer, "refine");
            // (check_mesh_goal() marked the cells already.)
            if (goal)
              execute_refinement();
            else
              refine_mesh();
          }
        solve_and_report(mesh, n_meshes);
        bool last = (mesh + 1 == n_meshes);
        if (goal)
          last = check_mesh_goal(last);
        // The last mesh of a growth step first computes the moves (its
        // front file shows them).
        if (propagation.enabled() && last)
          stop = grow();
        key = solve_key(step, mesh);
        finish_solve(key);
        if (!results_written)
          run_record->keep_results();
        results_written = true;
        if (last)
          break;
      }
    if (!propagation.enabled() || stop)
      return true;
    if (propagation.corrects_directions())
      correct_directions(key);
    advance_cracks();
    ++step;
    return false;
  }



  template <int dim>
  unsigned int
  Simulator<dim>::n_meshes_of(const unsigned int step_of_solve) const
  {
    // Step 0 may be solved on several successively refined meshes (a
    // convergence study of the initial crack); every step after it on the
    // mesh its fronts adapted. A strategy with a goal refines every step
    // until the goal is met, on at most Number of meshes.
    return (step_of_solve == 0 || mesh_refinement->has_goal() ?
              refinement_parameters.n_meshes :
              1);
  }



  template <int dim>
  std::string
  Simulator<dim>::solve_key(const unsigned int step_of_solve,
                            const unsigned int mesh) const
  {
    return Utilities::int_to_string(step_of_solve, 3) +
           (n_meshes_of(step_of_solve) > 1 ?
              "." + Utilities::int_to_string(mesh, 2) :
              "");
  }



  template <int dim>
  void
  Simulator<dim>::solve_and_report(const unsigned int mesh,
                                   const unsigned int n_meshes)
  {
    setup_system();
    const NonlinearSolver::Result result =
      solve_load_state(load_cycle.maximum());
    const unsigned int iterations = result.linear_iterations;
    // What solve() kept for the dual solves of the K error estimate goes
    // when this function is left, also by an exception: it must not outlive
    // the matrix it was factorized from.
    struct Release
    {
      LinearSolver::Interface<dim> &solver;
      ~Release()
      {
        solver.release();
      }
    } release{*linear_solver};

    statistics.start_row();
    statistics.add_value("step", (unsigned long long)step);
    statistics.add_value("mesh", (unsigned long long)mesh);
    statistics.add_value("cycles", cycles);
    statistics.add_value(
      "cells", (unsigned long long)triangulation.n_global_active_cells());
    statistics.add_value("dofs", (unsigned long long)dof_handler.n_dofs());
    statistics.add_value("enriched_dofs",
                         (unsigned long long)n_free_enriched_dofs());
    statistics.add_value("solver_iterations", (unsigned long long)iterations);
    statistics.add_value("newton_iterations",
                         (unsigned long long)result.iterations);
    statistics.add_value("residual", result.residual);
    if (contact)
      for (const auto &[column, value] : contact->statistics())
        statistics.add_value(column, value);
    if (enrichment && Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      statistics.add_value("work_imbalance", work_imbalance);
    if (dof_handler.n_dofs() <= run_parameters.condition_number_limit &&
        n_own_unknowns == 0)
      statistics.add_value("condition_number",
                           condition_number(system_matrix, constraints));

    std::ostringstream line;
    line << "Step " << step;
    if (n_meshes > 1)
      line << ", mesh " << mesh;
    line << ": " << triangulation.n_global_active_cells() << " cells, "
         << dof_handler.n_dofs() << " dofs";
    if (!linear_solver->iterative_method().empty())
      line << ", " << iterations << " " << linear_solver->iterative_method()
           << " iterations";
    if (!is_linear())
      line << ", " << result.iterations << " Newton steps";
    // The largest displacement component: a first sanity check of any run
    // (and what the demo compares with beam theory).
    const double max_displacement = compute_max_displacement();
    // A singular system (rigid-body motions left free) solved by the
    // direct solver gives a displacement of round-off divided by a zero
    // pivot: not finite, or far beyond what the loads can produce.
    if (!std::isfinite(max_displacement))
      throw NumericalError(
        "the displacement of step " + std::to_string(step) +
        " is not finite (NaN or inf): the system is singular, or data that "
        "is not finite reached it.");
    if (displacement_scale > 0 && max_displacement > 1e6 * displacement_scale)
      {
        std::ostringstream message;
        message << "the displacement of step " << step << " reaches "
                << max_displacement << ", " << std::scientific
                << std::setprecision(1) << max_displacement / displacement_scale
                << " times what the loads can produce: the system is "
                   "singular. Rigid-body motions are left free: the "
                   "Dirichlet data and pinned points must hold every part "
                   "of the body in every direction, and a crack that cuts a "
                   "piece loose frees that piece.";
        throw NumericalError(message.str());
      }
    statistics.add_value("max_displacement", max_displacement);
    line << std::scientific << std::setprecision(4) << ", max |u_i| "
         << max_displacement << std::defaultfloat;
    // The exact solution is that of the initial crack.
    if (exact_solution && !cracks_moved)
      {
        const auto [l2, energy] = compute_errors();
        statistics.add_value("L2_error", l2);
        statistics.add_value("energy_error", energy);
        line << std::scientific << std::setprecision(3) << ", L2 error " << l2
             << ", energy error " << energy << std::defaultfloat;
      }
    if (detailed_screen)
      pcout << line.str() << std::endl;
    if (detailed_screen && enrichment && enrichment->get_parameters().gather)
      {
        const auto n_masters = enrichment->gathering_masters().n_elements();
        pcout << "  gathering: " << n_masters / (4 * dim) << " masters, "
              << n_masters << " branch unknowns" << std::endl;
      }
    if (enrichment)
      report_crack_surface();
    front_values.clear();
    front_moves.clear();
    if (enrichment && fracture_parameters.compute)
      compute_fracture_parameters(load_cycle.maximum());
  }



  template <int dim>
  void
  Simulator<dim>::finish_solve(const std::string &key)
  {
    if (enrichment && fracture_parameters.compute &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      write_front_file(key);
    if (run_parameters.write_vtu)
      output_results(key);

    // Wall time of each phase in this row: the timer accumulates over the
    // run, so take differences.
    const auto times =
      timer->get_summary_data(TimerOutput::OutputData::total_wall_time);
    std::vector<std::string> phases = {
      "setup", "assemble", "solve", "errors", "fracture", "output", "refine"};
    if (propagation.enabled())
      for (const std::string phase : {"levelset", "checkpoint"})
        phases.push_back(phase);
    for (const std::string &phase : phases)
      {
        const double total = (times.count(phase) ? times.at(phase) : 0.);
        statistics.add_value("t_" + phase, total - previous_times[phase]);
        previous_times[phase] = total;
      }
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      statistics.write_csv(run_parameters.output_directory + "/statistics.csv");
    run_record->add_file("statistics.csv");
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
