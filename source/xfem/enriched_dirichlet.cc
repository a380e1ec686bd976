#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/input_error.h>
#include <xcrack/xfem/enriched_dirichlet.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace xcrack
{
  namespace
  {
    /// What the boundary faces tell about one standard DoF (a node and a
    /// displacement component).
    template <int dim>
    struct BoundaryNode
    {
      /// The free enriched DoFs of the same node and component.
      std::vector<types::global_dof_index> enriched;
      std::vector<const Function<dim> *>   functions;
      /// Side of the crack (+1, -1) -> point just inside a face, data.
      std::map<int, std::pair<Point<dim>, double>> sides;
      /// Points of the Dirichlet faces around a vertex, with the weight
      /// (quadrature weight times the vertex's hat function) and the data.
      std::vector<std::tuple<Point<dim>, double, double>> samples;
      bool                                                branches = false;
    };

    /**
     * The copy of @p dof that stays free: the hanging-node constraints tie
     * the copies of a node's DoFs (one per element around it) with
     * dof = other, or set enriched copies to zero next to plain cells.
     * invalid_dof_index if no copy stays free.
     */
    types::global_dof_index
    free_copy(const AffineConstraints<double> &constraints,
              types::global_dof_index          dof)
    {
      while (constraints.is_constrained(dof))
        {
          const auto *entries = constraints.get_constraint_entries(dof);
          if (entries->size() != 1 || (*entries)[0].second != 1. ||
              constraints.get_inhomogeneity(dof) != 0.)
            return numbers::invalid_dof_index;
          dof = (*entries)[0].first;
        }
      return dof;
    }

    /**
     * Least squares on the node's boundary patch: s + sum_j phi_j a_j should
     * match the data g at the patch's points x_q (weights w_q); the fitted
     * s and a_j are all prescribed. Leaving some of them free (those a
     * patch hardly sees, far from the front) relaxes the boundary condition
     * and the discrete solution exploits it: on Case 1 with every node
     * enriched the energy error grows from 1e-4 to 2e-2. Far from the front
     * the branch functions are nearly affine across a patch and the normal
     * matrix nearly singular, yet data from the enriched space still has
     * large components along those directions (dropping eigenvalues below
     * 1e-10 of the largest also gave 1e-2): the matrix is solved in
     * variables scaled to a unit diagonal by a pseudo-inverse that only
     * drops numerically zero eigenvalues (below 1e-15 of the largest).
     */
    template <int dim>
    void
    constrain_by_local_fit(const types::global_dof_index standard,
                           const BoundaryNode<dim>      &node,
                           AffineConstraints<double>    &constraints)
    {
      const unsigned int  m = 1 + node.enriched.size();
      FullMatrix<double>  normal(m, m);
      Vector<double>      rhs(m);
      std::vector<double> phi(m);
      for (const auto &[point, weight, g] : node.samples)
        {
          phi[0] = 1;
          for (unsigned int j = 1; j < m; ++j)
            phi[j] = node.functions[j - 1]->value(point);
          for (unsigned int i = 0; i < m; ++i)
            {
              rhs(i) += weight * phi[i] * g;
              for (unsigned int j = 0; j < m; ++j)
                normal(i, j) += weight * phi[i] * phi[j];
            }
        }
      std::vector<double> scale(m);
      for (unsigned int i = 0; i < m; ++i)
        scale[i] = (normal(i, i) > 0 ? std::sqrt(normal(i, i)) : 1.);
      LAPACKFullMatrix<double> scaled(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          scaled(i, j) = normal(i, j) / (scale[i] * scale[j]);
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      scaled.compute_eigenvalues_symmetric(
        -1, 2 * m, 0, eigenvalues, eigenvectors);
      const double largest = eigenvalues(eigenvalues.size() - 1);

      std::vector<double> x(m, 0.);
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        if (eigenvalues(k) > 1e-15 * largest)
          {
            double q_b = 0;
            for (unsigned int i = 0; i < m; ++i)
              q_b += eigenvectors(i, k) * rhs(i) / scale[i];
            for (unsigned int i = 0; i < m; ++i)
              x[i] += eigenvectors(i, k) * q_b / eigenvalues(k);
          }

      std::vector<types::global_dof_index> dofs = {standard};
      dofs.insert(dofs.end(), node.enriched.begin(), node.enriched.end());
      for (unsigned int j = 0; j < m; ++j)
        if (!constraints.is_constrained(dofs[j]))
          {
            constraints.add_line(dofs[j]);
            constraints.set_inhomogeneity(dofs[j], x[j] / scale[j]);
          }
    }



    /**
     * s + sum_j phi_j a_j = g on each side the node's faces lie on: s from
     * the mean over the sides, and at a crack mouth also the jump, solved
     * for the enriched DoF with the largest jump of its function (a =
     * (g+ - g-)/2 for H).
     */
    template <int dim>
    void
    constrain_by_sides(const types::global_dof_index standard,
                       const BoundaryNode<dim>      &node,
                       AffineConstraints<double>    &constraints)
    {
      const unsigned int  n = node.enriched.size();
      std::vector<double> mean(n, 0.), jump(n, 0.);
      double              g_mean = 0, g_jump = 0;
      for (const auto &[side, data] : node.sides)
        {
          const double weight = 1. / node.sides.size();
          g_mean += weight * data.second;
          g_jump += side * data.second;
          for (unsigned int j = 0; j < n; ++j)
            {
              const double phi = node.functions[j]->value(data.first);
              mean[j] += weight * phi;
              jump[j] += side * phi;
            }
        }
      constraints.add_line(standard);
      for (unsigned int j = 0; j < n; ++j)
        constraints.add_entry(standard, node.enriched[j], -mean[j]);
      constraints.set_inhomogeneity(standard, g_mean);
      if (node.sides.size() != 2)
        return;
      unsigned int p = 0;
      for (unsigned int j = 1; j < n; ++j)
        if (std::abs(jump[j]) > std::abs(jump[p]))
          p = j;
      if (std::abs(jump[p]) <= 1e-12 ||
          constraints.is_constrained(node.enriched[p]))
        return;
      constraints.add_line(node.enriched[p]);
      for (unsigned int j = 0; j < n; ++j)
        if (j != p)
          constraints.add_entry(node.enriched[p],
                                node.enriched[j],
                                -jump[j] / jump[p]);
      constraints.set_inhomogeneity(node.enriched[p], g_jump / jump[p]);
    }
  } // namespace



  template <int dim>
  void
  make_enriched_dirichlet_constraints(
    const DoFHandler<dim>         &dof_handler,
    const Enrichment<dim>         &enrichment,
    const BoundaryConditions<dim> &boundary_conditions,
    AffineConstraints<double>     &constraints)
  {
    // Only the DoFs of owned cells need constraints, and only for them is
    // the enrichment known completely (their supports are owned or ghost).
    IndexSet locally_active_dofs;
    DoFTools::extract_locally_active_dofs(dof_handler, locally_active_dofs);
    const IndexSet enriched_dofs = enrichment.enriched_dofs(dof_handler);

    std::map<types::global_dof_index, BoundaryNode<dim>> nodes; // by s
    std::set<types::global_dof_index>                    partners;
    std::vector<types::global_dof_index>                 dofs;
    const QGauss<dim - 1>                                face_rule(3);
    const FE_Q<dim - 1>                                  face_q1(1);
    Vector<double> g(dim), g_sample(dim), g_beyond(dim);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() &&
          cell->active_fe_index() != Enrichment<dim>::plain)
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary())
              continue;
            const LevelSetFunctions<dim> &crack = enrichment.crack_of(cell);
            // lsn at the cell's vertices, by vertex index: the crossings of
            // the face's edges come from these, not from evaluations at the
            // vertices (whose round-off would pick a side where the crack
            // was fitted to a vertex).
            std::map<unsigned int, double> vertex_lsn;
            {
              const std::vector<double> lsn =
                enrichment.level_set_values(cell).first;
              for (const unsigned int v : cell->vertex_indices())
                vertex_lsn[cell->vertex_index(v)] = lsn[v];
            }
            const auto bc =
              boundary_conditions.dirichlet.find(face->boundary_id());
            if (bc == boundary_conditions.dirichlet.end())
              continue;
            const ComponentMask &mask =
              boundary_conditions.dirichlet_mask.at(face->boundary_id());
            const FiniteElement<dim> &fe = cell->get_fe();
            dofs.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);

            // The face's DoFs by the node they belong to (a vertex; for Q2
            // a line or the face itself), with the node's position: face
            // DoFs are numbered vertices first, then lines, then the quad.
            std::map<unsigned int, std::vector<unsigned int>> groups;
            std::map<unsigned int, Point<dim>>                positions;
            const unsigned int                                vertex_block =
              fe.n_dofs_per_vertex() * face->n_vertices();
            const unsigned int line_block =
              (dim == 3 ? fe.n_dofs_per_line() * face->n_lines() : 0);
            for (unsigned int k = 0; k < fe.n_dofs_per_face(f); ++k)
              {
                unsigned int group;
                Point<dim>   position;
                if (k < vertex_block)
                  {
                    group    = k / fe.n_dofs_per_vertex();
                    position = face->vertex(group);
                  }
                else if (k < vertex_block + line_block)
                  {
                    const unsigned int l =
                      (k - vertex_block) / fe.n_dofs_per_line();
                    group    = 100 + l;
                    position = face->line(l)->center();
                  }
                else
                  {
                    group    = 200;
                    position = face->center();
                  }
                groups[group].push_back(
                  fe.face_to_cell_index(k,
                                        f,
                                        cell->face_orientation(f),
                                        cell->face_flip(f),
                                        cell->face_rotation(f)));
                positions[group] = position;
              }

            for (const auto &[group, members] : groups)
              {
                // The data of this face's side at the node: evaluate just
                // inside the face. Where fit to vertex moved the crack
                // through the node, the data still has its crack where it
                // was, |shift| away: evaluate beyond that.
                double hair = 1e-10;
                if (group < face->n_vertices())
                  {
                    const auto  &shifts = enrichment.lsn_shift();
                    const double shift =
                      (enrichment.crack_index(cell) < shifts.size() &&
                           !shifts[enrichment.crack_index(cell)].empty() ?
                         shifts[enrichment.crack_index(cell)]
                               [face->vertex_index(group)] :
                         0.);
                    hair =
                      std::max(hair,
                               2 * std::abs(shift) /
                                 positions[group].distance(face->center()));
                  }
                const Point<dim> x =
                  positions[group] + hair * (face->center() - positions[group]);
                const int side = (crack.lsn(x) >= 0 ? 1 : -1);
                bc->second->vector_value(x, g);
                // A face the crack cuts (a mouth) also holds the other side:
                // the node's jump DoFs must take the jump of the data, or
                // the part of the face beyond the crack would be left free
                // (a roller there let the lips slide along it). The data of
                // the other side is taken just beyond the crossing nearest
                // to the node: exact for data constant on each side.
                std::optional<Point<dim>> beyond;
                double                    nearest = 0;
                for (unsigned int l = 0; l < (dim == 2 ? 1 : face->n_lines());
                     ++l)
                  {
                    const Point<dim> a =
                      (dim == 2 ? face->vertex(0) : face->line(l)->vertex(0));
                    const Point<dim> b =
                      (dim == 2 ? face->vertex(1) : face->line(l)->vertex(1));
                    const double la =
                      vertex_lsn.at(dim == 2 ? face->vertex_index(0) :
                                               face->line(l)->vertex_index(0));
                    const double lb =
                      vertex_lsn.at(dim == 2 ? face->vertex_index(1) :
                                               face->line(l)->vertex_index(1));
                    if (la * lb >= 0)
                      continue;
                    const Point<dim> crossing = a + la / (la - lb) * (b - a);
                    const Point<dim> far_end = ((la > 0) == (side > 0) ? b : a);
                    if (!beyond ||
                        crossing.distance(positions[group]) < nearest)
                      {
                        // Beyond by a hair of the edge, but never past its
                        // far end (a crack very near a vertex).
                        nearest = crossing.distance(positions[group]);
                        const double step =
                          std::min(1e-10 * a.distance(b),
                                   0.5 * crossing.distance(far_end));
                        beyond = crossing + step * (far_end - crossing) /
                                              crossing.distance(far_end);
                      }
                  }
                if (beyond)
                  bc->second->vector_value(*beyond, g_beyond);
                for (const unsigned int i : members)
                  {
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    const types::global_dof_index standard =
                      free_copy(constraints, dofs[i]);
                    if (!mask[c] || Enrichment<dim>::is_enriched_dof(fe, i) ||
                        standard == numbers::invalid_dof_index)
                      continue;
                    BoundaryNode<dim> &node = nodes[standard];
                    for (const unsigned int j : members)
                      {
                        if (!Enrichment<dim>::is_enriched_dof(fe, j) ||
                            fe.system_to_component_index(j).first != c)
                          continue;
                        partners.insert(dofs[j]);
                        // A gathered DoF stays itself: its tie to the
                        // masters is resolved when the constraints close.
                        const types::global_dof_index a =
                          (enrichment.gathered().is_element(dofs[j]) ?
                             dofs[j] :
                             free_copy(constraints, dofs[j]));
                        if (a == numbers::invalid_dof_index ||
                            std::find(node.enriched.begin(),
                                      node.enriched.end(),
                                      a) != node.enriched.end())
                          continue;
                        node.enriched.push_back(a);
                        node.functions.push_back(
                          enrichment.enrichment_function(cell, j));
                        node.branches =
                          node.branches ||
                          dynamic_cast<const BranchFunction<dim> *>(
                            node.functions.back());
                      }
                    // With Q2, the standard DoFs at edge midpoints see the
                    // Q1 hats of the neighbouring vertices' branch DoFs;
                    // nodal data for them is not implemented.
                    check_input(!node.branches || fe.degree == 1,
                                "Discretization/Degree = 2: the crack-tip "
                                "zone reaches boundary " +
                                  std::to_string(face->boundary_id()) +
                                  ", which has prescribed displacements; "
                                  "this is only implemented for Degree = 1. "
                                  "Use a smaller Enrichment/Enrichment radius "
                                  "or Degree = 1.");
                    node.sides[side] = {x, g[c]};
                    if (beyond)
                      node.sides.emplace(-side,
                                         std::make_pair(*beyond, g_beyond[c]));
                    if (group >= face->n_vertices())
                      continue;
                    for (unsigned int q = 0; q < face_rule.size(); ++q)
                      {
                        Point<dim> y;
                        for (const unsigned int w : face->vertex_indices())
                          y += face_q1.shape_value(w, face_rule.point(q)) *
                               face->vertex(w);
                        bc->second->vector_value(y, g_sample);
                        node.samples.emplace_back(
                          y,
                          face_rule.weight(q) *
                            face_q1.shape_value(group, face_rule.point(q)) *
                            face->measure(),
                          g_sample[c]);
                      }
                  }
              }
          }

    for (const auto &[id, function] : boundary_conditions.dirichlet)
      {
        std::map<types::global_dof_index, double> values;
        VectorTools::interpolate_boundary_values(
          dof_handler,
          id,
          *function,
          values,
          boundary_conditions.dirichlet_mask.at(id));
        for (const auto &[dof, value] : values)
          {
            if (constraints.is_constrained(dof) ||
                !locally_active_dofs.is_element(dof))
              continue;
            if (enriched_dofs.is_element(dof))
              {
                // Enriched DoFs are handled with their standard partner.
                Assert(partners.count(dof) == 1,
                       ExcMessage("An enriched DoF on a Dirichlet boundary "
                                  "has no standard partner."));
                continue;
              }
            const auto node = nodes.find(dof);
            if (node == nodes.end() || node->second.enriched.empty())
              {
                constraints.add_line(dof);
                constraints.set_inhomogeneity(dof, value);
              }
            else if (node->second.branches &&
                     !enrichment.get_parameters().gather)
              constrain_by_local_fit(dof, node->second, constraints);
            else
              constrain_by_sides(dof, node->second, constraints);
          }
      }
  }



  template void
  make_enriched_dirichlet_constraints<2>(const DoFHandler<2> &,
                                         const Enrichment<2> &,
                                         const BoundaryConditions<2> &,
                                         AffineConstraints<double> &);
  template void
  make_enriched_dirichlet_constraints<3>(const DoFHandler<3> &,
                                         const Enrichment<3> &,
                                         const BoundaryConditions<3> &,
                                         AffineConstraints<double> &);
} // namespace xcrack
