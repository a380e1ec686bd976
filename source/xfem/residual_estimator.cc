#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <xcrack/xfem/cell_quadrature.h>
#include <xcrack/xfem/residual_estimator.h>

#include <algorithm>
#include <cmath>

namespace xcrack
{
  namespace
  {
    /// Move reference point @p p by @p offset inside the unit cell.
    template <int dim>
    Point<dim>
    inside_unit_cell(Point<dim> p, const double offset)
    {
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = std::clamp(p[d], offset, 1 - offset);
      return p;
    }

    /// The unit cell as a box.
    template <int dim>
    BoundingBox<dim>
    unit_box()
    {
      Point<dim> one;
      for (unsigned int d = 0; d < dim; ++d)
        one[d] = 1;
      return BoundingBox<dim>(std::make_pair(Point<dim>(), one));
    }

    /// Where the sides of a face are read, in reference coordinates: the
    /// enrichment functions take each cell's one-sided values there.
    constexpr double hair = 1e-8;
  } // namespace



  template <int dim>
  ResidualEstimator<dim>::ResidualEstimator(
    const Enrichment<dim>         *enrichment,
    const BoundaryConditions<dim> &boundary_conditions,
    const double                   lambda,
    const double                   mu)
    : enrichment(enrichment)
    , boundary_conditions(boundary_conditions)
    , lambda(lambda)
    , mu(mu)
  {}



  template <int dim>
  SymmetricTensor<2, dim>
  ResidualEstimator<dim>::stress(const Tensor<2, dim> &gradient) const
  {
    const SymmetricTensor<2, dim> strain = symmetrize(gradient);
    return lambda * trace(strain) * unit_symmetric_tensor<dim>() +
           2 * mu * strain;
  }



  template <int dim>
  bool
  ResidualEstimator<dim>::is_cut(const CellIterator &cell) const
  {
    return enrichment &&
           (enrichment->is_split(cell) || enrichment->is_tip(cell));
  }



  template <int dim>
  Tensor<1, dim>
  ResidualEstimator<dim>::boundary_residual(
    const types::boundary_id id,
    const Point<dim>        &x,
    const Tensor<1, dim>    &traction) const
  {
    Tensor<1, dim> residual = traction;
    if (const auto it = boundary_conditions.neumann.find(id);
        it != boundary_conditions.neumann.end())
      {
        Vector<double> t(dim);
        it->second->vector_value(x, t);
        for (unsigned int c = 0; c < dim; ++c)
          residual[c] -= t(c);
      }
    if (boundary_conditions.dirichlet.count(id))
      {
        const auto it = boundary_conditions.dirichlet_mask.find(id);
        const auto mask =
          (it == boundary_conditions.dirichlet_mask.end() ? ComponentMask() :
                                                            it->second);
        for (unsigned int c = 0; c < dim; ++c)
          if (mask[c])
            residual[c] = 0;
      }
    return residual;
  }



  template <int dim>
  double
  ResidualEstimator<dim>::cut_face_term(
    const CellIterator                  &cell,
    const unsigned int                   face_no,
    const CellIterator                  &neighbor,
    const BoundingBox<dim>              &box,
    const double                         h,
    const TrilinosWrappers::MPI::Vector &solution) const
  {
    // The crack that classifies the face: the cell's, or, for a cell
    // without enriched functions, its neighbour's read at its vertices.
    const bool at_boundary = (neighbor.state() != IteratorState::valid);
    std::vector<double> lsn(GeometryInfo<dim>::vertices_per_cell, 1.);
    std::vector<double> lst = lsn;
    if (cell->active_fe_index() != Enrichment<dim>::plain)
      std::tie(lsn, lst) = enrichment->level_set_values(cell);
    else if (!at_boundary &&
             neighbor->active_fe_index() != Enrichment<dim>::plain)
      {
        const LevelSetFunctions<dim> &crack = enrichment->crack_of(neighbor);
        for (const unsigned int v : cell->vertex_indices())
          {
            lsn[v] = crack.lsn(cell->vertex(v));
            lst[v] = crack.lst(cell->vertex(v));
          }
      }
    const unsigned int n_points_1d =
      cell->get_dof_handler().get_fe_collection().max_degree() + 1;
    const CellQuadrature::FaceRule<dim> rule = CellQuadrature::face_rule<dim>(
      lsn, lst, face_no, box, n_points_1d, 1e-12 * cell->diameter());
    if (rule.points.empty())
      return 0;

    std::vector<Point<dim>> points;
    for (const Point<dim> &p : rule.points)
      points.push_back(inside_unit_cell(p, hair));
    FEValues<dim> here(cell->get_fe(),
                       Quadrature<dim>(points),
                       update_gradients | update_quadrature_points |
                         update_jacobians);
    here.reinit(cell);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<2, dim>>      gradients(points.size());
    here[u].get_function_gradients(solution, gradients);

    std::vector<Tensor<2, dim>> neighbor_gradients;
    if (!at_boundary)
      {
        std::vector<Point<dim>> neighbor_points;
        for (unsigned int q = 0; q < points.size(); ++q)
          neighbor_points.push_back(
            inside_unit_cell(mapping.transform_real_to_unit_cell(
                               neighbor, here.quadrature_point(q)),
                             hair));
        FEValues<dim> there(neighbor->get_fe(),
                            Quadrature<dim>(neighbor_points),
                            update_gradients);
        there.reinit(neighbor);
        neighbor_gradients.resize(points.size());
        there[u].get_function_gradients(solution, neighbor_gradients);
      }

    Tensor<1, dim> reference_normal;
    reference_normal[face_no / 2] = (face_no % 2 ? 1 : -1);
    double sum                    = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const Tensor<1, dim> n_ds =
          CellQuadrature::mapped_normal<dim>(here.jacobian(q),
                                             reference_normal,
                                             rule.weights[q]);
        const double         ds       = n_ds.norm();
        const Tensor<1, dim> n        = n_ds / ds;
        const Point<dim>    &x        = here.quadrature_point(q);
        const Tensor<1, dim> traction = stress(gradients[q]) * n;
        if (at_boundary)
          sum +=
            h *
            boundary_residual(cell->face(face_no)->boundary_id(), x, traction)
              .norm_square() *
            ds;
        else if (rule.on_lip[q])
          {
            const double p = (boundary_conditions.lip_pressure ?
                                boundary_conditions.lip_pressure->value(x) :
                                0.);
            sum += h * (traction + p * n).norm_square() * ds;
          }
        else
          sum += h / 2 *
                 (traction - stress(neighbor_gradients[q]) * n).norm_square() *
                 ds;
      }
    return sum;
  }



  template <int dim>
  double
  ResidualEstimator<dim>::lip_term(
    const CellIterator                  &cell,
    const TrilinosWrappers::MPI::Vector &solution) const
  {
    const auto rule = enrichment->lip_quadrature(cell);
    // A crack in one of the cell's faces is read by the face terms.
    std::vector<Point<dim>>     points;
    std::vector<Tensor<1, dim>> normals;
    std::vector<double>         weights;
    for (unsigned int q = 0; q < rule.size(); ++q)
      if (inside_unit_cell(rule.point(q), 1e-12).distance(rule.point(q)) == 0)
        {
          points.push_back(rule.point(q));
          normals.push_back(rule.normal_vector(q));
          weights.push_back(rule.weight(q));
        }
    if (points.empty())
      return 0;
    FEValues<dim> sides(
      cell->get_fe(),
      Quadrature<dim>(CellQuadrature::both_sides(points, normals, hair)),
      update_gradients | update_quadrature_points | update_jacobians);
    sides.reinit(cell);
    std::vector<Tensor<2, dim>> gradients(2 * points.size());
    sides[FEValuesExtractors::Vector(0)].get_function_gradients(solution,
                                                                gradients);
    double sum = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const Tensor<1, dim> n_ds =
          CellQuadrature::mapped_normal<dim>(sides.jacobian(2 * q),
                                             normals[q],
                                             weights[q]);
        const double         ds = n_ds.norm();
        const Tensor<1, dim> n  = n_ds / ds;
        const double         p  = (boundary_conditions.lip_pressure ?
                                     boundary_conditions.lip_pressure->value(
                              sides.quadrature_point(2 * q)) :
                                     0.);
        for (const unsigned int side : {2 * q, 2 * q + 1})
          sum += cell->diameter() *
                 (stress(gradients[side]) * n + p * n).norm_square() * ds;
      }
    return sum;
  }



  template <int dim>
  void
  ResidualEstimator<dim>::estimate(
    const DoFHandler<dim>               &dof_handler,
    const TrilinosWrappers::MPI::Vector &solution,
    Vector<float>                       &indicators) const
  {
    const hp::FECollection<dim> &fes = dof_handler.get_fe_collection();
    hp::QCollection<dim - 1>     face_rules;
    for (unsigned int i = 0; i < fes.size(); ++i)
      face_rules.push_back(QGauss<dim - 1>(fes.max_degree() + 1));
    const UpdateFlags here_flags = update_gradients | update_normal_vectors |
                                   update_JxW_values | update_quadrature_points;
    hp::FEFaceValues<dim>    here(fes, face_rules, here_flags);
    hp::FESubfaceValues<dim> here_sub(fes, face_rules, here_flags);
    hp::FEFaceValues<dim>    there(fes, face_rules, update_gradients);
    hp::FESubfaceValues<dim> there_sub(fes, face_rules, update_gradients);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<2, dim>>      gradients, neighbor_gradients;

    // h_F/2 |[sigma n]|^2 over a face both sides of which see the same
    // points (as deal.II's Kelly estimator pairs them).
    const auto jump = [&](const FEFaceValuesBase<dim> &a,
                          const FEFaceValuesBase<dim> &b,
                          const double                 h) {
      gradients.resize(a.n_quadrature_points);
      neighbor_gradients.resize(a.n_quadrature_points);
      a[u].get_function_gradients(solution, gradients);
      b[u].get_function_gradients(solution, neighbor_gradients);
      double sum = 0;
      for (const unsigned int q : a.quadrature_point_indices())
        sum += h / 2 *
               ((stress(gradients[q]) - stress(neighbor_gradients[q])) *
                a.normal_vector(q))
                 .norm_square() *
               a.JxW(q);
      return sum;
    };

    indicators.reinit(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double eta2 = 0;
          for (const unsigned int f : cell->face_indices())
            {
              if (cell->at_boundary(f))
                {
                  if (is_cut(cell))
                    {
                      eta2 += cut_face_term(cell,
                                            f,
                                            CellIterator(),
                                            unit_box<dim>(),
                                            cell->face(f)->diameter(),
                                            solution);
                      continue;
                    }
                  here.reinit(cell, f);
                  const FEFaceValues<dim> &a = here.get_present_fe_values();
                  gradients.resize(a.n_quadrature_points);
                  a[u].get_function_gradients(solution, gradients);
                  for (const unsigned int q : a.quadrature_point_indices())
                    eta2 += cell->face(f)->diameter() *
                            boundary_residual(cell->face(f)->boundary_id(),
                                              a.quadrature_point(q),
                                              stress(gradients[q]) *
                                                a.normal_vector(q))
                              .norm_square() *
                            a.JxW(q);
                }
              else if (cell->face(f)->has_children())
                {
                  // A finer neighbour: one piece per child face.
                  const unsigned int neighbor_face =
                    cell->neighbor_of_neighbor(f);
                  for (unsigned int s = 0; s < cell->face(f)->n_children(); ++s)
                    {
                      const CellIterator child =
                        cell->neighbor_child_on_subface(f, s);
                      if (is_cut(cell) || is_cut(child))
                        {
                          // The child face's part of the reference cell.
                          std::vector<Point<dim>> corners;
                          for (const unsigned int v :
                               cell->face(f)->child(s)->vertex_indices())
                            corners.push_back(
                              mapping.transform_real_to_unit_cell(
                                cell, cell->face(f)->child(s)->vertex(v)));
                          BoundingBox<dim> box(corners);
                          auto             bounds = box.get_boundary_points();
                          bounds.first[f / 2]     = 0;
                          bounds.second[f / 2]    = 1;
                          eta2 +=
                            cut_face_term(cell,
                                          f,
                                          child,
                                          BoundingBox<dim>(bounds),
                                          cell->face(f)->child(s)->diameter(),
                                          solution);
                        }
                      else
                        {
                          here_sub.reinit(cell, f, s);
                          there.reinit(child, neighbor_face);
                          eta2 += jump(here_sub.get_present_fe_values(),
                                       there.get_present_fe_values(),
                                       cell->face(f)->child(s)->diameter());
                        }
                    }
                }
              else
                {
                  const CellIterator neighbor = cell->neighbor(f);
                  if (is_cut(cell) || is_cut(neighbor))
                    eta2 += cut_face_term(cell,
                                          f,
                                          neighbor,
                                          unit_box<dim>(),
                                          cell->face(f)->diameter(),
                                          solution);
                  else if (cell->neighbor_is_coarser(f))
                    {
                      const auto [nf, ns] =
                        cell->neighbor_of_coarser_neighbor(f);
                      here.reinit(cell, f);
                      there_sub.reinit(neighbor, nf, ns);
                      eta2 += jump(here.get_present_fe_values(),
                                   there_sub.get_present_fe_values(),
                                   cell->face(f)->diameter());
                    }
                  else
                    {
                      here.reinit(cell, f);
                      there.reinit(neighbor, cell->neighbor_of_neighbor(f));
                      eta2 += jump(here.get_present_fe_values(),
                                   there.get_present_fe_values(),
                                   cell->face(f)->diameter());
                    }
                }
            }
          if (is_cut(cell))
            eta2 += lip_term(cell, solution);
          indicators(cell->active_cell_index()) = std::sqrt(eta2 / (2 * mu));
        }
  }



  template class ResidualEstimator<2>;
  template class ResidualEstimator<3>;
} // namespace xcrack
