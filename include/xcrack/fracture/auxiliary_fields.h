#ifndef xcrack_fracture_auxiliary_fields_h
#define xcrack_fracture_auxiliary_fields_h

#include <deal.II/base/tensor.h>

#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/williams.h>

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
    const Tensor<2, dim> &R = projection.R;
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        gradients[m] = transpose(R) * leading_block<dim>(local[m]) * R;
        if constexpr (dim == 3)
          {
            const Tensor<1, 3> e3  = R[2];
            const double       h_s = 1 + xl[0] * (projection.dR[0] * e3) +
                               xl[1] * (projection.dR[1] * e3);
            for (unsigned int a = 0; a < 3; ++a)
              gradients[m] +=
                (u[m][a] / h_s) * outer_product(projection.dR[a], e3);
          }
      }
  }
} // namespace xcrack

#endif
