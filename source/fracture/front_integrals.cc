#include <deal.II/base/geometry_info.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/front_integrals.h>
#include <xcrack/xfem/cell_quadrature.h>

namespace xcrack
{
  template <int dim>
  void
  FrontIntegrals<dim>::add_domain_terms(const FEValues<dim>  &fe_values,
                                        const CellTheta<dim> &cell_theta,
                                        const unsigned int    first,
                                        const unsigned int    last,
                                        const Function<dim>  *body_force)
  {
    const std::vector<unsigned int> &active = cell_theta.active_tests();
    grad_u.resize(fe_values.n_quadrature_points);
    fe_values[displacement].get_function_gradients(solution, grad_u);
    Vector<double> f_value(dim);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        CrownPoint<dim> p(crown,
                          fe_values.get_quadrature().point(q),
                          fe_values.quadrature_point(q),
                          first,
                          last);
        // Within Crown::core of the polyline the rule's weights do not
        // match the auxiliary fields' singularity.
        if (p.r < crown.core())
          continue;
        p.du             = grad_u[q];
        const double JxW = fe_values.JxW(q);
        const auto   grad_N =
          CellTheta<dim>::shape_gradients(p.xi, fe_values.inverse_jacobian(q));
        // theta itself only where a term reads it.
        const bool values = (dim == 3 || body_force != nullptr);
        for (const unsigned int j : active)
          {
            grad_theta[j] =
              cell_theta.gradient(p.xi, grad_N, p.projection, p.xl, p.r, j);
            if (values)
              theta[j] = cell_theta.value(p.xi, p.r, j);
          }

        Tensor<2, dim> du_aux[n_modes];
        aux_gradients<dim, n_modes>(
          unit, p.projection, p.xl, p.r, p.angle, du_aux);
        domain_term(p, du_aux, active, JxW);
        if (body_force != nullptr)
          {
            body_force->vector_value(p.x, f_value);
            Tensor<1, dim> f;
            for (unsigned int d = 0; d < dim; ++d)
              f[d] = f_value[d];
            body_force_term(p, f, du_aux, active, JxW);
          }
        if constexpr (dim == 3)
          divergence_term(p, active, JxW);
        if (d_b)
          d_b->flush_point(fe_values, q);
      }
  }



  template <int dim>
  void
  FrontIntegrals<dim>::domain_term(const CrownPoint<dim> &p,
                                   const Tensor<2, dim> (&du_aux)[n_modes],
                                   const std::vector<unsigned int> &active,
                                   const double                     JxW)
  {
    const Tensor<2, dim>         &du    = p.du;
    const SymmetricTensor<2, dim> eps   = symmetrize(du);
    const SymmetricTensor<2, dim> sigma = material.stress<dim>(eps);
    Tensor<2, dim>                T[n_integrals];
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        const SymmetricTensor<2, dim> eps_aux   = symmetrize(du_aux[m]);
        const SymmetricTensor<2, dim> sigma_aux = material.stress<dim>(eps_aux);
        T[m] = transpose(du_aux[m]) * Tensor<2, dim>(sigma) +
               transpose(du) * Tensor<2, dim>(sigma_aux);
        const double w = sigma * eps_aux;
        for (unsigned int k = 0; k < dim; ++k)
          T[m][k][k] -= w;
      }
    T[n_modes] = transpose(du) * Tensor<2, dim>(sigma);
    for (unsigned int k = 0; k < dim; ++k)
      T[n_modes][k][k] -= 0.5 * (sigma * eps);
    for (const unsigned int j : active)
      for (unsigned int m = 0; m < n_integrals; ++m)
        b[j * n_integrals + m] += scalar_product(T[m], grad_theta[j]) * JxW;
    if (d_b)
      for (unsigned int m = 0; m < n_modes; ++m)
        {
          const Tensor<2, dim> sigma_aux(
            material.stress<dim>(symmetrize(du_aux[m])));
          for (const unsigned int j : active)
            {
              const Tensor<2, dim> &Theta = grad_theta[j];
              const Tensor<2, dim>  A =
                Tensor<2, dim>(
                  material.stress<dim>(symmetrize(du_aux[m] * Theta))) +
                sigma_aux * transpose(Theta) - trace(Theta) * sigma_aux;
              d_b->add(j, m, A * JxW);
            }
        }
  }



  template <int dim>
  void
  FrontIntegrals<dim>::body_force_term(const CrownPoint<dim> &p,
                                       const Tensor<1, dim>  &f,
                                       const Tensor<2, dim> (&du_aux)[n_modes],
                                       const std::vector<unsigned int> &active,
                                       const double                     JxW)
  {
    for (const unsigned int j : active)
      {
        for (unsigned int m = 0; m < n_modes; ++m)
          b[j * n_integrals + m] -= (f * (du_aux[m] * theta[j])) * JxW;
        b[j * n_integrals + n_modes] -= (f * (p.du * theta[j])) * JxW;
      }
  }



  template <int dim>
  void
  FrontIntegrals<dim>::divergence_term(const CrownPoint<dim>           &p,
                                       const std::vector<unsigned int> &active,
                                       const double                     JxW)
  {
    if constexpr (dim == 3)
      {
        Tensor<1, dim> div_aux[n_modes];
        aux_stress_divergence<n_modes>(
          unit, crown.curve, p.x, p.projection, p.xl, p.angle, div_aux);
        for (const unsigned int j : active)
          {
            const Tensor<1, dim> du_theta = p.du * theta[j];
            for (unsigned int m = 0; m < n_modes; ++m)
              {
                b[j * n_integrals + m] += (div_aux[m] * du_theta) * JxW;
                if (d_b)
                  d_b->add(j, m, outer_product(div_aux[m], theta[j]) * JxW);
              }
          }
      }
    else
      (void)p, (void)active, (void)JxW;
  }



  template <int dim>
  void
  FrontIntegrals<dim>::add_lip_terms(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const CellTheta<dim>                                 &cell_theta,
    const unsigned int                                    first,
    const unsigned int                                    last,
    const std::vector<Point<dim>>                        &points,
    const std::vector<double>                            &weights,
    const std::vector<Tensor<1, dim>>                    &normals,
    const Function<dim>                                  *lip_pressure,
    const typename InteractionIntegral<dim>::LipTraction &lip_traction)
  {
    // With a traction t on the lsn > 0 lip and -t on the other (a
    // pressure: t = p n; contact): - int t_i [u_i,k] theta_k. Along a
    // curved 3D front the auxiliary fields load the lips too: their hoop
    // strain u_1 / rho is not zero on the lips in mode II, so sigma^aux .
    // n is not, and + int (sigma^aux n . u_,k theta_k) [+ lip] - (the
    // same) [- lip] completes the identity (it vanishes for straight
    // fronts and in mode I).
    const std::vector<unsigned int> &active = cell_theta.active_tests();
    const std::vector<Point<dim>>    sides =
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
        const Tensor<1, dim> n_ds =
          CellQuadrature::mapped_normal<dim>(side_values.jacobian(2 * k),
                                             normals[k],
                                             weights[k]);
        const CrownPoint<dim> p(
          crown, points[k], side_values.quadrature_point(2 * k), first, last);
        // t ds on the lsn > 0 lip.
        Tensor<1, dim> t_ds =
          (lip_pressure ? lip_pressure->value(p.x) : 0.) * n_ds;
        if (lip_traction)
          t_ds += n_ds.norm() * lip_traction(cell, k);
        // The lsn > 0 lip lies at angle pi in the front frame if e2
        // points to it, else at -pi (the start tip of a segment).
        const double angle_plus =
          ((p.projection.R * n_ds)[1] > 0 ? 1. : -1.) * numbers::PI;
        Tensor<2, dim> plus[n_modes], minus[n_modes];
        aux_gradients<dim, n_modes>(
          unit, p.projection, p.xl, p.r, angle_plus, plus);
        aux_gradients<dim, n_modes>(
          unit, p.projection, p.xl, p.r, -angle_plus, minus);
        Tensor<2, dim> jump[n_integrals];
        for (unsigned int m = 0; m < n_modes; ++m)
          jump[m] = plus[m] - minus[m];
        jump[n_modes] = grad_u[2 * k] - grad_u[2 * k + 1];
        for (const unsigned int j : active)
          theta[j] = cell_theta.value(p.xi, p.r, j);
        for (const unsigned int j : active)
          for (unsigned int m = 0; m < n_integrals; ++m)
            b[j * n_integrals + m] -= t_ds * (jump[m] * theta[j]);
        if constexpr (dim == 3)
          {
            Tensor<1, dim> t_plus[n_modes], t_minus[n_modes];
            for (unsigned int m = 0; m < n_modes; ++m)
              {
                t_plus[m]  = material.stress<dim>(symmetrize(plus[m])) * n_ds;
                t_minus[m] = material.stress<dim>(symmetrize(minus[m])) * n_ds;
              }
            for (const unsigned int j : active)
              for (unsigned int m = 0; m < n_modes; ++m)
                b[j * n_integrals + m] +=
                  t_plus[m] * (grad_u[2 * k] * theta[j]) -
                  t_minus[m] * (grad_u[2 * k + 1] * theta[j]);
            // The derivatives, one side after the other.
            if (d_b)
              for (const unsigned int side : {0u, 1u})
                {
                  for (const unsigned int j : active)
                    for (unsigned int m = 0; m < n_modes; ++m)
                      d_b->add(j,
                               m,
                               side == 0 ?
                                 outer_product(t_plus[m], theta[j]) :
                                 -outer_product(t_minus[m], theta[j]));
                  d_b->flush_point(side_values, 2 * k + side);
                }
          }
      }
  }



  template <int dim>
  void
  FrontIntegrals<dim>::add_face_terms(
    const typename DoFHandler<dim>::active_cell_iterator  &cell,
    const CellTheta<dim>                                  &cell_theta,
    const unsigned int                                     first,
    const unsigned int                                     last,
    const unsigned int                                     face_no,
    const typename InteractionIntegral<dim>::BoundaryFace &face)
  {
    // With t the face's traction and n its outward normal (theta . n =
    // 0): - t . (grad u^aux theta) - sigma^aux n . (grad u theta) for the
    // modes, - t . (grad u theta) for G.
    const Quadrature<dim> &rule = face.rule;
    if (rule.size() == 0)
      return;
    const std::vector<unsigned int> &active = cell_theta.active_tests();
    FEValues<dim>                    values(mapping,
                         cell->get_fe(),
                         rule,
                         update_gradients | update_jacobians |
                           update_quadrature_points);
    values.reinit(cell);
    grad_u.resize(rule.size());
    values[displacement].get_function_gradients(solution, grad_u);
    const Tensor<1, dim> normal =
      GeometryInfo<dim>::unit_normal_vector[face_no];
    Vector<double> traction(dim);
    for (const unsigned int q : values.quadrature_point_indices())
      {
        // n dA, outward.
        const Tensor<1, dim> n_dA =
          CellQuadrature::mapped_normal<dim>(values.jacobian(q),
                                             normal,
                                             rule.weight(q));
        CrownPoint<dim> p(
          crown, rule.point(q), values.quadrature_point(q), first, last);
        p.du = grad_u[q];
        Tensor<1, dim> t_dA;
        if (face.traction)
          {
            face.traction->vector_value(p.x, traction);
            for (unsigned int d = 0; d < dim; ++d)
              t_dA[d] = traction[d] * n_dA.norm();
          }
        Tensor<2, dim> du_aux[n_modes];
        aux_gradients<dim, n_modes>(
          unit, p.projection, p.xl, p.r, p.angle, du_aux);
        Tensor<1, dim> aux_traction[n_modes];
        for (unsigned int m = 0; m < n_modes; ++m)
          aux_traction[m] = material.stress<dim>(symmetrize(du_aux[m])) * n_dA;
        for (const unsigned int j : active)
          {
            const Tensor<1, dim> theta_j  = cell_theta.value(p.xi, p.r, j);
            const Tensor<1, dim> du_theta = p.du * theta_j;
            for (unsigned int m = 0; m < n_modes; ++m)
              {
                b[j * n_integrals + m] -=
                  t_dA * (du_aux[m] * theta_j) + aux_traction[m] * du_theta;
                if (d_b)
                  d_b->add(j, m, -outer_product(aux_traction[m], theta_j));
              }
            b[j * n_integrals + n_modes] -= t_dA * du_theta;
          }
        if (d_b)
          d_b->flush_point(values, q);
      }
  }



  template class FrontIntegrals<2>;
  template class FrontIntegrals<3>;
} // namespace xcrack
