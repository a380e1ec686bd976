#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/k_error_estimator.h>

#include <algorithm>
#include <cmath>

namespace xcrack
{
  template <int dim>
  KErrorEstimator<dim>::KErrorEstimator(
    const DoFHandler<dim>                           &dof_handler,
    const Enrichment<dim>                           &enrichment,
    const AffineConstraints<double>                 &constraints,
    const Material                                  &material,
    const BoundaryConditions<dim>                   &boundary_conditions,
    const FEValuesOf                                &fe_values_of,
    const std::vector<std::vector<FrontPoint<dim>>> &front_points,
    const std::vector<FrontValues<dim>>             &front_values)
    : dof_handler(dof_handler)
    , enrichment(enrichment)
    , material(material)
    , boundary_conditions(boundary_conditions)
    , fe_values_of(fe_values_of)
    , fronts(front_points.size())
    , recovery_fe(FE_Q<dim>(1), n_components)
    , recovery_dof_handler(dof_handler.get_triangulation())
  {
    unit.mu    = material.mu();
    unit.kappa = material.kappa(dim);
    for (const auto &v : front_values)
      {
        Front &front = fronts[v.front];
        front.r_inf  = v.r_inf;
        front.r_sup  = v.r_sup;
        front.nodes.push_back(v.point.s);
      }
    for (unsigned int f = 0; f < fronts.size(); ++f)
      {
        fronts[f].curve =
          std::make_unique<FrontCurve<dim>>(front_points[f],
                                            0.5 * fronts[f].r_sup);
        std::sort(fronts[f].nodes.begin(), fronts[f].nodes.end());
      }

    recovery_dof_handler.distribute_dofs(recovery_fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(recovery_dof_handler, relevant);
    recovery_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(recovery_dof_handler,
                                            recovery_constraints);
    recovery_constraints.close();

    // An enriched DoF is free where it is not constrained to zero (those
    // of an enriched element at vertices the crack does not cut are).
    cut_at_vertex.assign(dof_handler.get_triangulation().n_vertices(), false);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const FiniteElement<dim> &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          // The vertex DoFs come first (the others, of a quadratic base,
          // are standard).
          for (unsigned int i = 0;
               i < cell->n_vertices() * fe.n_dofs_per_vertex();
               ++i)
            if (Enrichment<dim>::is_enriched_dof(fe, i))
              {
                const auto *entries =
                  constraints.get_constraint_entries(dofs[i]);
                if (entries == nullptr || !entries->empty() ||
                    constraints.get_inhomogeneity(dofs[i]) != 0)
                  cut_at_vertex[cell->vertex_index(
                    i / fe.n_dofs_per_vertex())] = true;
              }
        }
  }



  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  KErrorEstimator<dim>::Front::hats(const double s) const
  {
    const unsigned int n = nodes.size();
    if (n == 1)
      return {{0, 1.}};
    if (curve->closed && (s < nodes[0] || s >= nodes[n - 1]))
      {
        const double a = nodes[n - 1], b = nodes[0] + curve->length;
        const double t = ((s < nodes[0] ? s + curve->length : s) - a) / (b - a);
        return {{n - 1, 1 - t}, {0, t}};
      }
    if (s <= nodes[0])
      return {{0, 1.}};
    if (s >= nodes[n - 1])
      return {{n - 1, 1.}};
    const unsigned int i =
      std::upper_bound(nodes.begin(), nodes.end(), s) - nodes.begin() - 1;
    const double t = (s - nodes[i]) / (nodes[i + 1] - nodes[i]);
    return {{i, 1 - t}, {i + 1, t}};
  }



  template <int dim>
  double
  KErrorEstimator<dim>::singular_cutoff(const double distance,
                                        const double r_sup,
                                        const double h_s)
  {
    // Smooth steps (C1) in the distance and in h_s.
    const double t = std::clamp(distance / r_sup - 1, 0., 1.);
    const double c = std::clamp(4 * h_s - 2, 0., 1.);
    return (1 - t * t * (3 - 2 * t)) * c * c * (3 - 2 * c);
  }



  template <int dim>
  std::vector<typename KErrorEstimator<dim>::NearFront>
  KErrorEstimator<dim>::near_fronts(const Point<dim> &x) const
  {
    std::vector<NearFront> result;
    for (unsigned int f = 0; f < fronts.size(); ++f)
      {
        const Front &front      = fronts[f];
        const auto   projection = front.curve->project(x);
        const double distance   = x.distance(projection.foot);
        if (distance >= 2 * front.r_sup || distance == 0)
          continue;
        const Tensor<1, dim> xl = projection.R * (x - projection.foot);
        const double         r  = std::hypot(xl[0], xl[1]);
        if (r == 0)
          continue;
        NearFront near;
        near.front = f;
        near.hats  = front.hats(projection.s);
        near.chi =
          singular_cutoff(distance, front.r_sup, projection.jacobian_s(xl));
        if (near.chi == 0)
          continue;
        Tensor<2, dim> gradients[dim];
        aux_gradients<dim, dim>(
          unit, projection, xl, r, std::atan2(xl[1], xl[0]), gradients);
        for (unsigned int m = 0; m < n_modes; ++m)
          near.unit_stress[m] = material.stress<dim>(symmetrize(gradients[m]));
        result.push_back(std::move(near));
      }
    return result;
  }



  template <int dim>
  void
  KErrorEstimator<dim>::field_stresses(
    const FEValues<dim>                                      &values,
    const std::vector<const TrilinosWrappers::MPI::Vector *> &fields,
    std::vector<std::vector<SymmetricTensor<2, dim>>>        &stresses) const
  {
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      gradients(values.n_quadrature_points);
    stresses.resize(fields.size());
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        values[displacement].get_function_gradients(*fields[f], gradients);
        stresses[f].resize(values.n_quadrature_points);
        for (const unsigned int q : values.quadrature_point_indices())
          stresses[f][q] = material.stress<dim>(symmetrize(gradients[q]));
      }
  }



  template <int dim>
  double
  KErrorEstimator<dim>::energy_product(
    const SymmetricTensor<2, dim> &e,
    const SymmetricTensor<2, dim> &e_dual) const
  {
    const double mu     = material.mu();
    const double lambda = material.lambda(dim);
    return (e * e_dual -
            lambda / (2 * mu + dim * lambda) * trace(e) * trace(e_dual)) /
           (2 * mu);
  }



  template <int dim>
  std::vector<std::vector<std::vector<double>>>
  KErrorEstimator<dim>::fit(
    const std::vector<const TrilinosWrappers::MPI::Vector *> &fields) const
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    // Per front: the normal equations (unknowns node by node, mode by
    // mode), one right-hand side per field.
    std::vector<FullMatrix<double>>               matrices(fronts.size());
    std::vector<std::vector<std::vector<double>>> rhs(fields.size());
    for (unsigned int t = 0; t < fronts.size(); ++t)
      {
        const unsigned int n = fronts[t].nodes.size() * n_modes;
        matrices[t].reinit(n, n);
        for (auto &r : rhs)
          r.emplace_back(n, 0.);
      }
    std::vector<std::vector<SymmetricTensor<2, dim>>> stresses;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Only cells within r_inf of a front (where the 2D dual problems
          // carry no load) fit.
          bool close = false;
          for (const Front &front : fronts)
            close = close || (cell->center().distance(
                                front.curve->project(cell->center()).foot) <
                              front.r_inf + cell->diameter());
          if (!close)
            continue;
          std::vector<bool> inside(fronts.size(), true);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int t = 0; t < fronts.size(); ++t)
              inside[t] = inside[t] &&
                          cell->vertex(v).distance(
                            fronts[t].curve->project(cell->vertex(v)).foot) <=
                            fronts[t].r_inf;
          if (std::find(inside.begin(), inside.end(), true) == inside.end())
            continue;
          const FEValues<dim> &values = fe_values_of(cell);
          field_stresses(values, fields, stresses);
          for (const unsigned int q : values.quadrature_point_indices())
            for (const NearFront &near :
                 near_fronts(values.quadrature_point(q)))
              if (inside[near.front])
                {
                  const double JxW = values.JxW(q);
                  for (const auto &[k, phi] : near.hats)
                    for (unsigned int m = 0; m < n_modes; ++m)
                      {
                        const unsigned int row = k * n_modes + m;
                        for (const auto &[l, psi] : near.hats)
                          for (unsigned int n = 0; n < n_modes; ++n)
                            matrices[near.front](row, l * n_modes + n) +=
                              phi * psi *
                              energy_product(near.unit_stress[m],
                                             near.unit_stress[n]) *
                              JxW;
                        for (unsigned int f = 0; f < fields.size(); ++f)
                          rhs[f][near.front][row] +=
                            phi *
                            energy_product(near.unit_stress[m],
                                           stresses[f][q]) *
                            JxW;
                      }
                }
        }

    std::vector<std::vector<std::vector<double>>> result(fields.size());
    for (unsigned int t = 0; t < fronts.size(); ++t)
      {
        FullMatrix<double> matrix(matrices[t].m(), matrices[t].n());
        Utilities::MPI::sum(matrices[t], comm, matrix);
        // A node whose hats hold no fitting point gets c = 0.
        double largest = 0;
        for (unsigned int i = 0; i < matrix.m(); ++i)
          largest = std::max(largest, matrix(i, i));
        for (unsigned int i = 0; i < matrix.m(); ++i)
          matrix(i, i) += 1e-10 * largest + 1e-300;
        matrix.gauss_jordan();
        for (unsigned int f = 0; f < fields.size(); ++f)
          {
            Vector<double> b(rhs[f][t].size()), c(rhs[f][t].size());
            Utilities::MPI::sum(rhs[f][t], comm, rhs[f][t]);
            std::copy(rhs[f][t].begin(), rhs[f][t].end(), b.begin());
            matrix.vmult(c, b);
            result[f].emplace_back(c.begin(), c.end());
          }
      }
    return result;
  }



  template <int dim>
  unsigned int
  KErrorEstimator<dim>::slot(
    const CellIterator                                        &cell,
    const unsigned int                                         v,
    const std::pair<std::vector<double>, std::vector<double>> &level_sets,
    const Point<dim>                                          &xi) const
  {
    if (level_sets.first.empty() || !cut_at_vertex[cell->vertex_index(v)])
      return 0;
    double lsn = 0, lst = 0;
    for (const unsigned int w : cell->vertex_indices())
      {
        const double N = GeometryInfo<dim>::d_linear_shape_function(xi, w);
        lsn += level_sets.first[w] * N;
        lst += level_sets.second[w] * N;
      }
    if (lst >= 0)
      return 0;
    return (lsn > 0 ? 1 : 2);
  }



  template <int dim>
  std::vector<double>
  KErrorEstimator<dim>::estimate(
    const TrilinosWrappers::MPI::Vector              &solution,
    const std::vector<TrilinosWrappers::MPI::Vector> &duals,
    std::vector<Vector<float>>                       *shares) const
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    std::vector<const TrilinosWrappers::MPI::Vector *> fields = {&solution};
    for (const auto &z : duals)
      fields.push_back(&z);
    const unsigned int     n_fields     = fields.size();
    constexpr unsigned int n_vertices   = GeometryInfo<dim>::vertices_per_cell;
    const auto             coefficients = fit(fields);

    // The level sets of a cell at its vertices, where the crack cuts it.
    const auto level_sets_of = [&](const CellIterator &cell) {
      for (const unsigned int v : cell->vertex_indices())
        if (cut_at_vertex[cell->vertex_index(v)] &&
            cell->active_fe_index() != 0)
          return enrichment.level_set_values(cell);
      return std::pair<std::vector<double>, std::vector<double>>();
    };
    const auto recovery_cell = [&](const CellIterator &cell) {
      return typename DoFHandler<dim>::active_cell_iterator(
        &dof_handler.get_triangulation(),
        cell->level(),
        cell->index(),
        &recovery_dof_handler);
    };
    // sigma_h - sigma_s of each field at the points of a cell.
    std::vector<std::vector<SymmetricTensor<2, dim>>> rest;
    const auto rest_of = [&](const FEValues<dim> &values) {
      field_stresses(values, fields, rest);
      for (const unsigned int q : values.quadrature_point_indices())
        for (const NearFront &near : near_fronts(values.quadrature_point(q)))
          for (unsigned int f = 0; f < n_fields; ++f)
            for (const auto &[k, phi] : near.hats)
              for (unsigned int m = 0; m < n_modes; ++m)
                rest[f][q] -= (near.chi * phi *
                               coefficients[f][near.front][k * n_modes + m]) *
                              near.unit_stress[m];
    };

    // 1. Accumulate int N_v rest and int N_v per vertex and slot.
    const IndexSet &owned = recovery_dof_handler.locally_owned_dofs();
    IndexSet        relevant;
    DoFTools::extract_locally_relevant_dofs(recovery_dof_handler, relevant);
    std::vector<TrilinosWrappers::MPI::Vector> sums(
      n_fields, TrilinosWrappers::MPI::Vector(owned, comm));
    std::vector<types::global_dof_index> recovery_dofs(
      recovery_fe.n_dofs_per_cell());
    std::vector<double>       weights;
    std::vector<unsigned int> slots;
    Vector<double>            local(recovery_fe.n_dofs_per_cell());
    // The cell-local index of component k of slot s at vertex v, tabulated
    // (FiniteElement::component_to_system_index() searches a table).
    std::vector<unsigned int> index_table(n_vertices * n_components);
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < n_components; ++c)
        index_table[v * n_components + c] =
          recovery_fe.component_to_system_index(c, v);
    const auto index =
      [&](const unsigned int v, const unsigned int s, const unsigned int k) {
        return index_table[v * n_components + s * (n_stress + 1) + k];
      };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &values = fe_values_of(cell);
          rest_of(values);
          const auto level_sets = level_sets_of(cell);
          recovery_cell(cell)->get_dof_indices(recovery_dofs);
          // Each point's weight and slot at each vertex, the same for
          // every field.
          const unsigned int n_points = values.n_quadrature_points;
          weights.resize(n_points * n_vertices);
          slots.resize(n_points * n_vertices);
          for (const unsigned int q : values.quadrature_point_indices())
            {
              const Point<dim> &xi = values.get_quadrature().point(q);
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  weights[q * n_vertices + v] =
                    GeometryInfo<dim>::d_linear_shape_function(xi, v) *
                    values.JxW(q);
                  slots[q * n_vertices + v] = slot(cell, v, level_sets, xi);
                }
            }
          for (unsigned int f = 0; f < n_fields; ++f)
            {
              local = 0;
              for (unsigned int q = 0; q < n_points; ++q)
                for (unsigned int v = 0; v < n_vertices; ++v)
                  {
                    const double       w = weights[q * n_vertices + v];
                    const unsigned int s = slots[q * n_vertices + v];
                    for (unsigned int k = 0; k < n_stress; ++k)
                      local[index(v, s, k)] +=
                        w * rest[f][q].access_raw_entry(k);
                    local[index(v, s, n_stress)] += w;
                  }
              recovery_constraints.distribute_local_to_global(local,
                                                              recovery_dofs,
                                                              sums[f]);
            }
        }

    // 2. The averages, interpolated at hanging vertices; the mass slot
    // says whether the slot holds data (1) or not (0).
    std::vector<TrilinosWrappers::MPI::Vector> averages(n_fields);
    for (unsigned int f = 0; f < n_fields; ++f)
      {
        sums[f].compress(VectorOperation::add);
        TrilinosWrappers::MPI::Vector ghosted(owned, relevant, comm);
        ghosted = sums[f];
        TrilinosWrappers::MPI::Vector average(owned, comm);
        for (const auto &cell : recovery_dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(recovery_dofs);
              for (unsigned int v = 0; v < n_vertices; ++v)
                for (unsigned int s = 0; s < n_slots; ++s)
                  {
                    const auto mass_dof = recovery_dofs[index(v, s, n_stress)];
                    if (!owned.is_element(mass_dof))
                      continue;
                    const double mass = ghosted[mass_dof];
                    for (unsigned int k = 0; k < n_stress; ++k)
                      {
                        const auto dof = recovery_dofs[index(v, s, k)];
                        average[dof]   = (mass > 0 ? ghosted[dof] / mass : 0.);
                      }
                    average[mass_dof] = (mass > 0 ? 1. : 0.);
                  }
            }
        average.compress(VectorOperation::insert);
        recovery_constraints.distribute(average);
        averages[f].reinit(owned, relevant, comm);
        averages[f] = average;
      }

    // 3. The products of the stress errors sigma* - sigma_h = average -
    // rest, cell by cell.
    std::vector<double> result(duals.size(), 0.);
    if (shares)
      shares->assign(duals.size(),
                     Vector<float>(
                       dof_handler.get_triangulation().n_active_cells()));
    std::vector<SymmetricTensor<2, dim>> errors(n_fields);
    std::vector<double>                  share(duals.size());
    std::vector<Vector<double>>          cell_averages(
      n_fields, Vector<double>(recovery_fe.n_dofs_per_cell()));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &values = fe_values_of(cell);
          rest_of(values);
          const auto level_sets = level_sets_of(cell);
          // The averages on the cell (read from the vectors once).
          for (unsigned int f = 0; f < n_fields; ++f)
            recovery_cell(cell)->get_dof_values(averages[f], cell_averages[f]);
          std::fill(share.begin(), share.end(), 0.);
          for (const unsigned int q : values.quadrature_point_indices())
            {
              const Point<dim> &xi = values.get_quadrature().point(q);
              for (unsigned int f = 0; f < n_fields; ++f)
                errors[f] = -rest[f][q];
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  const double N =
                    GeometryInfo<dim>::d_linear_shape_function(xi, v);
                  // A slot without data (a side of a vertex whose support
                  // the crack barely cuts): the continuous slot, then the
                  // other side.
                  const unsigned int s0 = slot(cell, v, level_sets, xi);
                  unsigned int       s  = s0;
                  for (const unsigned int candidate : {s0, 0u, 3 - s0})
                    if (candidate < n_slots &&
                        cell_averages[0][index(v, candidate, n_stress)] > 0)
                      {
                        s = candidate;
                        break;
                      }
                  for (unsigned int f = 0; f < n_fields; ++f)
                    for (unsigned int k = 0; k < n_stress; ++k)
                      errors[f].access_raw_entry(k) +=
                        N * cell_averages[f][index(v, s, k)];
                }
              for (unsigned int d = 0; d < duals.size(); ++d)
                share[d] +=
                  energy_product(errors[0], errors[d + 1]) * values.JxW(q);
            }
          for (unsigned int d = 0; d < duals.size(); ++d)
            {
              result[d] += share[d];
              if (shares)
                (*shares)[d][cell->active_cell_index()] += share[d];
            }
        }
    add_dirichlet_term(fields, result, shares);
    Utilities::MPI::sum(result, comm, result);
    return result;
  }



  template <int dim>
  void
  KErrorEstimator<dim>::add_dirichlet_term(
    const std::vector<const TrilinosWrappers::MPI::Vector *> &fields,
    std::vector<double>                                      &result,
    std::vector<Vector<float>>                               *shares) const
  {
    if (boundary_conditions.dirichlet.empty())
      return;
    const hp::FECollection<dim> &fes = dof_handler.get_fe_collection();
    // g - u_h is the interpolation error of g: two points more than the
    // element's degree.
    hp::QCollection<dim - 1> rules;
    for (unsigned int i = 0; i < fes.size(); ++i)
      rules.push_back(QGauss<dim - 1>(fes[i].degree + 2));
    hp::FEFaceValues<dim>            hp_values(fes,
                                    rules,
                                    update_values | update_gradients |
                                      update_quadrature_points |
                                      update_normal_vectors |
                                      update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, dim>>      u_h;
    std::vector<Tensor<1, dim>>      error;
    std::vector<Tensor<2, dim>>      grad_z;
    Vector<double>                   g(dim);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int face : cell->face_indices())
          {
            if (!cell->face(face)->at_boundary())
              continue;
            const auto data = boundary_conditions.dirichlet.find(
              cell->face(face)->boundary_id());
            if (data == boundary_conditions.dirichlet.end())
              continue;
            const ComponentMask &mask =
              boundary_conditions.dirichlet_mask.at(data->first);
            hp_values.reinit(cell, face);
            const FEFaceValues<dim> &values = hp_values.get_present_fe_values();
            const unsigned int       n_points = values.n_quadrature_points;
            // The error on the prescribed components.
            u_h.resize(n_points);
            values[displacement].get_function_values(*fields[0], u_h);
            error.assign(n_points, Tensor<1, dim>());
            for (unsigned int q = 0; q < n_points; ++q)
              {
                data->second->vector_value(values.quadrature_point(q), g);
                for (unsigned int c = 0; c < dim; ++c)
                  if (mask[c])
                    error[q][c] = g[c] - u_h[q][c];
              }
            grad_z.resize(n_points);
            for (unsigned int d = 0; d + 1 < fields.size(); ++d)
              {
                values[displacement].get_function_gradients(*fields[d + 1],
                                                            grad_z);
                double share = 0;
                for (unsigned int q = 0; q < n_points; ++q)
                  share -= error[q] *
                           (material.stress<dim>(symmetrize(grad_z[q])) *
                            values.normal_vector(q)) *
                           values.JxW(q);
                result[d] += share;
                if (shares)
                  (*shares)[d][cell->active_cell_index()] += share;
              }
          }
  }



  template class KErrorEstimator<2>;
  template class KErrorEstimator<3>;
} // namespace xcrack
