#include <xcrack/simulator.h>

namespace xcrack
{
  namespace
  {
    /**
     * The rigid translations of the space, one per component, on the
     * locally owned DoFs (in the order of the owned index set): the
     * near-null space from which AMG builds its coarse spaces. A
     * translation is 1 on the standard DoFs and 0 on the enriched ones,
     * whose functions are not constants. DoFTools::extract_constant_modes()
     * does not know FE_Enriched: deal.II's debug library stops there, and
     * the release one marked none of the DoFs of enriched cells, leaving
     * holes in the modes around the cracks.
     */
    template <int dim>
    std::vector<std::vector<bool>>
    translation_modes(const DoFHandler<dim> &dof_handler,
                      const bool             enriched_space)
    {
      const IndexSet                &owned = dof_handler.locally_owned_dofs();
      std::vector<std::vector<bool>> modes(dim,
                                           std::vector<bool>(owned.n_elements(),
                                                             false));
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const FiniteElement<dim> &fe = cell->get_fe();
            dofs.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (owned.is_element(dofs[i]) &&
                  !(enriched_space && Enrichment<dim>::is_enriched_dof(fe, i)))
                modes[fe.system_to_component_index(i).first]
                     [owned.index_within_set(dofs[i])] = true;
          }
      return modes;
    }
  } // namespace



  template <int dim>
  unsigned int
  Simulator<dim>::solve()
  {
    TimerOutput::Scope t(*timer, "solve");

    const LinearSolver::System system{
      system_matrix, matrix_property(), [this]() {
        return translation_modes(dof_handler, enrichment != nullptr);
      }};
    TrilinosWrappers::MPI::Vector distributed(system_owned, mpi_communicator);
    const unsigned int            iterations =
      linear_solver->solve(system, distributed, system_rhs);
    // The factorization references the matrix: keep it only for the dual
    // solves of the K error estimate, which follow at once.
    if (!(fracture_parameters.error_estimate && fracture_parameters.compute))
      linear_solver->release();
    if (n_own_unknowns == 0)
      {
        constraints.distribute(distributed);
        solution = distributed;
        return iterations;
      }

    // The DoFs, and each contribution's own unknowns on every rank.
    TrilinosWrappers::MPI::Vector dofs(locally_owned_dofs, mpi_communicator);
    for (const types::global_dof_index i : locally_owned_dofs)
      dofs[i] = distributed[i];
    dofs.compress(VectorOperation::insert);
    constraints.distribute(dofs);
    solution        = dofs;
    system_solution = distributed;
    for (const types::global_dof_index i : locally_owned_dofs)
      system_solution[i] = dofs[i];
    system_solution.compress(VectorOperation::insert);
    for (unsigned int c = 0; c < contributions.size(); ++c)
      {
        std::vector<double> values(contributions[c]->n_own_unknowns(), 0.);
        if (values.empty())
          continue;
        const auto [begin, end] = contributions[c]->owned_own_unknowns();
        for (unsigned int k = begin; k < end; ++k)
          values[k] = distributed[dof_handler.n_dofs() + own_offsets[c] + k];
        Utilities::MPI::sum(values, mpi_communicator, values);
        contributions[c]->set_own_values(values);
      }
    return iterations;
  }


  template <int dim>
  std::pair<double, double>
  Simulator<dim>::residual_norms() const
  {
    TrilinosWrappers::MPI::Vector residual(system_owned, mpi_communicator),
      iterate(system_owned, mpi_communicator), load(system_rhs);
    if (n_own_unknowns > 0)
      iterate = system_solution;
    else
      iterate = solution;
    system_matrix.vmult(residual, iterate);
    residual.sadd(-1., 1., system_rhs);
    assembly_constraints().set_zero(residual);
    assembly_constraints().set_zero(load);
    return {residual.l2_norm(), load.l2_norm()};
  }



  template <int dim>
  NonlinearSolver::Result
  Simulator<dim>::solve_load_state(const LoadState<dim> &state)
  {
    NonlinearSolver::Problem problem;
    problem.assemble = [&](const bool first) { assemble_system(state, first); };
    problem.solve    = [&]() { return solve(); };
    problem.residual = [&]() {
      TimerOutput::Scope t(*timer, "solve");
      return residual_norms();
    };
    problem.linear           = is_linear();
    problem.changed_statuses = [&]() {
      unsigned int n = 0;
      std::string  where;
      for (const Assembly::Contribution<dim> *contribution : contributions)
        {
          const auto [changed, place] = contribution->changed_statuses();
          n += changed;
          if (where.empty())
            where = place;
        }
      // Over all ranks: the count, and the place the first rank with one
      // gives.
      std::string first;
      for (const std::string &place :
           Utilities::MPI::all_gather(mpi_communicator, where))
        if (first.empty())
          first = place;
      return std::make_pair(Utilities::MPI::sum(n, mpi_communicator), first);
    };
    return nonlinear_solver.solve(problem,
                                  "the " + state.name + " load of step " +
                                    std::to_string(step));
  }



  template <int dim>
  bool
  Simulator<dim>::is_linear() const
  {
    for (const auto &contribution : contributions)
      if (!contribution->is_linear())
        return false;
    return true;
  }



  template <int dim>
  bool
  Simulator<dim>::solves_minimum() const
  {
    return propagation.enabled() && fracture_parameters.compute && enrichment &&
           !(load_cycle.proportional() && is_linear());
  }



  template <int dim>
  std::vector<FrontValues<dim>>
  Simulator<dim>::minimum_front_values()
  {
    if (!solves_minimum())
      {
        // Linearity: every K is the maximum's times R.
        const double                  r      = load_cycle.load_ratio();
        std::vector<FrontValues<dim>> values = front_values;
        for (FrontValues<dim> &v : values)
          {
            v.k_I *= r;
            v.k_II *= r;
            v.k_III *= r;
            v.g *= r * r;
            v.g_irwin *= r * r;
            for (double &k : v.k_jump)
              k *= r;
          }
        return values;
      }
    // Solved on the maximum's space, which stays: the solution, the
    // constraints and the K's of the maximum are restored afterwards.
    const TrilinosWrappers::MPI::Vector maximum_solution = solution;
    const std::vector<FrontValues<dim>> maximum_values   = front_values;
    const LoadState<dim>               &minimum          = load_cycle.minimum();
    {
      TimerOutput::Scope t(*timer, "setup");
      make_constraints(minimum);
    }
    const NonlinearSolver::Result result = solve_load_state(minimum);
    linear_solver->release();
    statistics.add_value("minimum_newton_iterations",
                         (unsigned long long)result.iterations);
    statistics.add_value("minimum_residual", result.residual);
    compute_fracture_parameters(minimum, false);
    std::vector<FrontValues<dim>> values = front_values;
    // The points must be the maximum's (the same fronts, the same space).
    AssertDimension(values.size(), maximum_values.size());
    front_values = maximum_values;
    solution     = maximum_solution;
    {
      TimerOutput::Scope t(*timer, "setup");
      make_constraints(load_cycle.maximum());
    }
    return values;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
