#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/input_error.h>
#include <xcrack/simulator.h>
#include <xcrack/xfem/enriched_dirichlet.h>

#include <sstream>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::setup_system(const bool may_split)
  {
    // The cracks' fields on this mesh, the cells they enrich, and the
    // fields fitted to the vertices the enrichment chose; gathering ties
    // the branch DoFs along the fronts they give.
    update_level_sets();
    {
      TimerOutput::Scope t(*timer, "setup");
      dof_handler.reinit(triangulation);
      if (enrichment)
        {
          enrichment->set_fe_indices(dof_handler, level_sets);
          if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
            share_work(may_split);
          level_sets.subtract_from_lsn(enrichment->lsn_shift());
        }
    }
    gathering_fronts.clear();
    if (enrichment && enrichment->get_parameters().gather)
      for (unsigned int c = 0; c < cracks.size(); ++c)
        {
          CrackSurface<dim> surface;
          surface.extract(level_sets, c);
          gathering_fronts.push_back(surface.fronts());
        }

    TimerOutput::Scope t(*timer, "setup");
    dof_handler.distribute_dofs(fe_collection);
    enriched_dofs      = (enrichment ? enrichment->enriched_dofs(dof_handler) :
                                       IndexSet(dof_handler.n_dofs()));
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    setup_own_unknowns();
    make_constraints(load_cycle.maximum());

    // Gathered DoFs are tied to masters that may be owned by another rank
    // and lie outside the relevant set: assembly writes to their rows too.
    IndexSet rows = locally_relevant_dofs;
    if (enrichment)
      rows.add_indices(enrichment->gathering_masters());
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    if (n_own_unknowns > 0)
      {
        setup_system_with_own_unknowns(dsp, rows);
        return;
      }
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               rows);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::setup_own_unknowns()
  {
    own_offsets.assign(contributions.size(), 0);
    n_own_unknowns = 0;
    for (unsigned int c = 0; c < contributions.size(); ++c)
      {
        contributions[c]->setup_own_unknowns();
        own_offsets[c] = n_own_unknowns;
        n_own_unknowns += contributions[c]->n_own_unknowns();
      }
    system_owned = locally_owned_dofs;
    if (n_own_unknowns == 0)
      return;
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    system_owned                         = IndexSet(n_dofs + n_own_unknowns);
    system_owned.add_indices(locally_owned_dofs);
    for (unsigned int c = 0; c < contributions.size(); ++c)
      {
        const auto [begin, end] = contributions[c]->owned_own_unknowns();
        if (end > begin)
          system_owned.add_range(n_dofs + own_offsets[c] + begin,
                                 n_dofs + own_offsets[c] + end);
      }
    system_owned.compress();
  }



  template <int dim>
  void
  Simulator<dim>::setup_system_with_own_unknowns(
    const DynamicSparsityPattern &dsp,
    const IndexSet               &dof_rows)
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    const types::global_dof_index n      = n_dofs + n_own_unknowns;
    // Any rank may write to the row of any own unknown its cells couple to.
    IndexSet rows(n);
    rows.add_indices(dof_rows);
    rows.add_range(n_dofs, n);
    DynamicSparsityPattern system_dsp(n, n, rows);
    for (const types::global_dof_index row : dof_rows)
      for (auto entry = dsp.begin(row); entry != dsp.end(row); ++entry)
        system_dsp.add(row, entry->column());
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int c = 0; c < contributions.size(); ++c)
          {
            const std::vector<unsigned int> own =
              contributions[c]->own_unknowns_of(cell);
            if (own.empty())
              continue;
            indices.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(indices);
            for (const unsigned int k : own)
              indices.push_back(n_dofs + own_offsets[c] + k);
            system_constraints.add_entries_local_to_global(indices,
                                                           system_dsp,
                                                           false);
          }
    SparsityTools::distribute_sparsity_pattern(system_dsp,
                                               system_owned,
                                               mpi_communicator,
                                               rows);
    system_matrix.reinit(system_owned,
                         system_owned,
                         system_dsp,
                         mpi_communicator);
    system_rhs.reinit(system_owned, mpi_communicator);
    system_solution.reinit(system_owned, mpi_communicator);
  }



  template <int dim>
  const AffineConstraints<double> &
  Simulator<dim>::assembly_constraints() const
  {
    return (n_own_unknowns > 0 ? system_constraints : constraints);
  }



  template <int dim>
  void
  Simulator<dim>::share_work(const bool may_split)
  {
    const std::vector<unsigned int> work = cell_work();
    work_imbalance = WorkBalance<dim>::imbalance(triangulation, work);
    if (may_split &&
        work_balance.balance(
          triangulation,
          work,
          work_imbalance,
          [this]() { level_sets.prepare_for_coarsening_and_refinement(); },
          [this]() { level_sets.interpolate(); }))
      {
        // Indexed by the cells of the previous split.
        k_error_cells.indicators.reinit(0);
        dof_handler.reinit(triangulation);
        enrichment->set_fe_indices(dof_handler, level_sets);
        work_imbalance =
          WorkBalance<dim>::imbalance(triangulation, cell_work());
      }
  }



  template <int dim>
  std::vector<unsigned int>
  Simulator<dim>::cell_work() const
  {
    // The rules are built here (and cached for the assembly) rather than
    // guessed from the cells' kinds.
    std::vector<unsigned int> work(triangulation.n_active_cells(), 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Before distribute_dofs(): the cell knows its index only.
          const unsigned int     index = cell->active_fe_index();
          const Quadrature<dim> *rule =
            enrichment->special_quadrature(cell, degree + 1);
          const unsigned int n_points =
            (rule ? rule->size() : quadrature_collection[index].size());
          work[cell->active_cell_index()] =
            n_points * fe_collection[index].n_dofs_per_cell();
        }
    return work;
  }



  template <int dim>
  void
  Simulator<dim>::update_level_sets()
  {
    if (cracks.size() == 0)
      return;
    // Until the cracks move they are their initial shapes, which a new mesh
    // interpolates exactly; afterwards the fields were carried across.
    if (cracks_moved)
      return;
    TimerOutput::Scope t(*timer, "levelset");
    level_sets.initialize(cracks.shapes());
  }



  template <int dim>
  void
  Simulator<dim>::make_constraints(const LoadState<dim> &state)
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (enrichment)
      enrichment->make_constraints(dof_handler, constraints, gathering_fronts);
    make_dirichlet_constraints(state);
    constraints.close();
    if (n_own_unknowns == 0)
      return;
    // The same constraints on the system's index range: the own unknowns
    // are free, and the assembly condenses their couplings to constrained
    // DoFs (and the Dirichlet data of those) with them.
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    IndexSet                      lines(n_dofs + n_own_unknowns);
    lines.add_indices(locally_relevant_dofs);
    lines.add_range(n_dofs, n_dofs + n_own_unknowns);
    system_constraints.clear();
    system_constraints.reinit(lines);
    system_constraints.merge(
      constraints,
      AffineConstraints<double>::MergeConflictBehavior::no_conflicts_allowed,
      true);
    system_constraints.close();
  }



  template <int dim>
  void
  Simulator<dim>::make_dirichlet_constraints(const LoadState<dim> &state)
  {
    // Pinned vertices: their standard DoFs of the listed components. A pin
    // where the vertex carries enrichment would not hold the displacement
    // there (the enriched functions add to it): refused.
    for (const auto &[point, mask] : boundary_conditions.pinned)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(point) < 1e-10 * cell->diameter())
              {
                const FiniteElement<dim>            &fe = cell->get_fe();
                std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
                cell->get_dof_indices(dofs);
                for (unsigned int k = 0; k < fe.n_dofs_per_vertex(); ++k)
                  {
                    const unsigned int i = v * fe.n_dofs_per_vertex() + k;
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    if (!mask[c])
                      continue;
                    if (enrichment && Enrichment<dim>::is_enriched_dof(fe, i))
                      {
                        std::ostringstream where;
                        where << point;
                        check_input(constraints.is_constrained(dofs[i]),
                                    "Boundary conditions/Pinned points: (" +
                                      where.str() +
                                      ") lies where the crack enriches the "
                                      "space; pin a vertex farther from it.");
                        continue;
                      }
                    if (!constraints.is_constrained(dofs[i]))
                      {
                        constraints.add_line(dofs[i]);
                        constraints.set_inhomogeneity(dofs[i], 0.);
                      }
                  }
              }

    // The state's data: its load set's, times its factor.
    BoundaryConditions<dim> data;
    data.dirichlet_mask = state.loads->dirichlet_mask;
    for (const auto &[id, function] : state.loads->dirichlet)
      data.dirichlet[id] =
        (state.factor == 1 ?
           function :
           std::make_shared<ScaledFunction<dim>>(*function, state.factor));
    if (enrichment)
      {
        make_enriched_dirichlet_constraints(dof_handler,
                                            *enrichment,
                                            data,
                                            constraints);
        return;
      }
    for (const auto &[id, function] : data.dirichlet)
      VectorTools::interpolate_boundary_values(
        dof_handler, id, *function, constraints, data.dirichlet_mask.at(id));
  }



  template <int dim>
  types::global_dof_index
  Simulator<dim>::n_free_enriched_dofs() const
  {
    types::global_dof_index n = 0;
    for (const auto dof : enriched_dofs)
      if (locally_owned_dofs.is_element(dof) &&
          !constraints.is_constrained(dof))
        ++n;
    return Utilities::MPI::sum(n, mpi_communicator);
  }


  template <int dim>
  void
  Simulator<dim>::create_finite_elements(ParameterHandler &prm)
  {
    if (cracks.size() > 0)
      {
        EnrichmentParameters enrichment_parameters;
        enrichment_parameters.parse_parameters(prm);
        enrichment = std::make_unique<Enrichment<dim>>(cracks.size(),
                                                       degree,
                                                       enrichment_parameters);
        // Several cracks: classify the coarse mesh once now, so that
        // cracks whose enriched zones meet stop the run here, before any
        // result is written.
        if (cracks.size() > 1)
          {
            DoFHandler<dim> probe(triangulation);
            if (!resume_directory.empty()) // else done by the check above
              level_sets.initialize(cracks.shapes());
            enrichment->set_fe_indices(probe, level_sets);
          }
        // Gauss rules per element: the cells of the tip zone carry the
        // non-polynomial branch functions and get two more points.
        for (const auto &fe : enrichment->get_fe_collection())
          {
            fe_collection.push_back(fe);
            quadrature_collection.push_back(QGauss<dim>(
              degree +
              (fe_collection.size() - 1 >= Enrichment<dim>::tip ? 3 : 1)));
          }
      }
    else
      {
        fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), dim));
        quadrature_collection.push_back(QGauss<dim>(degree + 1));
      }
    face_quadrature_collection.push_back(QGauss<dim - 1>(degree + 1));
  }



  template <int dim>
  void
  Simulator<dim>::create_terms(ParameterHandler &prm)
  {
    {
      const Plugins::ScopedSubsection scope(prm, "Contact");
      contact = Contact::create<dim>(prm, *this);
      check_input(!contact || !fracture_parameters.error_estimate,
                  "Fracture parameters/Error estimate = true with Contact/"
                  "Formulation = " +
                    prm.get("Formulation") +
                    ": the estimate's dual problems are those of lips "
                    "without contact; it is not available with contact "
                    "yet.");
      check_input(!contact || cracks.size() > 0,
                  "Contact/Formulation = " + prm.get("Formulation") +
                    " but there is no crack whose lips could touch (Cracks/"
                    "Number of cracks = 0).");
    }
    create_contributions();
    bool saddle_point = false;
    for (const Assembly::Contribution<dim> *contribution : contributions)
      saddle_point = saddle_point || contribution->has_own_unknowns();
    check_input(!saddle_point || linear_solver->accepts_saddle_point(),
                "Linear solver/Type = " + linear_solver_type +
                  " cannot solve the saddle-point systems of Contact/"
                  "Formulation = lagrange (its multipliers have no "
                  "diagonal for a preconditioner): use Type = direct.");
    check_input(linear_solver->accepts(matrix_property()),
                "Linear solver/Type = " + linear_solver_type +
                  " cannot solve the " +
                  LinearSolver::to_string(matrix_property()) +
                  " systems of this scene (its contact formulation): use "
                  "Type = direct" +
                  (matrix_property() == LinearSolver::MatrixProperty::general ?
                     " or gmres amg." :
                     "."));
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
