#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/hanging_vertices.h>
#include <xcrack/fracture/integral_derivatives.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/input_error.h>
#include <xcrack/xfem/cell_quadrature.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace xcrack
{
  void
  FractureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture parameters");
    {
      prm.declare_entry("Compute",
                        "true",
                        Patterns::Bool(),
                        "Extract K_I, K_II (, K_III) and G at the crack "
                        "tips or along the fronts after each solve and "
                        "write front_<step>.csv.");
      prm.declare_entry(
        "Error estimate",
        "false",
        Patterns::Bool(),
        "Estimate the error of every K (K_exact - K, written as "
        "K_I_error, ... beside the K's): a goal-oriented estimate with "
        "recovered stresses on a crown as wide as the body allows, one "
        "dual solve per K mode and tip (3D: per test function of the "
        "smoothing basis) with the solver's factorization. See "
        "doc/verification.md for its effectivity and cost.");
      prm.declare_entry("Crown radii",
                        "2, 4",
                        Patterns::Anything(),
                        "r_inf, r_sup of the virtual extension q: 1 within "
                        "r_inf of the tip, 0 beyond r_sup, linear between.");
      prm.declare_entry("Crown unit",
                        "cells",
                        Patterns::Selection("cells|absolute"),
                        "cells: the radii are multiples of the size of the "
                        "cell holding the tip; absolute: lengths.");
      prm.declare_entry(
        "Crown weight",
        "linear",
        Patterns::Selection("linear|smooth"),
        "The virtual extension's q across the crown: linear in r, "
        "interpolated from the cells' vertices (the usual G-theta "
        "domain), or a smooth step of r (zero slope at both radii) "
        "evaluated at every quadrature point, whose K varies less from "
        "mesh to mesh where the crown's cells are graded (adaptive "
        "refinement); doc/verification.md.");
      prm.declare_entry("Reference K",
                        "",
                        Patterns::Anything(),
                        "Exact or handbook K at the front, 'K_I; K_II' (2D) "
                        "or 'K_I; K_II; K_III' (3D) as expressions of x, y[, "
                        "z] of the front point; the run prints the error "
                        "against them. Empty: none.");
      prm.declare_entry("Smoothing",
                        "legendre",
                        Patterns::Selection(
                          "legendre|lagrange|lagrange regularized"),
                        "3D: functions of s on which K(s), G(s) and the "
                        "virtual extensions are built: Legendre polynomials "
                        "(their periodic analogue, a Fourier series, on a "
                        "closed front), hats on the front segments, or "
                        "hats spanning four segments with K at a node the "
                        "weighted average over them.");
      prm.declare_entry("Legendre degree",
                        "5",
                        Patterns::Integer(0, 7),
                        "3D, Smoothing = legendre: highest degree.");
      prm.declare_entry("Front segments",
                        "0",
                        Patterns::Integer(0, 10000),
                        "3D: number of equal segments of a front (nodes of "
                        "the Lagrange bases, points where K is reported); "
                        "0: segments about r_sup long.");
    }
    prm.leave_subsection();
  }



  void
  FractureParameters::parse_parameters(ParameterHandler        &prm,
                                       const FunctionConstants &constants)
  {
    const std::string section = "Fracture parameters/";
    prm.enter_subsection("Fracture parameters");
    compute                              = prm.get_bool("Compute");
    error_estimate                       = prm.get_bool("Error estimate");
    const std::string         radii_text = prm.get("Crown radii");
    const std::vector<double> radii =
      parse_numbers(radii_text, 2, section + "Crown radii");
    crown_in_cells              = (prm.get("Crown unit") == "cells");
    smooth_weight               = (prm.get("Crown weight") == "smooth");
    const std::string reference = prm.get("Reference K");
    smoothing                   = FrontBasis::parse_type(prm.get("Smoothing"));
    legendre_degree             = prm.get_integer("Legendre degree");
    front_segments              = prm.get_integer("Front segments");
    prm.leave_subsection();

    crown_inner = radii[0];
    crown_outer = radii[1];
    check_input(crown_inner > 0 && crown_outer > crown_inner,
                section + "Crown radii = " + radii_text +
                  ": need 0 < r_inf < r_sup.");
    reference_2d.reset();
    reference_3d.reset();
    if (!Utilities::trim(reference).empty())
      {
        // The same text serves both dimensions: parse it for the one whose
        // component count matches.
        const unsigned int n = split_and_trim(reference, ';').size();
        check_input(n == 2 || n == 3,
                    section + "Reference K = " + reference +
                      ": give 'K_I; K_II' (2D) or 'K_I; K_II; K_III' (3D).");
        if (n == 2)
          reference_2d = std::make_shared<ParsedVectorFunction<2>>(
            reference, 2, constants, section + "Reference K");
        else
          reference_3d = std::make_shared<ParsedVectorFunction<3>>(
            reference, 3, constants, section + "Reference K");
      }
  }



  template <int dim>
  InteractionIntegral<dim>::InteractionIntegral(
    const FractureParameters &parameters,
    const Material           &material)
    : parameters(parameters)
    , material(material)
  {}



  template <int dim>
  std::vector<FrontValues<dim>>
  InteractionIntegral<dim>::compute(
    const DoFHandler<dim>                           &dof_handler,
    const TrilinosWrappers::MPI::Vector             &solution,
    const std::vector<std::vector<FrontPoint<dim>>> &fronts,
    const FEValuesOf                                &fe_values_of,
    const Function<dim>                             *lip_pressure,
    const LipsOf                                    &lips_of,
    const Function<dim>                             *body_force,
    KDerivatives                                    *derivatives,
    const LipTraction                               &lip_traction) const
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const double   nu   = material.poisson_ratio;
    const double   e_star =
      (dim == 2 && material.plane_model == Material::PlaneModel::plane_stress ?
         material.youngs_modulus :
         material.youngs_modulus / (1 - nu * nu));
    // Auxiliary fields: unit K_I, K_II (, K_III).
    constexpr unsigned int n_modes = (dim == 3 ? 3 : 2);
    // Integrals per test function: I for each mode, then G.
    constexpr unsigned int n_integrals = n_modes + 1;
    WilliamsField          unit;
    unit.mu    = material.mu();
    unit.kappa = material.kappa(dim);
    const FEValuesExtractors::Vector displacement(0);
    const MappingQ1<dim>             mapping;
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;

    // Only the linear weight is interpolated from the vertices.
    std::optional<HangingVertices<dim>> hanging;
    if (!parameters.smooth_weight)
      hanging.emplace(dof_handler.get_triangulation());
    // The distance of x from the front, in the normal plane of its foot.
    const auto distance_to_foot =
      [](const typename FrontCurve<dim>::Projection &projection,
         const Point<dim>                           &x) {
        const Tensor<1, dim> xl = projection.R * (x - projection.foot);
        return std::hypot(xl[0], xl[1]);
      };

    std::vector<FrontValues<dim>> result;
    for (unsigned int f = 0; f < fronts.size(); ++f)
      {
        const unsigned int n_segments = fronts[f].size() - 1;
        // Distance to the front (before the crown radii are known).
        const FrontCurve<dim> polyline(fronts[f], 0);
        const auto            distance = [&](const Point<dim> &x) {
          double d = std::numeric_limits<double>::max();
          if (n_segments == 0)
            return x.distance(fronts[f][0].position);
          for (unsigned int i = 0; i < n_segments; ++i)
            d = std::min(d, polyline.segment_distance(i, x));
          return d;
        };

        // The crown radii, in cells of the size of those the front crosses.
        double h = std::numeric_limits<double>::max();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (dim == 2 ? cell->point_inside(fronts[f][0].position) :
                          distance(cell->center()) < 0.5 * cell->diameter()))
            h = std::min(h, cell->diameter() / std::sqrt(double(dim)));
        h                   = Utilities::MPI::min(h, comm);
        const double scale  = (parameters.crown_in_cells ? h : 1.);
        const double r_inf  = parameters.crown_inner * scale;
        const double r_sup  = parameters.crown_outer * scale;
        const bool   smooth = parameters.smooth_weight;
        // q(r): linear from r_inf to r_sup, or a smooth step (dq_dr).
        const auto q_of_r = [&](const double r) {
          const double t = std::clamp((r_sup - r) / (r_sup - r_inf), 0., 1.);
          return smooth ? t * t * (3 - 2 * t) : t;
        };
        const auto dq_dr = [&](const double r) {
          const double t = std::clamp((r_sup - r) / (r_sup - r_inf), 0., 1.);
          return 6 * t * (1 - t) / (r_inf - r_sup);
        };
        const FrontCurve<dim> curve(fronts[f], 0.5 * r_sup);

        // A test function must not vary along the front on a scale shorter
        // than the crown, or theta_j is not resolved by the crown cells:
        // the degree is capped at L / (2 r_sup) (said on screen).
        const unsigned int degree =
          std::min<unsigned int>(parameters.legendre_degree,
                                 static_cast<unsigned int>(curve.length /
                                                           (2 * r_sup)));
        const FrontBasis basis =
          (dim == 2 ? FrontBasis() :
                      FrontBasis(parameters.smoothing,
                                 degree,
                                 curve.length,
                                 curve.closed,
                                 f < parameters.node_segments.size() ?
                                   parameters.node_segments[f] :
                                 parameters.front_segments > 0 ?
                                   parameters.front_segments :
                                   static_cast<unsigned int>(
                                     std::round(curve.length / r_sup))));
        const unsigned int  n_test = basis.n_test_functions();
        std::vector<double> local(n_test * n_integrals, 0.);
        // With derivatives: d b_jm / dU per test function j and mode m.
        std::optional<IntegralDerivatives<dim>> d_b;
        if (derivatives)
          d_b.emplace(dof_handler.locally_owned_dofs(), comm, n_test, n_modes);

        // Other fronts or tips inside the crown.
        bool clear = true;
        // Whether the crown holds a vertex of the mesh at all (with crowns
        // smaller than the cells, q vanishes at every vertex, and so do K
        // and G).
        bool sees_crown = false;
        for (unsigned int g = 0; g < fronts.size(); ++g)
          if (g != f)
            for (const auto &other : fronts[g])
              if (distance(other.position) < r_sup)
                clear = false;

        // Bounding box of the front grown by r_sup: cells beyond it carry
        // no theta.
        Point<dim> box_low = fronts[f][0].position, box_high = box_low;
        for (const auto &p : fronts[f])
          for (unsigned int d = 0; d < dim; ++d)
            {
              box_low[d]  = std::min(box_low[d], p.position[d] - r_sup);
              box_high[d] = std::max(box_high[d], p.position[d] + r_sup);
            }

        std::vector<Tensor<2, dim>> grad_u;
        Vector<double>              f_value(dim);
        // Per vertex: q e1 (made tangent to the boundary; e1 alone with a
        // smooth weight, whose q is evaluated at the points), psi_j(s).
        std::array<Tensor<1, dim>, n_vertices>      w_vertex;
        std::array<std::vector<double>, n_vertices> psi_vertex;
        std::vector<unsigned int>                   active_tests;
        std::vector<Tensor<2, dim>>                 grad_theta(n_test);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            {
              const Point<dim> c      = cell->center();
              const double     margin = cell->diameter();
              bool             inside = true;
              for (unsigned int d = 0; d < dim; ++d)
                inside = inside && c[d] > box_low[d] - margin &&
                         c[d] < box_high[d] + margin;
              if (!inside)
                continue;
            }
            // The segments that can be nearest to a point of the cell.
            unsigned int first = 0, last = std::max(n_segments, 1u);
            if (n_segments > 1)
              {
                const auto near =
                  curve.near_segments(cell->center(), cell->diameter());
                if (near.distance > r_sup + cell->diameter())
                  continue;
                first = near.first;
                last  = near.last;
              }

            // The boundary faces of the cell that hold its vertex v.
            const auto boundary_faces_at = [&](const unsigned int v) {
              std::vector<unsigned int> faces;
              for (const unsigned int face : cell->face_indices())
                if (cell->face(face)->at_boundary())
                  for (const unsigned int fv :
                       cell->face(face)->vertex_indices())
                    if (cell->face(face)->vertex_index(fv) ==
                        cell->vertex_index(v))
                      faces.push_back(face);
              return faces;
            };
            double q_min = 1, q_max = 0;
            for (const unsigned int v : cell->vertex_indices())
              {
                const auto projection =
                  curve.project(cell->vertex(v), first, last);
                const double r = distance_to_foot(projection, cell->vertex(v));
                // At a hanging vertex, the linear q is its masters'
                // interpolation (any segment of the front may be nearest to
                // them): q stays continuous across the faces of coarser
                // neighbours. (A smooth q is evaluated at the points.)
                std::vector<std::pair<Point<dim>, double>> masters;
                if (hanging)
                  masters = hanging->masters(cell, v);
                double q = (masters.empty() ? q_of_r(r) : 0.);
                for (const auto &[x, c] : masters)
                  q += c * q_of_r(distance_to_foot(
                             curve.project(x, 0, std::max(n_segments, 1u)), x));
                // A smooth weight is read at the points: the cell's range
                // of it, from the vertices' distances widened by the cell.
                q_min =
                  std::min(q_min, smooth ? q_of_r(r + cell->diameter()) : q);
                q_max =
                  std::max(q_max, smooth ? q_of_r(r - cell->diameter()) : q);
                Tensor<1, dim> e1;
                for (unsigned int d = 0; d < dim; ++d)
                  e1[d] = projection.R[0][d];
                w_vertex[v] = (smooth ? 1. : q) * e1;
                psi_vertex[v].resize(n_test);
                for (unsigned int j = 0; j < n_test; ++j)
                  psi_vertex[v][j] = basis.test_function(j, projection.s);
                // The domain form holds if theta . n = 0 on the boundary
                // (or the boundary is traction free and theta tangent to
                // it, the end of an open 3D front on a free surface).
                if (q > 0 && !projection.at_end &&
                    !boundary_faces_at(v).empty())
                  clear = false;
              }
            if (q_max == 0)
              continue;
            sees_crown = true;
            // Free surfaces: theta tangent to the boundary faces of the
            // cell at their vertices (Gram-Schmidt over their normals).
            if constexpr (dim == 3)
              for (const unsigned int v : cell->vertex_indices())
                {
                  std::vector<Tensor<1, dim>> normals;
                  for (const unsigned int face : boundary_faces_at(v))
                    {
                      Tensor<1, dim> n =
                        cross_product_3d(cell->face(face)->vertex(1) -
                                           cell->face(face)->vertex(0),
                                         cell->face(face)->vertex(2) -
                                           cell->face(face)->vertex(0));
                      for (const auto &m : normals)
                        n -= (n * m) * m;
                      if (n.norm() >
                          1e-12 * cell->diameter() * cell->diameter())
                        normals.push_back(n / n.norm());
                    }
                  for (const auto &n : normals)
                    w_vertex[v] -= (w_vertex[v] * n) * n;
                }
            active_tests.clear();
            for (unsigned int j = 0; j < n_test; ++j)
              for (const unsigned int v : cell->vertex_indices())
                if (psi_vertex[v][j] != 0 && w_vertex[v].norm() > 0)
                  {
                    active_tests.push_back(j);
                    break;
                  }
            if (derivatives)
              d_b->reinit(cell, active_tests);
            // The interpolant of the vertices' psi_j w at reference point
            // xi, and theta_j there, at distance r from the front.
            const auto interpolant = [&](const Point<dim>  &xi,
                                         const unsigned int j) {
              Tensor<1, dim> value;
              for (unsigned int v = 0; v < n_vertices; ++v)
                value += (psi_vertex[v][j] *
                          GeometryInfo<dim>::d_linear_shape_function(xi, v)) *
                         w_vertex[v];
              return value;
            };
            const auto theta_at =
              [&](const Point<dim> &xi, const double r, const unsigned int j) {
                return (smooth ? q_of_r(r) : 1.) * interpolant(xi, j);
              };

            // Domain terms: where theta varies (2D: where q does), and
            // wherever theta is not zero under a body force.
            if (dim == 3 || q_max > q_min || (body_force != nullptr))
              {
                const FEValues<dim> &fe_values = fe_values_of(cell);
                grad_u.resize(fe_values.n_quadrature_points);
                fe_values[displacement].get_function_gradients(solution,
                                                               grad_u);
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  {
                    const Point<dim> &xi = fe_values.get_quadrature().point(q);
                    // grad_x theta_j = sum_v psi_j(v) w_v (x) (d xi/d x)^T
                    // grad_xi N_v.
                    const DerivativeForm<1, dim, dim> &inverse =
                      fe_values.inverse_jacobian(q);
                    std::array<Tensor<1, dim>, n_vertices> grad_N;
                    for (unsigned int v = 0; v < n_vertices; ++v)
                      {
                        const Tensor<1, dim> g =
                          GeometryInfo<dim>::d_linear_shape_function_gradient(
                            xi, v);
                        grad_N[v] = Tensor<1, dim>();
                        for (unsigned int j = 0; j < dim; ++j)
                          for (unsigned int k = 0; k < dim; ++k)
                            grad_N[v][j] += g[k] * inverse[k][j];
                      }
                    const Point<dim> &x   = fe_values.quadrature_point(q);
                    const auto projection = curve.project(x, first, last);
                    const Tensor<1, dim> xl =
                      projection.R * (x - projection.foot);
                    const double r     = std::hypot(xl[0], xl[1]);
                    const double angle = std::atan2(xl[1], xl[0]);
                    const double JxW   = fe_values.JxW(q);

                    // With a smooth weight theta_j = q(r) I_h(psi_j e1):
                    // q'(r) I_h(psi_j e1) (x) grad r + q(r) grad I_h(...),
                    // grad r the unit vector from the foot in the normal
                    // plane.
                    Tensor<1, dim> grad_r;
                    if (smooth && r > 0)
                      for (unsigned int d = 0; d < dim; ++d)
                        grad_r[d] = (projection.R[0][d] * xl[0] +
                                     projection.R[1][d] * xl[1]) /
                                    r;
                    for (const unsigned int j : active_tests)
                      {
                        grad_theta[j] = Tensor<2, dim>();
                        for (unsigned int v = 0; v < n_vertices; ++v)
                          grad_theta[j] +=
                            outer_product(psi_vertex[v][j] * w_vertex[v],
                                          grad_N[v]);
                        if (smooth)
                          grad_theta[j] =
                            q_of_r(r) * grad_theta[j] +
                            dq_dr(r) *
                              outer_product(interpolant(xi, j), grad_r);
                      }

                    const Tensor<2, dim>         &du  = grad_u[q];
                    const SymmetricTensor<2, dim> eps = symmetrize(du);
                    const SymmetricTensor<2, dim> sigma =
                      material.stress<dim>(eps);

                    // T_kj with I = int T_kj theta_k,j.
                    Tensor<2, dim> T[n_integrals];
                    Tensor<2, dim> du_aux[n_modes];
                    aux_gradients<dim, n_modes>(
                      unit, projection, xl, r, angle, du_aux);
                    for (unsigned int m = 0; m < n_modes; ++m)
                      {
                        const SymmetricTensor<2, dim> eps_aux =
                          symmetrize(du_aux[m]);
                        const SymmetricTensor<2, dim> sigma_aux =
                          material.stress<dim>(eps_aux);
                        T[m] = transpose(du_aux[m]) * Tensor<2, dim>(sigma) +
                               transpose(du) * Tensor<2, dim>(sigma_aux);
                        const double w = sigma * eps_aux;
                        for (unsigned int k = 0; k < dim; ++k)
                          T[m][k][k] -= w;
                      }
                    T[n_modes] = transpose(du) * Tensor<2, dim>(sigma);
                    for (unsigned int k = 0; k < dim; ++k)
                      T[n_modes][k][k] -= 0.5 * (sigma * eps);
                    for (const unsigned int j : active_tests)
                      for (unsigned int m = 0; m < n_integrals; ++m)
                        local[j * n_integrals + m] +=
                          scalar_product(T[m], grad_theta[j]) * JxW;
                    // T[m] : Theta for du = G is G : A with A = C :
                    // sym(du_aux Theta) + sigma_aux Theta^T - tr(Theta)
                    // sigma_aux.
                    if (derivatives)
                      for (unsigned int m = 0; m < n_modes; ++m)
                        {
                          const Tensor<2, dim> sigma_aux(
                            material.stress<dim>(symmetrize(du_aux[m])));
                          for (const unsigned int j : active_tests)
                            {
                              const Tensor<2, dim> &Theta = grad_theta[j];
                              const Tensor<2, dim>  A =
                                Tensor<2, dim>(material.stress<dim>(
                                  symmetrize(du_aux[m] * Theta))) +
                                sigma_aux * transpose(Theta) -
                                trace(Theta) * sigma_aux;
                              d_b->add(j, m, A * JxW);
                            }
                        }

                    // Body force: - int f_i u_i,k theta_k (u^aux for I).
                    if (body_force != nullptr)
                      {
                        body_force->vector_value(x, f_value);
                        Tensor<1, dim> f;
                        for (unsigned int d = 0; d < dim; ++d)
                          f[d] = f_value[d];
                        for (const unsigned int j : active_tests)
                          {
                            const Tensor<1, dim> theta = theta_at(xi, r, j);
                            for (unsigned int m = 0; m < n_modes; ++m)
                              local[j * n_integrals + m] -=
                                (f * (du_aux[m] * theta)) * JxW;
                            local[j * n_integrals + n_modes] -=
                              (f * (du * theta)) * JxW;
                          }
                      }

                    // Along a curved 3D front the auxiliary stress is not
                    // in equilibrium: + int div(sigma^aux)_i u_i,k theta_k.
                    if constexpr (dim == 3)
                      {
                        Tensor<1, dim> div_aux[n_modes];
                        aux_stress_divergence<n_modes>(
                          unit, curve, x, projection, xl, angle, div_aux);
                        for (const unsigned int j : active_tests)
                          {
                            const Tensor<1, dim> theta    = theta_at(xi, r, j);
                            const Tensor<1, dim> du_theta = du * theta;
                            for (unsigned int m = 0; m < n_modes; ++m)
                              {
                                local[j * n_integrals + m] +=
                                  (div_aux[m] * du_theta) * JxW;
                                if (derivatives)
                                  d_b->add(j,
                                           m,
                                           outer_product(div_aux[m], theta) *
                                             JxW);
                              }
                          }
                      }
                    if (derivatives)
                      d_b->flush_point(fe_values, q);
                  }
              }

            // The cell's derivatives so far into the global ones.
            if (derivatives)
              d_b->flush_cell(*derivatives->constraints);

            // Lip terms. With a traction t on the lsn > 0 lip and -t on the
            // other (a pressure: t = p n; contact): - int t_i [u_i,k]
            // theta_k. Along a curved 3D
            // front the auxiliary fields load the lips too: their hoop
            // strain u_1 / rho is not zero on the lips in mode II, so
            // sigma^aux . n is not, and + int (sigma^aux n . u_,k theta_k)
            // [+ lip] - (the same) [- lip] completes the identity (it
            // vanishes for straight fronts and in mode I).
            if (lip_pressure == nullptr && !lip_traction && dim == 2)
              continue;
            std::vector<Point<dim>>     points;
            std::vector<double>         weights;
            std::vector<Tensor<1, dim>> normals;
            lips_of(cell, points, weights, normals);
            if (points.empty())
              continue;
            const std::vector<Point<dim>> sides =
              CellQuadrature::both_sides(points, normals);
            FEValues<dim> side_values(mapping,
                                      cell->get_fe(),
                                      Quadrature<dim>(sides),
                                      update_gradients | update_jacobians |
                                        update_quadrature_points);
            side_values.reinit(cell);
            grad_u.resize(sides.size());
            side_values[displacement].get_function_gradients(solution, grad_u);
            for (unsigned int k = 0; k < points.size(); ++k)
              {
                // n ds, to the lsn > 0 lip.
                const Tensor<1, dim> n_ds = CellQuadrature::mapped_normal<dim>(
                  side_values.jacobian(2 * k), normals[k], weights[k]);
                const Point<dim> x_global = side_values.quadrature_point(2 * k);
                // t ds on the lsn > 0 lip.
                Tensor<1, dim> t_ds =
                  (lip_pressure ? lip_pressure->value(x_global) : 0.) * n_ds;
                if (lip_traction)
                  t_ds += n_ds.norm() * lip_traction(cell, k);
                const auto projection    = curve.project(x_global, first, last);
                const Tensor<2, dim> &R  = projection.R;
                const Tensor<1, dim>  xl = R * (x_global - projection.foot);
                const double          r  = std::hypot(xl[0], xl[1]);
                // The lsn > 0 lip lies at angle pi in the front frame if e2
                // points to it, else at -pi (the start tip of a segment).
                const double angle_plus =
                  ((R * n_ds)[1] > 0 ? 1. : -1.) * numbers::PI;
                Tensor<2, dim> plus[n_modes], minus[n_modes];
                aux_gradients<dim, n_modes>(
                  unit, projection, xl, r, angle_plus, plus);
                aux_gradients<dim, n_modes>(
                  unit, projection, xl, r, -angle_plus, minus);
                Tensor<2, dim> jump[n_integrals];
                for (unsigned int m = 0; m < n_modes; ++m)
                  jump[m] = plus[m] - minus[m];
                jump[n_modes] = grad_u[2 * k] - grad_u[2 * k + 1];
                for (const unsigned int j : active_tests)
                  {
                    const Tensor<1, dim> theta = theta_at(points[k], r, j);
                    for (unsigned int m = 0; m < n_integrals; ++m)
                      local[j * n_integrals + m] -= t_ds * (jump[m] * theta);
                  }
                if constexpr (dim == 3)
                  {
                    Tensor<1, dim> t_plus[n_modes], t_minus[n_modes];
                    for (unsigned int m = 0; m < n_modes; ++m)
                      {
                        t_plus[m] =
                          material.stress<dim>(symmetrize(plus[m])) * n_ds;
                        t_minus[m] =
                          material.stress<dim>(symmetrize(minus[m])) * n_ds;
                      }
                    for (const unsigned int j : active_tests)
                      {
                        const Tensor<1, dim> theta = theta_at(points[k], r, j);
                        for (unsigned int m = 0; m < n_modes; ++m)
                          local[j * n_integrals + m] +=
                            t_plus[m] * (grad_u[2 * k] * theta) -
                            t_minus[m] * (grad_u[2 * k + 1] * theta);
                      }
                    // The derivatives, one side after the other.
                    if (derivatives)
                      for (const unsigned int side : {0u, 1u})
                        {
                          for (const unsigned int j : active_tests)
                            {
                              const Tensor<1, dim> theta =
                                theta_at(points[k], r, j);
                              for (unsigned int m = 0; m < n_modes; ++m)
                                d_b->add(j,
                                         m,
                                         side == 0 ?
                                           outer_product(t_plus[m], theta) :
                                           -outer_product(t_minus[m], theta));
                            }
                          d_b->flush_point(side_values, 2 * k + side);
                        }
                  }
              }
            if (derivatives)
              d_b->flush_cell(*derivatives->constraints);
          }

        std::vector<double> b_all(local.size());
        Utilities::MPI::sum(ArrayView<const double>(local),
                            comm,
                            ArrayView<double>(b_all));
        clear = !Utilities::MPI::logical_or(!clear, comm);
        if (!Utilities::MPI::logical_or(sees_crown, comm))
          {
            std::ostringstream message;
            message << "Fracture parameters/Crown radii: the crown of "
                    << (dim == 2 ? "tip " : "front ") << f + 1 << " at ("
                    << fronts[f][0].position << ") (r_sup = " << r_sup
                    << ") holds no vertex of the mesh, so K and G would be 0 "
                       "there; use radii of at least a cell there, or Crown "
                       "unit = cells.";
            throw InputError(message.str());
          }
        std::vector<std::vector<double>> nodal(n_integrals);
        for (unsigned int m = 0; m < n_integrals; ++m)
          {
            std::vector<double> b(n_test);
            for (unsigned int j = 0; j < n_test; ++j)
              b[j] = b_all[j * n_integrals + m];
            nodal[m] = basis.values_at_nodes(b);
          }
        // dK: per test function, scaled as the K's, and the weights that
        // take them to the nodes (the map the b_j take above).
        if (derivatives)
          {
            std::vector<std::vector<double>> to_nodes(n_test);
            for (unsigned int j = 0; j < n_test; ++j)
              {
                std::vector<double> unit_b(n_test, 0.);
                unit_b[j]   = 1;
                to_nodes[j] = basis.values_at_nodes(unit_b);
              }
            const unsigned int first_test = derivatives->test_loads.size();
            for (unsigned int j = 0; j < n_test; ++j)
              {
                std::vector<TrilinosWrappers::MPI::Vector> loads;
                for (unsigned int m = 0; m < n_modes; ++m)
                  loads.push_back(
                    d_b->scaled(j, m, m < 2 ? 0.5 * e_star : material.mu()));
                derivatives->test_loads.push_back(std::move(loads));
              }
            for (unsigned int k = 0; k < basis.nodes().size(); ++k)
              {
                std::vector<std::pair<unsigned int, double>> weights;
                for (unsigned int j = 0; j < n_test; ++j)
                  if (to_nodes[j][k] != 0)
                    weights.emplace_back(first_test + j, to_nodes[j][k]);
                derivatives->node_weights.push_back(std::move(weights));
              }
          }
        for (unsigned int k = 0; k < basis.nodes().size(); ++k)
          {
            FrontValues<dim> values;
            values.front = f;
            values.basis = basis.description();
            values.point = curve.at(basis.nodes()[k]);
            values.k_I   = 0.5 * e_star * nodal[0][k];
            values.k_II  = 0.5 * e_star * nodal[1][k];
            if (dim == 3)
              values.k_III = material.mu() * nodal[n_modes - 1][k];
            values.g = nodal[n_modes][k];
            values.g_irwin =
              (values.k_I * values.k_I + values.k_II * values.k_II) / e_star +
              values.k_III * values.k_III / (2 * material.mu());
            values.r_inf       = r_inf;
            values.r_sup       = r_sup;
            values.crown_clear = clear;
            result.push_back(values);
          }
      }
    return result;
  }



  template class InteractionIntegral<2>;
  template class InteractionIntegral<3>;
} // namespace xcrack
