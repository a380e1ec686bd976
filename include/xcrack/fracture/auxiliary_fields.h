#ifndef xcrack_fracture_auxiliary_fields_h
#define xcrack_fracture_auxiliary_fields_h

#include <deal.II/base/tensor.h>

#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/williams.h>

#include <cmath>

namespace xcrack
{
  using namespace dealii;

  /// The dim x dim block of a 3 x 3 tensor.
  template <int dim>
  Tensor<2, dim>
  leading_block(const Tensor<2, 3> &t)
  {
    Tensor<2, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        result[i][j] = t[i][j];
    return result;
  }



  /**
   * Gradients (global components) of the auxiliary fields u = u_a(x1, x2)
   * e_a(s) of unit K_I, K_II (, K_III) at local coordinates @p xl, polar
   * (@p r, @p angle), of the front frame at the projection: the plane
   * Williams gradient rotated, plus, along a curved 3D front, the turning
   * of the frame, u_a de_a/ds (x) grad s with grad s = e3 / (1 + x1
   * de1/ds . e3 + x2 de2/ds . e3). Without that term the auxiliary strain
   * is not the strain of any displacement and K along a circle of radius
   * rho is off by about r_sup / rho (7 % for crowns of 4 cells of 1/16 on
   * the unit penny). @p unit gives mu and kappa.
   */
  template <int dim, int n_modes>
  void
  aux_gradients(const WilliamsField                        &unit,
                const typename FrontCurve<dim>::Projection &projection,
                const Tensor<1, dim>                       &xl,
                const double                                r,
                const double                                angle,
                Tensor<2, dim> (&gradients)[n_modes])
  {
    Tensor<1, 3> u[3];
    Tensor<2, 3> local[3];
    unit.unit_modes(r, angle, u, local);
    const Tensor<2, dim> &R   = projection.R;
    const double          h_s = projection.jacobian_s(xl);
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        gradients[m] = transpose(R) * leading_block<dim>(local[m]) * R;
        if constexpr (dim == 3)
          {
            const Tensor<1, 3> e3 = R[2];
            for (unsigned int a = 0; a < 3; ++a)
              gradients[m] +=
                (u[m][a] / h_s) * outer_product(projection.dR[a], e3);
          }
      }
  }



  /**
   * div sigma^aux of the unit fields of aux_gradients() (K_I, K_II, K_III
   * = 1) at @p x along a 3D front, whose foot is @p projection, local
   * coordinates @p xl, angle @p angle: the interaction integral's
   * non-equilibrium term. The fields are G(x) = G(s(x), xl(x)) with xl = R(s)
   * (x - p(s)), so
   *
   *   d G / d x_j = (d G / d xl_b) R_bj + D grad_j s,
   *
   * D = d G / d s at fixed x (the foot moved along the front,
   * FrontCurve::moved(), differenced over a small step) and grad s of
   * FrontCurve::grad_s(). In the first term the plane Williams part is in
   * equilibrium (its divergence at a fixed frame vanishes), which leaves
   * the turning part u_a de_a/ds (x) e3 / h_s, differentiated here in
   * closed form. This replaces central differences of the fields at six
   * shifted points, each a projection on the front. With the nearest point
   * as the foot (FrontCurve::project()'s fallback) the jumps of the foot
   * across bisector planes are left out: they are no divergence.
   */
  template <int n_modes>
  void
  aux_stress_divergence(const WilliamsField                      &unit,
                        const FrontCurve<3>                      &curve,
                        const Point<3>                           &x,
                        const typename FrontCurve<3>::Projection &projection,
                        const Tensor<1, 3>                       &xl,
                        const double                              angle,
                        Tensor<1, 3> (&divergence)[n_modes])
  {
    const double mu     = unit.mu;
    const double lambda = mu * (3 - unit.kappa) / (unit.kappa - 1);
    const double r      = std::hypot(xl[0], xl[1]);
    Tensor<1, 3> u[3];
    Tensor<2, 3> local[3];
    unit.unit_modes(r, angle, u, local);

    // D: the fields at x with the foot at s -+ a step, the angle kept on
    // the branch of x's (the fields extend smoothly across the lips).
    const auto [s_minus, s_plus] = curve.difference_abscissae(projection);
    Tensor<2, 3> G_minus[n_modes], G_plus[n_modes];
    for (const double s : {s_minus, s_plus})
      {
        const auto   moved = curve.moved(projection, s);
        const auto   yl    = moved.R * (x - moved.foot);
        const double ry    = std::hypot(yl[0], yl[1]);
        double       a     = std::atan2(yl[1], yl[0]);
        if (a - angle > numbers::PI)
          a -= 2 * numbers::PI;
        else if (a - angle < -numbers::PI)
          a += 2 * numbers::PI;
        aux_gradients<3, n_modes>(
          unit, moved, yl, ry, a, s == s_minus ? G_minus : G_plus);
      }
    const Tensor<1, 3> grad_s = curve.grad_s(x, projection);

    // The turning part's gradient at a fixed frame: d/dx_j of u_a dR_a
    // (x) e3 / h_s is dR_a (x) e3 (x) w_a with w_a = (grad u_a) / h_s -
    // u_a grad h_s / h_s^2, in the plane (e1, e2).
    const Tensor<2, 3> &R      = projection.R;
    const Tensor<2, 3> &dR     = projection.dR;
    const Tensor<1, 3>  e3     = R[2];
    const double        h_s    = projection.jacobian_s(xl);
    const Tensor<1, 3>  grad_h = (dR[0] * e3) * R[0] + (dR[1] * e3) * R[1];
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        Tensor<1, 3> trace_part;
        double       along_e3 = 0;
        for (unsigned int a = 0; a < 3; ++a)
          {
            const Tensor<1, 3> w =
              (local[m][a][0] * R[0] + local[m][a][1] * R[1]) / h_s -
              (u[m][a] / (h_s * h_s)) * grad_h;
            // d_i tr: (dR_a . e3) w_a; d_j of the transpose: (dR_a . w_a)
            // e3; d_j of the tensor itself: (e3 . w_a) dR_a = 0.
            trace_part += (dR[a] * e3) * w;
            along_e3 += dR[a] * w;
          }
        const Tensor<2, 3> D = (G_plus[m] - G_minus[m]) / (s_plus - s_minus);
        divergence[m]        = lambda * (trace_part + trace(D) * grad_s) +
                        mu * (along_e3 * e3 + (D + transpose(D)) * grad_s);
      }
  }
} // namespace xcrack

#endif
