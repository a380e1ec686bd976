#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <xcrack/elastic_cell_matrix.h>
#include <xcrack/input_error.h>
#include <xcrack/simulator.h>
#include <xcrack/xfem/cell_quadrature.h>

#include <cmath>
#include <sstream>

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
  Simulator<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "assemble");

    const double lambda = material.lambda(dim);
    const double mu     = material.mu();

    // Shape values only for a body force: the stiffness reads gradients,
    // and FE_Enriched's tables for a tip rule of 750 points are large.
    hp::FEValues<dim> hp_fe_values(
      fe_collection,
      quadrature_collection,
      (boundary_conditions.body_force ? update_values : update_default) |
        update_gradients | update_quadrature_points | update_JxW_values);
    hp::FEFaceValues<dim> hp_fe_face_values(fe_collection,
                                            face_quadrature_collection,
                                            update_values |
                                              update_quadrature_points |
                                              update_JxW_values);

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> local_dof_indices;
    ElasticCellMatrix<dim>               stiffness;
    std::vector<Vector<double>>          load;
    SpecialFEValues                      special_values;
    // The first load that is not finite where it is used, on this rank.
    std::string culprit;
    const auto  check = [&culprit](const std::vector<Vector<double>> &values,
                                  const std::vector<Point<dim>>     &points,
                                  const std::string                 &entry) {
      for (unsigned int q = 0; q < values.size() && culprit.empty(); ++q)
        for (const double v : values[q])
          if (!std::isfinite(v))
            {
              std::ostringstream message;
              message << entry << " is not finite at (" << points[q]
                      << "), where it is used: " << v << ".";
              culprit = message.str();
              break;
            }
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &fe_values =
            reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
          const unsigned int n_dofs = fe_values.dofs_per_cell;
          cell_rhs.reinit(n_dofs);

          if (boundary_conditions.body_force)
            {
              load.resize(fe_values.n_quadrature_points, Vector<double>(dim));
              boundary_conditions.body_force->vector_value_list(
                fe_values.get_quadrature_points(), load);
              check(load,
                    fe_values.get_quadrature_points(),
                    "Boundary conditions/Body force");
            }

          stiffness.compute(fe_values, lambda, mu, cell_matrix);
          if (boundary_conditions.body_force)
            for (const unsigned int q : fe_values.quadrature_point_indices())
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int c =
                    fe_values.get_fe().system_to_component_index(i).first;
                  cell_rhs(i) +=
                    fe_values.shape_value(i, q) * load[q](c) * fe_values.JxW(q);
                }

          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const auto it =
                  boundary_conditions.neumann.find(face->boundary_id());
                if (it == boundary_conditions.neumann.end())
                  continue;
                hp_fe_face_values.reinit(cell, face);
                const FEFaceValues<dim> &fe_face_values =
                  hp_fe_face_values.get_present_fe_values();
                load.resize(fe_face_values.n_quadrature_points,
                            Vector<double>(dim));
                it->second->vector_value_list(
                  fe_face_values.get_quadrature_points(), load);
                check(load,
                      fe_face_values.get_quadrature_points(),
                      "Boundary conditions/Neumann (boundary " +
                        std::to_string(face->boundary_id()) + ")");
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      const unsigned int c =
                        fe_values.get_fe().system_to_component_index(i).first;
                      cell_rhs(i) += fe_face_values.shape_value(i, q) *
                                     load[q](c) * fe_face_values.JxW(q);
                    }
              }

          if (boundary_conditions.lip_pressure)
            {
              add_lip_pressure(cell, cell_rhs);
              for (const double v : cell_rhs)
                if (!std::isfinite(v) && culprit.empty())
                  {
                    std::ostringstream message;
                    message << "Boundary conditions/Lip pressure is not "
                               "finite on the lips in the cell at ("
                            << cell->center() << ").";
                    culprit = message.str();
                  }
            }

          // A load that is not finite is reported after the loop (every
          // rank must reach the collective check); until then it must not
          // reach the global vector.
          if (!culprit.empty())
            cell_rhs = 0;

          local_dof_indices.resize(n_dofs);
          cell->get_dof_indices(local_dof_indices);
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_rhs,
                                                 local_dof_indices,
                                                 system_matrix,
                                                 system_rhs);
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
  Simulator<dim>::add_lip_pressure(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    Vector<double>                                       &cell_rhs) const
  {
    if (!enrichment)
      return;
    const auto rule = enrichment->lip_quadrature(cell);
    if (rule.size() == 0)
      return;
    const FiniteElement<dim> &fe = cell->get_fe();
    FEValues<dim>             sides(
      fe,
      Quadrature<dim>(CellQuadrature::both_sides(rule.get_points(),
                                                 rule.get_normal_vectors())),
      update_values | update_quadrature_points | update_jacobians);
    sides.reinit(cell);
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const Tensor<1, dim> n_ds =
          CellQuadrature::mapped_normal<dim>(sides.jacobian(2 * q),
                                             rule.normal_vector(q),
                                             rule.weight(q));
        const double p = boundary_conditions.lip_pressure->value(
          sides.quadrature_point(2 * q));
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            cell_rhs(i) +=
              p * n_ds[c] *
              (sides.shape_value(i, 2 * q) - sides.shape_value(i, 2 * q + 1));
          }
      }
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
