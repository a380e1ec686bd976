#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/input_error.h>
#include <xcrack/xfem/cell_quadrature.h>

#include <cmath>
#include <limits>

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
                        "tips after each solve (2D; 3D fronts are not "
                        "implemented yet) and write front_<cycle>.csv.");
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
      prm.declare_entry("Reference K",
                        "",
                        Patterns::Anything(),
                        "Exact or handbook K at the front, 'K_I; K_II' (2D) "
                        "or 'K_I; K_II; K_III' (3D) as expressions of x, y[, "
                        "z] of the front point; the run prints the error "
                        "against them. Empty: none.");
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
    const std::string         radii_text = prm.get("Crown radii");
    const std::vector<double> radii =
      parse_numbers(radii_text, 2, section + "Crown radii");
    crown_in_cells              = (prm.get("Crown unit") == "cells");
    const std::string reference = prm.get("Reference K");
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
    const DoFHandler<dim>               &dof_handler,
    const TrilinosWrappers::MPI::Vector &solution,
    const std::vector<FrontPoint<dim>>  &tips,
    const FEValuesOf                    &fe_values_of,
    const Function<dim>                 *lip_pressure,
    const LipsOf                        &lips_of) const
  {
    static_assert(dim == 2, "The interaction integral is 2D for now.");
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const double   nu   = material.poisson_ratio;
    const double   e_star =
      (material.plane_model == Material::PlaneModel::plane_stress ?
         material.youngs_modulus :
         material.youngs_modulus / (1 - nu * nu));
    WilliamsField aux[2];
    for (auto &field : aux)
      {
        field.mu    = material.mu();
        field.kappa = material.kappa(dim);
      }
    aux[0].k_I  = 1;
    aux[1].k_II = 1;
    const FEValuesExtractors::Vector displacement(0);
    const MappingQ1<dim>             mapping;
    const FE_Q<dim>                  q1(1);

    std::vector<FrontValues<dim>> result;
    for (const FrontPoint<dim> &tip : tips)
      {
        // The crown radii, in cells of the size of the one holding the tip.
        double h = std::numeric_limits<double>::max();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->point_inside(tip.position))
            h = std::min(h, cell->diameter() / std::sqrt(double(dim)));
        h                   = Utilities::MPI::min(h, comm);
        const double scale  = (parameters.crown_in_cells ? h : 1.);
        const double r_inf  = parameters.crown_inner * scale;
        const double r_sup  = parameters.crown_outer * scale;
        const auto   q_of_r = [&](const double r) {
          return std::clamp((r_sup - r) / (r_sup - r_inf), 0., 1.);
        };
        // Rows e1, e2: global to tip-frame components.
        Tensor<2, dim> R;
        for (unsigned int d = 0; d < dim; ++d)
          {
            R[0][d] = tip.e1[d];
            R[1][d] = tip.e2[d];
          }

        // [I for K_I^aux = 1, I for K_II^aux = 1, J]
        double local[3] = {0, 0, 0};
        bool   clear    = true;
        for (const FrontPoint<dim> &other : tips)
          if (&other != &tip && other.position.distance(tip.position) < r_sup)
            clear = false;
        std::vector<Tensor<2, dim>> grad_u;
        std::vector<double> q_vertex(GeometryInfo<dim>::vertices_per_cell);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            double q_min = 1, q_max = 0;
            for (const unsigned int v : cell->vertex_indices())
              {
                q_vertex[v] = q_of_r(cell->vertex(v).distance(tip.position));
                q_min       = std::min(q_min, q_vertex[v]);
                q_max       = std::max(q_max, q_vertex[v]);
              }
            if (q_max > 0)
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary())
                  for (const unsigned int v : cell->face(f)->vertex_indices())
                    if (cell->face(f)->vertex(v).distance(tip.position) < r_sup)
                      clear = false;
            const auto q_at = [&](const Point<dim> &xi) {
              double value = 0;
              for (unsigned int v = 0; v < q_vertex.size(); ++v)
                value += q_vertex[v] *
                         GeometryInfo<dim>::d_linear_shape_function(xi, v);
              return value;
            };

            // Domain terms: only where q varies.
            if (q_max > q_min)
              {
                const FEValues<dim> &fe_values = fe_values_of(cell);
                grad_u.resize(fe_values.n_quadrature_points);
                fe_values[displacement].get_function_gradients(solution,
                                                               grad_u);
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  {
                    const Point<dim> &xi = fe_values.get_quadrature().point(q);
                    Tensor<1, dim>    grad_q_ref;
                    for (unsigned int v = 0; v < q_vertex.size(); ++v)
                      grad_q_ref +=
                        q_vertex[v] *
                        GeometryInfo<dim>::d_linear_shape_function_gradient(xi,
                                                                            v);
                    // grad_x q = (d xi / d x)^T grad_xi q, in the tip frame.
                    const DerivativeForm<1, dim, dim> &inverse =
                      fe_values.inverse_jacobian(q);
                    Tensor<1, dim> grad_q;
                    for (unsigned int j = 0; j < dim; ++j)
                      for (unsigned int k = 0; k < dim; ++k)
                        grad_q[j] += grad_q_ref[k] * inverse[k][j];
                    const Tensor<1, dim> dq = R * grad_q;

                    const Tensor<2, dim> du = R * grad_u[q] * transpose(R);
                    const SymmetricTensor<2, dim> eps = symmetrize(du);
                    const SymmetricTensor<2, dim> sigma =
                      material.stress<dim>(eps);
                    const Tensor<1, dim> x =
                      R * (fe_values.quadrature_point(q) - tip.position);
                    const double r     = x.norm();
                    const double theta = std::atan2(x[1], x[0]);
                    const double JxW   = fe_values.JxW(q);

                    for (unsigned int m = 0; m < 2; ++m)
                      {
                        const Tensor<2, 3> du3 =
                          aux[m].displacement_gradient(r, theta);
                        const SymmetricTensor<2, 3> s3 =
                          aux[m].stress(r, theta);
                        Tensor<2, dim>          du_aux;
                        SymmetricTensor<2, dim> sigma_aux, eps_aux;
                        for (unsigned int i = 0; i < dim; ++i)
                          for (unsigned int j = 0; j < dim; ++j)
                            du_aux[i][j] = du3[i][j];
                        for (unsigned int i = 0; i < dim; ++i)
                          for (unsigned int j = i; j < dim; ++j)
                            sigma_aux[i][j] = s3[i][j];
                        eps_aux          = symmetrize(du_aux);
                        double integrand = -(sigma * eps_aux) * dq[0];
                        for (unsigned int i = 0; i < dim; ++i)
                          for (unsigned int j = 0; j < dim; ++j)
                            integrand += (sigma[i][j] * du_aux[i][0] +
                                          sigma_aux[i][j] * du[i][0]) *
                                         dq[j];
                        local[m] += integrand * JxW;
                      }
                    double integrand = -0.5 * (sigma * eps) * dq[0];
                    for (unsigned int i = 0; i < dim; ++i)
                      for (unsigned int j = 0; j < dim; ++j)
                        integrand += sigma[i][j] * du[i][0] * dq[j];
                    local[2] += integrand * JxW;
                  }
              }

            // Lip term: - int q t_i [d u_i / d x_1] over both lips, t = p n
            // on the lsn > 0 lip and -p n on the other.
            if (lip_pressure == nullptr || q_max == 0)
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
                // n ds, to the lsn > 0 lip, in the tip frame.
                const Tensor<1, dim> n_ds =
                  R * CellQuadrature::mapped_normal<dim>(
                        side_values.jacobian(2 * k), normals[k], weights[k]);
                const Point<dim> x_global = side_values.quadrature_point(2 * k);
                const double     p        = lip_pressure->value(x_global);
                const double     q        = q_at(points[k]);
                const double     r = (R * (x_global - tip.position)).norm();
                // The lsn > 0 lip lies at theta = pi in the tip frame if e2
                // points to it, else at -pi (the start tip of a segment).
                const double theta_plus =
                  (n_ds[1] > 0 ? 1. : -1.) * numbers::PI;
                for (unsigned int m = 0; m < 2; ++m)
                  {
                    const Tensor<2, 3> plus =
                      aux[m].displacement_gradient(r, theta_plus);
                    const Tensor<2, 3> minus =
                      aux[m].displacement_gradient(r, -theta_plus);
                    double jump = 0;
                    for (unsigned int i = 0; i < dim; ++i)
                      jump += n_ds[i] * (plus[i][0] - minus[i][0]);
                    local[m] -= q * p * jump;
                  }
                const Tensor<2, dim> plus = R * grad_u[2 * k] * transpose(R);
                const Tensor<2, dim> minus =
                  R * grad_u[2 * k + 1] * transpose(R);
                double jump = 0;
                for (unsigned int i = 0; i < dim; ++i)
                  jump += n_ds[i] * (plus[i][0] - minus[i][0]);
                local[2] -= q * p * jump;
              }
          }

        double global[3];
        Utilities::MPI::sum(ArrayView<const double>(local, 3),
                            comm,
                            ArrayView<double>(global, 3));
        FrontValues<dim> values;
        values.point = tip;
        values.k_I   = 0.5 * e_star * global[0];
        values.k_II  = 0.5 * e_star * global[1];
        values.g     = global[2];
        values.g_irwin =
          (values.k_I * values.k_I + values.k_II * values.k_II) / e_star;
        values.r_inf       = r_inf;
        values.r_sup       = r_sup;
        values.crown_clear = !Utilities::MPI::logical_or(!clear, comm);
        result.push_back(values);
      }
    return result;
  }



  template class InteractionIntegral<2>;
} // namespace xcrack
