#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>

#include <xcrack/fracture/displacement_jump.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/k_error_estimator.h>
#include <xcrack/output_file.h>
#include <xcrack/simulator.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::compute_fracture_parameters(const LoadState<dim> &state,
                                              const bool            report)
  {
    TimerOutput::Scope t(*timer, "fracture");
    // The fronts of all cracks, numbered one after the other.
    std::vector<std::vector<FrontPoint<dim>>> fronts;
    for (const auto &surface : crack_surfaces)
      fronts.insert(fronts.end(),
                    surface.fronts().begin(),
                    surface.fronts().end());
    if (fronts.empty())
      return;

    // No shape values: the integrals and the estimate read gradients only
    // (FE_Enriched's tables for a tip rule of 750 points are large).
    hp::FEValues<dim> hp_fe_values(fe_collection,
                                   quadrature_collection,
                                   update_gradients | update_quadrature_points |
                                     update_JxW_values |
                                     update_inverse_jacobians);
    SpecialFEValues   special_values;
    const auto fe_values_of = [&](const auto &cell) -> const FEValues<dim> & {
      return reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
    };
    const auto lips_of = [&](const auto                  &cell,
                             std::vector<Point<dim>>     &points,
                             std::vector<double>         &weights,
                             std::vector<Tensor<1, dim>> &normals) {
      const auto rule = enrichment->lip_quadrature(cell);
      points          = rule.get_points();
      weights         = rule.get_weights();
      normals         = rule.get_normal_vectors();
    };
    const InteractionIntegral<dim> integral(fracture_parameters, material);
    const auto lip_pressure = scaled(state.loads->lip_pressure.get(), state);
    const auto body_force   = scaled(state.loads->body_force.get(), state);
    // Closed lips press on each other: their tractions load the lips.
    typename InteractionIntegral<dim>::LipTraction contact_traction;
    if (contact)
      contact_traction = [this](const auto &cell, const unsigned int k) {
        return contact->lip_traction(cell->id(), k);
      };
    const auto faces = boundary_face_of(state);
    front_values     = integral.compute(dof_handler,
                                    solution,
                                    fronts,
                                    fe_values_of,
                                    lip_pressure.get(),
                                    lips_of,
                                    body_force.get(),
                                    nullptr,
                                    contact_traction,
                                    faces);
    // Where the lips touch at the front, it is closed. Without contact, a
    // negative K_I says that the lips pass through each other there: the
    // point is closed too, and its K's are those of a body that does not
    // exist (Propagation does not grow it).
    for (FrontValues<dim> &v : front_values)
      v.closed =
        (contact ? contact->closed_fraction(v.point.position, v.r_inf) > 0.5 :
                   v.k_I < 0);
    if (!report)
      return;
    const bool estimate = fracture_parameters.error_estimate;
    if (estimate)
      estimate_k_errors(fronts, fe_values_of, lips_of, faces);

    // The cross-check by the displacement jumps over the crown.
    const MappingQ1<dim>        mapping;
    const GridTools::Cache<dim> cache(triangulation, mapping);
    for (auto &v : front_values)
      v.k_jump = displacement_jump_k(dof_handler,
                                     cache,
                                     solution,
                                     v.point,
                                     material,
                                     v.r_inf,
                                     v.r_sup,
                                     enrichment.get());
    flag_unreliable_points();
    const auto &values = front_values;
    // In a growth run the screen shows one line per step; the values are
    // in front_<step>.csv.
    ConditionalOStream out(std::cout, pcout.is_active() && detailed_screen);

    // The reference K at each point, if given.
    std::vector<Vector<double>> reference(values.size());
    const Function<dim>        *reference_function = nullptr;
    if constexpr (dim == 2)
      reference_function = fracture_parameters.reference_2d.get();
    else
      reference_function = fracture_parameters.reference_3d.get();
    if (reference_function)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          reference[i].reinit(dim);
          reference_function->vector_value(values[i].point.position,
                                           reference[i]);
        }
    const auto k_of = [](const FrontValues<dim> &v, const unsigned int m) {
      return (m == 0 ? v.k_I : m == 1 ? v.k_II : v.k_III);
    };
    constexpr unsigned int n_modes       = dim;
    const char            *mode_names[3] = {"K_I", "K_II", "K_III"};

    const auto warn_crown = [&](const FrontValues<dim> &v) {
      if (!v.crown_clear)
        out << "  Warning: the crown of " << (dim == 2 ? "tip " : "front ")
            << v.front + 1 << " (r_sup = " << v.r_sup
            << ") reaches the boundary or another "
            << (dim == 2 ? "tip" : "front")
            << "; its K and G are unreliable. Use smaller Fracture "
               "parameters/Crown radii or a finer mesh there."
            << std::endl;
    };

    // What closed points mean: with contact, lips that touch; without, a
    // negative K_I, lips that pass through each other.
    const auto closed_words = [&](const unsigned int n_closed,
                                  const unsigned int n) {
      std::ostringstream words;
      const std::string  where =
        (n == 1 ? "the tip" :
                  std::to_string(n_closed) + " of its " + std::to_string(n) +
                    " points");
      if (contact)
        words << "    the lips are closed at " << where << ": K_I counts as 0"
              << (n == 1 ? "" : " there");
      else
        words << "    K_I < 0 at " << where << ": the lips pass through each "
              << "other (Contact/Formulation = none); closed, "
              << (n == 1 ? "it does" : "they do") << " not grow";
      return words.str();
    };

    // On screen, K's are rounded to 1e-6 of the largest one: a K that
    // vanishes by symmetry then reads 0 rather than round-off that differs
    // between builds (the CSV files and the statistics keep every digit).
    if constexpr (dim == 2)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          const auto  &v = values[i];
          const double quantum =
            1e-6 * std::max({std::abs(v.k_I), std::abs(v.k_II), 1e-300});
          const auto rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          out << "  tip " << i + 1 << std::scientific << std::setprecision(6)
              << ": K_I = " << rounded(v.k_I) << ", K_II = " << rounded(v.k_II)
              << ", G = " << v.g << ", G_Irwin = " << v.g_irwin << std::endl
              << "    displacement jumps: ";
          if (std::isfinite(v.k_jump[0]))
            out << "K_I = " << rounded(v.k_jump[0])
                << ", K_II = " << rounded(v.k_jump[1]);
          else
            out << "none (the lips across the crown are too short or kinked)";
          out << std::defaultfloat << std::endl;
          if (estimate)
            out << "    estimated errors (K_exact - K): K_I " << std::scientific
                << std::setprecision(2) << rounded(v.k_error[0]) << ", K_II "
                << rounded(v.k_error[1]) << std::defaultfloat
                << (k_error_cells.crown_cells < 4 ?
                      " (unreliable: the mesh is too coarse for the dual "
                      "problem, its crown is less than 4 cells wide)" :
                      "")
                << std::endl;
          if (v.closed)
            out << closed_words(1, 1) << std::endl;
          warn_crown(v);
          const std::string suffix = "_" + std::to_string(i + 1);
          statistics.add_value("K_I" + suffix, v.k_I);
          statistics.add_value("K_II" + suffix, v.k_II);
          statistics.add_value("G" + suffix, v.g);
          // (Left empty where the lips do not reach across the crown.)
          if (std::isfinite(v.k_jump[0]))
            {
              statistics.add_value("K_I_jump" + suffix, v.k_jump[0]);
              statistics.add_value("K_II_jump" + suffix, v.k_jump[1]);
            }
          if (estimate)
            {
              statistics.add_value("K_I_estimate" + suffix, v.k_error[0]);
              statistics.add_value("K_II_estimate" + suffix, v.k_error[1]);
              if (i == 0)
                statistics.add_value("estimate_crown_cells",
                                     k_error_cells.crown_cells);
            }
        }
    else
      // Per front: the range and mean of each K over its nodes, and the
      // largest gap between G-theta and Irwin's G.
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          double       k_min[3] = {1e300, 1e300, 1e300};
          double       k_max[3] = {-1e300, -1e300, -1e300}, k_mean[3] = {};
          double       largest = 1e-300, irwin_gap = 0, g_max = 1e-300;
          double       estimate_max[3] = {0, 0, 0};
          unsigned int n               = 0;
          for (const auto &v : values)
            if (v.front == f)
              {
                for (unsigned int m = 0; m < 3; ++m)
                  {
                    k_min[m] = std::min(k_min[m], k_of(v, m));
                    k_max[m] = std::max(k_max[m], k_of(v, m));
                    k_mean[m] += k_of(v, m);
                    largest = std::max(largest, std::abs(k_of(v, m)));
                    estimate_max[m] =
                      std::max(estimate_max[m], std::abs(v.k_error[m]));
                  }
                irwin_gap = std::max(irwin_gap, std::abs(v.g - v.g_irwin));
                g_max     = std::max(g_max, std::abs(v.g));
                ++n;
              }
          const double quantum = 1e-6 * largest;
          const auto   rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          std::string basis;
          for (const auto &v : values)
            if (v.front == f)
              basis = v.basis;
          out << "  front " << f + 1 << ": " << n << " points (" << basis
              << "), " << std::scientific << std::setprecision(6);
          for (unsigned int m = 0; m < 3; ++m)
            {
              k_mean[m] /= n;
              out << (m > 0 ? "; " : "") << mode_names[m] << " in ["
                  << rounded(k_min[m]) << ", " << rounded(k_max[m]) << "]";
              const std::string suffix = "_" + std::to_string(f + 1);
              statistics.add_value(std::string(mode_names[m]) + "_min" + suffix,
                                   k_min[m]);
              statistics.add_value(std::string(mode_names[m]) + "_max" + suffix,
                                   k_max[m]);
              if (estimate)
                statistics.add_value(std::string(mode_names[m]) +
                                       "_estimate_max" + suffix,
                                     estimate_max[m]);
            }
          out << std::endl
              << "    |G - G_Irwin| / max G = " << std::setprecision(2)
              << std::round(irwin_gap / g_max * 1e4) * 1e-4 << std::defaultfloat
              << std::endl;
          if (estimate)
            {
              out << "    estimated errors (K_exact - K), largest along the "
                     "front: "
                  << std::scientific << std::setprecision(2);
              for (unsigned int m = 0; m < 3; ++m)
                out << (m > 0 ? ", " : "") << mode_names[m] << " "
                    << rounded(estimate_max[m]);
              out << std::defaultfloat
                  << (k_error_cells.crown_cells < 4 ?
                        " (unreliable: the mesh is too coarse for the dual "
                        "problem, its crown is less than 4 cells wide)" :
                        "")
                  << std::endl;
              if (f == 0)
                statistics.add_value("estimate_crown_cells",
                                     k_error_cells.crown_cells);
            }
          unsigned int n_closed = 0;
          for (const auto &v : values)
            n_closed += (v.front == f && v.closed);
          if (n_closed > 0)
            out << closed_words(n_closed, n) << std::endl;
          for (const auto &v : values)
            if (v.front == f && !v.crown_clear)
              {
                warn_crown(v);
                break;
              }
        }
    // Errors against the reference: relative to |K| where it does not
    // vanish (2D), or (3D) to the largest |K| of that mode along the front
    // (K_II and K_III vary in sign along a front under shear); absolute
    // where the reference is zero altogether.
    if (reference_function)
      {
        double error[3] = {0, 0, 0};
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            double scale = 0, overall = 0;
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                scale   = std::max(scale, std::abs(reference[i][m]));
                overall = std::max(overall, reference[i].l2_norm());
              }
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                double norm = (scale > 1e-12 * overall ? scale : overall);
                if (dim == 2)
                  norm = (std::abs(reference[i][m]) >
                              1e-12 * reference[i].l2_norm() ?
                            std::abs(reference[i][m]) :
                            reference[i].l2_norm());
                // A reference that vanishes altogether: the absolute error.
                if (norm == 0)
                  norm = 1;
                error[m] =
                  std::max(error[m],
                           std::abs(k_of(values[i], m) - reference[i][m]) /
                             norm);
              }
            statistics.add_value(std::string(mode_names[m]) + "_error",
                                 error[m]);
          }
        out << "  K errors against the reference (max over the "
            << (dim == 2 ? "tips" : "front")
            << ", to 1e-6): " << std::scientific << std::setprecision(3);
        for (unsigned int m = 0; m < n_modes; ++m)
          out << (m > 0 ? ", " : "") << mode_names[m] << " "
              << std::round(error[m] * 1e6) * 1e-6;
        out << std::defaultfloat << std::endl;
      }
  }



  template <int dim>
  void
  Simulator<dim>::flag_unreliable_points()
  {
    // The files say which points a run cannot trust (front_<key>.csv per
    // point, statistics.csv per solve): the screen's warnings alone are
    // lost once the run is over.
    unsigned long long       n_unreliable = 0;
    std::vector<std::string> reasons;
    for (const FrontValues<dim> &v : front_values)
      if (const std::string why = v.unreliable_reason(); !why.empty())
        {
          ++n_unreliable;
          if (std::find(reasons.begin(), reasons.end(), why) == reasons.end())
            reasons.push_back(why);
        }
    std::string text;
    for (const std::string &why : reasons)
      text += (text.empty() ? "" : "; ") + why;
    statistics.add_value("unreliable_points", n_unreliable);
    statistics.add_text("reason", text);
  }



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
  typename InteractionIntegral<dim>::BoundaryFaceOf
  Simulator<dim>::boundary_face_of(const LoadState<dim> &state) const
  {
    // The Neumann data of the state, scaled by its factor, shared by the
    // returned function's copies.
    auto tractions = std::make_shared<
      std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>>();
    for (const auto &[id, traction] : state.loads->neumann)
      (*tractions)[id] = scaled(traction.get(), state);
    return
      [this, tractions, &state](const auto &cell, const unsigned int face_no) {
        typename InteractionIntegral<dim>::BoundaryFace face;
        const types::boundary_id id = cell->face(face_no)->boundary_id();
        face.constrained            = state.loads->dirichlet.count(id) > 0;
        const auto traction         = tractions->find(id);
        if (traction != tractions->end())
          face.traction = traction->second.get();
        if (!face.constrained)
          face.rule = enrichment->boundary_face_quadrature(cell, face_no);
        return face;
      };
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



  template <int dim>
  void
  Simulator<dim>::write_front_file(const std::string &key) const
  {
    write_file(run_parameters.output_directory + "/front_" + key + ".csv",
               [&](std::ostream &csv) { write_front_table(csv); });
    run_record->add_file("front_" + key + ".csv");
  }



  template <int dim>
  void
  Simulator<dim>::write_front_table(std::ostream &csv) const
  {
    csv << "index,s,x,y,z,K_I,K_II,K_III,G,G_Irwin,r_inf,r_sup,"
           "K_I_jump,K_II_jump,K_III_jump,front,closed";
    // The estimates of K_exact - K, when asked for.
    const bool errors = fracture_parameters.error_estimate;
    if (errors)
      csv << ",K_I_error,K_II_error,K_III_error";
    // The moves of a growth step: the K's at the minimum of the load
    // cycle, the equivalent K, its range, the rate, the kink angle
    // (radians) and the advance to the next step.
    const bool moves =
      (front_moves.size() == front_values.size() && !front_moves.empty());
    if (moves)
      csv << ",K_I_min,K_II_min,K_III_min,K_eq,delta_K,rate,angle,advance";
    // Last: whether the point's K (and its growth) cannot be trusted, and
    // why.
    csv << ",unreliable,reason";
    csv << '\n' << std::setprecision(10);
    for (unsigned int i = 0; i < front_values.size(); ++i)
      {
        const auto &v = front_values[i];
        csv << i << ',' << v.point.s << ',' << v.point.position[0] << ','
            << v.point.position[1] << ','
            << (dim == 3 ? v.point.position[dim - 1] : 0.) << ',' << v.k_I
            << ',' << v.k_II << ',' << v.k_III << ',' << v.g << ',' << v.g_irwin
            << ',' << v.r_inf << ',' << v.r_sup << ',';
        // No cross-check where the lips do not reach across the crown.
        if (std::isfinite(v.k_jump[0]))
          csv << v.k_jump[0] << ',' << v.k_jump[1] << ',' << v.k_jump[2];
        else
          csv << ",,";
        csv << ',' << v.front + 1 << ',' << v.closed;
        if (errors)
          csv << ',' << v.k_error[0] << ',' << v.k_error[1] << ','
              << v.k_error[2];
        if (moves)
          {
            // A rate that is not finite ended the run (check_rates()): its
            // field stays empty rather than holding inf or nan.
            const auto &m = front_moves[i];
            csv << ',' << m.k_minimum[0] << ',' << m.k_minimum[1] << ','
                << m.k_minimum[2] << ',' << m.k_eq << ',' << m.delta_k << ',';
            if (std::isfinite(m.rate))
              csv << m.rate;
            csv << ',' << m.angle << ',' << m.advance;
          }
        const std::string why = v.unreliable_reason();
        csv << ',' << !why.empty() << ',' << why << '\n';
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
