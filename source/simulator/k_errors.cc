#include <deal.II/base/mpi.h>

#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/k_error_estimator.h>
#include <xcrack/simulator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

// The K error estimate's part of the Simulator: the wide crown, as wide as
// the boundary and the other fronts allow, and the estimate on it
// (Fracture parameters/Error estimate).
namespace xcrack
{
  namespace
  {
    /// The distance from @p x to the nearest of @p fronts (polylines, or
    /// points in 2D).
    template <int dim>
    double
    distance_to_fronts(const std::vector<FrontCurve<dim>> &curves,
                       const Point<dim>                   &x)
    {
      double d = std::numeric_limits<double>::max();
      for (const auto &curve : curves)
        if (curve.points.size() == 1)
          d = std::min(d, x.distance(curve.points[0].position));
        else
          for (unsigned int i = 0; i + 1 < curve.points.size(); ++i)
            d = std::min(d, curve.segment_distance(i, x));
      return d;
    }



    /**
     * The smallest radius of curvature of a 3D front: of the circles
     * through the points a sixteenth of the front apart (the front's
     * points come from the level sets and wander by O(h) from point to
     * point; over that span the circle reads the shape, not the noise).
     * Infinite for a point or a straight front.
     */
    template <int dim>
    double
    radius_of_curvature(const FrontCurve<dim> &curve)
    {
      double radius = std::numeric_limits<double>::max();
      if constexpr (dim == 3)
        {
          if (curve.points.size() < 3)
            return radius;
          const double span = curve.length / 16;
          for (unsigned int k = 0; k <= 64; ++k)
            {
              double s = curve.length * k / 64;
              if (!curve.closed)
                s = std::clamp(s, span, curve.length - span);
              const auto wrap = [&](const double t) {
                return curve.closed ?
                         t - curve.length * std::floor(t / curve.length) :
                         t;
              };
              const Point<dim>     a  = curve.at(wrap(s - span)).position;
              const Point<dim>     b  = curve.at(s).position;
              const Point<dim>     c  = curve.at(wrap(s + span)).position;
              const Tensor<1, dim> ab = b - a, bc = c - b, ca = a - c;
              const double         twice_area = cross_product_3d(ab, bc).norm();
              if (twice_area > 1e-12 * ab.norm() * bc.norm())
                radius = std::min(radius,
                                  ab.norm() * bc.norm() * ca.norm() /
                                    (2 * twice_area));
            }
        }
      return radius;
    }

    /// The wide crown's inner radius on a mesh fine at the fronts, as a
    /// fraction of its outer one.
    constexpr double wide_inner_fraction = 1. / 9;
  } // namespace



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::wide_crown(
    const std::vector<std::vector<FrontPoint<dim>>> &fronts) const
  {
    // From r_inf to r_sup = 0.9 d, d the distance from the fronts to the
    // boundary (in 3D, from the boundary points that lie in the normal
    // plane of a front point, not beyond the ends of an open front: a
    // surface crack's front ends on the boundary) and to each other,
    // r_inf = 0.1 d but at least two cells of the front. Along a curved
    // front also r_sup <= rho / 2, rho the smallest radius of curvature:
    // the crown's frames stay those of the nearest front stretch.
    std::vector<FrontCurve<dim>> curves;
    for (const auto &front : fronts)
      curves.emplace_back(front, 0);
    double clear = std::numeric_limits<double>::max();
    double h     = std::numeric_limits<double>::max();
    // (The cells, not the DoF handler's: this runs before the first set-up
    // too.)
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The cells the fronts cross (as InteractionIntegral measures
          // the crown's cells).
          bool at_front = false;
          if (dim == 2)
            for (const auto &front : fronts)
              at_front = at_front || cell->point_inside(front[0].position);
          else
            at_front = distance_to_fronts(curves, cell->center()) <
                       0.5 * cell->diameter();
          if (at_front)
            h = std::min(h, cell->diameter() / std::sqrt(double(dim)));
          // The boundary faces' vertices, and in 3D their centres (on a
          // mesh one cell thick along a front, every vertex lies beside one
          // of the front's ends).
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary())
              for (unsigned int v = 0;
                   v < cell->face(face)->n_vertices() + (dim == 3);
                   ++v)
                for (const auto &curve : curves)
                  {
                    const Point<dim> x = (v < cell->face(face)->n_vertices() ?
                                            cell->face(face)->vertex(v) :
                                            cell->face(face)->center());
                    const auto       projection = curve.project(x);
                    // (An open front's end lies on the boundary, and the
                    // vertices there project on it, up to round-off.)
                    const double s = projection.s;
                    const bool   at_end =
                      projection.at_end || (dim == 3 && !curve.closed &&
                                            (s < 1e-8 * curve.length ||
                                             s > (1 - 1e-8) * curve.length));
                    if (!at_end)
                      clear = std::min(clear, x.distance(projection.foot));
                  }
        }
    for (unsigned int f = 0; f < fronts.size(); ++f)
      for (unsigned int g = 0; g < f; ++g)
        for (const auto &p : fronts[f])
          clear =
            std::min(clear, distance_to_fronts<dim>({curves[g]}, p.position));
    double rho = std::numeric_limits<double>::max();
    for (const auto &curve : curves)
      rho = std::min(rho, radius_of_curvature(curve));
    clear              = Utilities::MPI::min(clear, mpi_communicator);
    h                  = Utilities::MPI::min(h, mpi_communicator);
    const double outer = std::min(0.9 * clear, 0.5 * rho);
    // (On a mesh too coarse for it the crown shrinks to half its width;
    // the run then says the estimate is unreliable.)
    return {std::min(std::max(wide_inner_fraction * outer, 2 * h), 0.5 * outer),
            outer};
  }



  template <int dim>
  void
  Simulator<dim>::expect_wide_crown(
    const std::vector<std::vector<FrontPoint<dim>>> &fronts)
  {
    // Widened as estimate_k_errors() will (there with the K's crown of the
    // solve), and its inner radius that of a mesh fine at the fronts: two
    // of the present cells there would ask a coarse mesh for a narrow crown
    // and so for many cells that the solve to come would not need.
    double outer = wide_crown(fronts).second;
    if (!fracture_parameters.crown_in_cells)
      outer = std::max(outer, fracture_parameters.crown_outer);
    k_error_cells.crown_inner = wide_inner_fraction * outer;
    k_error_cells.crown_outer = outer;
  }



  template <int dim>
  void
  Simulator<dim>::estimate_k_errors(
    const std::vector<std::vector<FrontPoint<dim>>>         &fronts,
    const typename InteractionIntegral<dim>::FEValuesOf     &fe_values_of,
    const typename InteractionIntegral<dim>::LipsOf         &lips_of,
    const typename InteractionIntegral<dim>::BoundaryFaceOf &faces)
  {
    FractureParameters wide                      = fracture_parameters;
    wide.crown_in_cells                          = false;
    wide.smooth_weight                           = true;
    std::tie(wide.crown_inner, wide.crown_outer) = wide_crown(fronts);
    // Never narrower than the reported K's crown (a coarse front's
    // polygon has corners of a small radius of curvature): the run then
    // says that the estimate is unreliable rather than stop.
    for (const auto &v : front_values)
      wide.crown_outer = std::max(wide.crown_outer, v.r_sup);
    wide.crown_inner = std::min(wide.crown_inner, 0.5 * wide.crown_outer);
    // Along a 3D front: the wide crown's K on the nodes of the reported
    // ones, which the difference of the two K's needs.
    if constexpr (dim == 3)
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          unsigned int n = 0;
          for (const auto &v : front_values)
            n += (v.front == f);
          const bool closed =
            fronts[f].size() > 2 &&
            fronts[f].front().position == fronts[f].back().position;
          wide.node_segments.push_back(closed ? n : n - 1);
        }

    // The wide crown's width in its coarsest cells (on a graded mesh, not
    // the tip's), the distances to the fronts those a refinement strategy
    // reads (LevelSetFields::cell_front_distances()): what the strategy
    // refines until the crown is fine enough, the estimate then trusts.
    const std::vector<double> distances = level_sets.cell_front_distances();
    double                    h_crown   = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double r    = distances[cell->active_cell_index()];
          const double half = cell->diameter() / 2;
          if (r + half > wide.crown_inner && r - half < wide.crown_outer)
            h_crown =
              std::max(h_crown, cell->diameter() / std::sqrt(double(dim)));
        }
    h_crown                   = Utilities::MPI::max(h_crown, mpi_communicator);
    k_error_cells.crown_inner = wide.crown_inner;
    k_error_cells.crown_outer = wide.crown_outer;
    k_error_cells.crown_cells =
      (h_crown > 0 ? (wide.crown_outer - wide.crown_inner) / h_crown : 0.);

    // K on the wide crown and its derivatives, condensed by the
    // homogeneous constraints (the dual problems' test space).
    AffineConstraints<double> homogeneous;
    homogeneous.copy_from(constraints);
    for (const auto &line : constraints.get_lines())
      homogeneous.set_inhomogeneity(line.index, 0.);
    KDerivatives derivatives;
    derivatives.constraints = &homogeneous;
    const std::vector<FrontValues<dim>> wide_values =
      InteractionIntegral<dim>(wide, material)
        .compute(dof_handler,
                 solution,
                 fronts,
                 fe_values_of,
                 boundary_conditions.lip_pressure.get(),
                 lips_of,
                 boundary_conditions.body_force.get(),
                 &derivatives,
                 typename InteractionIntegral<dim>::LipTraction(),
                 faces);

    // The dual solutions, one per test function and mode (their
    // combinations give the K nodes'), with the factorization of the solve;
    // estimated a few at a time: the recovery holds 21 (3D) values per
    // vertex and field.
    const KErrorEstimator<dim>         estimator(dof_handler,
                                         *enrichment,
                                         constraints,
                                         material,
                                         boundary_conditions,
                                         fe_values_of,
                                         fronts,
                                         wide_values);
    const unsigned int                 n_tests = derivatives.test_loads.size();
    std::vector<std::array<double, 3>> test_errors(n_tests, {{0, 0, 0}});
    // (At most about 1 GB of recovered stresses: 1.2e8 values, two
    // vectors per field.)
    const unsigned int tests_per_batch = std::max<types::global_dof_index>(
      1, 120'000'000 / (2 * dim * estimator.n_recovery_dofs()));
    // Each dual's signed shares per cell, [test][mode], kept until the
    // nodes' errors are known.
    std::vector<std::vector<Vector<float>>> test_shares(n_tests);
    for (unsigned int first = 0; first < n_tests; first += tests_per_batch)
      {
        const unsigned int end = std::min(first + tests_per_batch, n_tests);
        std::vector<TrilinosWrappers::MPI::Vector> duals;
        for (unsigned int t = first; t < end; ++t)
          for (const auto &load : derivatives.test_loads[t])
            {
              TrilinosWrappers::MPI::Vector z(locally_owned_dofs,
                                              mpi_communicator);
              linear_solver->solve_again(z, load);
              homogeneous.distribute(z);
              duals.emplace_back(locally_owned_dofs,
                                 locally_relevant_dofs,
                                 mpi_communicator);
              duals.back() = z;
            }
        std::vector<Vector<float>> shares;
        const std::vector<double>  errors =
          estimator.estimate(solution, duals, &shares);
        unsigned int d = 0;
        for (unsigned int t = first; t < end; ++t)
          for (unsigned int m = 0; m < derivatives.test_loads[t].size(); ++m)
            {
              test_errors[t][m] = errors[d];
              test_shares[t].push_back(std::move(shares[d]));
              ++d;
            }
      }
    // K_exact - K = (K_wide - K) + (K_exact - K_wide).
    std::vector<std::array<double, 3>> differences(front_values.size());
    double                             largest = 0;
    for (unsigned int i = 0; i < front_values.size(); ++i)
      {
        const FrontValues<dim> &w = wide_values[i];
        const FrontValues<dim> &v = front_values[i];
        differences[i] = {{w.k_I - v.k_I, w.k_II - v.k_II, w.k_III - v.k_III}};
        for (unsigned int m = 0; m < dim; ++m)
          {
            double error = 0;
            for (const auto &[t, weight] : derivatives.node_weights[i])
              error += weight * test_errors[t][m];
            front_values[i].k_error[m] = differences[i][m] + error;
            largest = std::max(largest, std::abs(front_values[i].k_error[m]));
          }
      }

    // The indicators. Each K node's error is a functional of its own (its
    // dual the weighted sum of the tests'), and so are its cells' shares;
    // they count by the node's estimated error relative to the largest, so
    // that the marking aims at the K's that miss the goal (the sum of all
    // duals' |shares| weighed a mode or node whose K is accurate as much:
    // doc/verification.md, "Along a 3D front"). The difference of the two
    // K's is the error of the crown at the node: shared among the cells
    // within that crown.
    k_error_cells.indicators.reinit(triangulation.n_active_cells());
    for (unsigned int i = 0; i < front_values.size() && largest > 0; ++i)
      {
        const FrontValues<dim>   &v = front_values[i];
        std::vector<unsigned int> crown_cells;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center().distance(v.point.position) < v.r_sup)
            crown_cells.push_back(cell->active_cell_index());
        const double n_crown_cells =
          Utilities::MPI::sum(double(crown_cells.size()), mpi_communicator);
        for (unsigned int m = 0; m < dim; ++m)
          {
            const double goal = std::abs(v.k_error[m]) / largest;
            for (unsigned int c = 0; c < k_error_cells.indicators.size(); ++c)
              {
                double share = 0;
                for (const auto &[t, weight] : derivatives.node_weights[i])
                  share += weight * test_shares[t][m][c];
                k_error_cells.indicators[c] += goal * std::abs(share);
              }
            for (const unsigned int c : crown_cells)
              k_error_cells.indicators[c] +=
                goal * std::abs(differences[i][m]) / n_crown_cells;
          }
      }
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
