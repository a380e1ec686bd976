#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <xcrack/assembly/elasticity.h>
#include <xcrack/assembly/loads.h>
#include <xcrack/input_error.h>
#include <xcrack/simulator.h>

namespace xcrack
{
  template <int dim>
  const FEValues<dim> &
  Simulator<dim>::reinit_fe_values(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    hp::FEValues<dim>                                    &hp_fe_values,
    SpecialFEValues                                      &special_values,
    const unsigned int                                    n_points_1d) const
  {
    if (const Quadrature<dim> *rule =
          (enrichment ? enrichment->special_quadrature(cell, n_points_1d) :
                        nullptr))
      {
        const bool shared = enrichment->is_shared_rule(rule);
        std::unique_ptr<FEValues<dim>> &values =
          (shared ? special_values.shared[{rule, cell->active_fe_index()}] :
                    special_values.per_cell);
        if (!shared || !values)
          values =
            std::make_unique<FEValues<dim>>(cell->get_fe(),
                                            *rule,
                                            hp_fe_values.get_update_flags());
        values->reinit(cell);
        return *values;
      }
    hp_fe_values.reinit(cell);
    return hp_fe_values.get_present_fe_values();
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system(const LoadState<dim> &state, const bool first)
  {
    TimerOutput::Scope t(*timer, "assemble");
    system_matrix = 0;
    system_rhs    = 0;

    UpdateFlags flags = update_default;
    for (Assembly::Contribution<dim> *contribution : contributions)
      {
        flags |= contribution->update_flags();
        contribution->start_assembly(first);
      }
    hp::FEValues<dim> hp_fe_values(fe_collection, quadrature_collection, flags);
    SpecialFEValues   special_values;

    const AffineConstraints<double>     &condensing = assembly_constraints();
    FullMatrix<double>                   cell_matrix, own_matrix;
    Vector<double>                       cell_rhs, own_rhs, iterate;
    std::vector<types::global_dof_index> local_dof_indices;
    Assembly::CellInput<dim>             input;
    input.state   = &state;
    input.iterate = (first ? nullptr : &iterate);
    // The first load that is not finite where it is used, on this rank.
    std::string culprit;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          input.cell = cell;
          input.fe_values =
            &reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
          const unsigned int n_dofs = cell->get_fe().n_dofs_per_cell();
          cell_matrix.reinit(n_dofs, n_dofs);
          cell_rhs.reinit(n_dofs);
          if (!first)
            {
              iterate.reinit(n_dofs);
              cell->get_dof_values(solution, iterate);
            }
          for (Assembly::Contribution<dim> *contribution : contributions)
            contribution->assemble(input, cell_matrix, cell_rhs, culprit);

          // A load that is not finite is reported after the loop (every
          // rank must reach the collective check); until then it must not
          // reach the global vector.
          if (!culprit.empty())
            cell_rhs = 0;

          local_dof_indices.resize(n_dofs);
          cell->get_dof_indices(local_dof_indices);
          condensing.distribute_local_to_global(cell_matrix,
                                                cell_rhs,
                                                local_dof_indices,
                                                system_matrix,
                                                system_rhs);

          // The rows and columns of the contributions' own unknowns on the
          // cell, after its DoFs.
          if (n_own_unknowns > 0)
            for (unsigned int c = 0; c < contributions.size(); ++c)
              {
                const std::vector<unsigned int> own =
                  contributions[c]->own_unknowns_of(cell);
                if (own.empty())
                  continue;
                own_matrix.reinit(n_dofs + own.size(), n_dofs + own.size());
                own_rhs.reinit(n_dofs + own.size());
                contributions[c]->assemble_own(input,
                                               n_dofs,
                                               own_matrix,
                                               own_rhs);
                local_dof_indices.resize(n_dofs);
                for (const unsigned int k : own)
                  local_dof_indices.push_back(dof_handler.n_dofs() +
                                              own_offsets[c] + k);
                condensing.distribute_local_to_global(own_matrix,
                                                      own_rhs,
                                                      local_dof_indices,
                                                      system_matrix,
                                                      system_rhs);
              }
        }

    // Every rank stops with the first culprit any rank found.
    for (const std::string &message :
         Utilities::MPI::all_gather(mpi_communicator, culprit))
      check_input(message.empty(), message);

    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
  }



  template <int dim>
  void
  Simulator<dim>::create_contributions()
  {
    own_terms.clear();
    own_terms.push_back(
      std::make_unique<Assembly::Elasticity<dim>>(material.lambda(dim),
                                                  material.mu()));
    own_terms.push_back(std::make_unique<Assembly::BoundaryTractions<dim>>(
      fe_collection, face_quadrature_collection));
    // Only where a load set has them: a body force makes the cells' FEValues
    // compute shape values, which FE_Enriched's tables for tip rules of
    // hundreds of points make costly.
    bool body_force = false, lip_pressure = false;
    for (const LoadState<dim> *state :
         {&load_cycle.maximum(), &load_cycle.minimum()})
      {
        body_force   = body_force || state->loads->body_force;
        lip_pressure = lip_pressure || state->loads->lip_pressure;
      }
    if (body_force)
      own_terms.push_back(std::make_unique<Assembly::BodyForce<dim>>());
    if (lip_pressure && enrichment)
      own_terms.push_back(
        std::make_unique<Assembly::LipPressure<dim>>(*enrichment));
    contributions.clear();
    for (const auto &term : own_terms)
      contributions.push_back(term.get());
    if (contact)
      contributions.push_back(contact.get());
  }



  template <int dim>
  LinearSolver::MatrixProperty
  Simulator<dim>::matrix_property() const
  {
    bool saddle_point = false;
    for (const Assembly::Contribution<dim> *contribution : contributions)
      {
        if (!contribution->is_symmetric())
          return LinearSolver::MatrixProperty::general;
        saddle_point = saddle_point || contribution->has_own_unknowns();
      }
    return (saddle_point ? LinearSolver::MatrixProperty::symmetric :
                           LinearSolver::MatrixProperty::spd);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
