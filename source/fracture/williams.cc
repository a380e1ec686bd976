#include <deal.II/lac/vector.h>

#include <xcrack/fracture/williams.h>

#include <cmath>

namespace xcrack
{
  Tensor<1, 3>
  WilliamsField::displacement(const double r, const double theta) const
  {
    Tensor<1, 3> u[3];
    Tensor<2, 3> grad[3];
    unit_modes(r, theta, u, grad);
    return k_I * u[0] + k_II * u[1] + k_III * u[2];
  }



  Tensor<2, 3>
  WilliamsField::displacement_gradient(const double r, const double theta) const
  {
    Tensor<1, 3> u[3];
    Tensor<2, 3> grad[3];
    unit_modes(r, theta, u, grad);
    return k_I * grad[0] + k_II * grad[1] + k_III * grad[2];
  }



  void
  WilliamsField::unit_modes(const double r,
                            const double theta,
                            Tensor<1, 3> (&u)[3],
                            Tensor<2, 3> (&grad)[3]) const
  {
    const double g = std::sqrt(r / (2 * numbers::PI));
    const double f = g / (2 * mu);
    const double c = std::cos(theta / 2), s = std::sin(theta / 2);
    const double ct = std::cos(theta), st = std::sin(theta);

    // u = f(r) a(theta): d/dr = u / (2 r), d/dtheta = f a'(theta).
    Tensor<1, 3> du_dtheta[3];
    for (unsigned int m = 0; m < 3; ++m)
      {
        u[m]         = Tensor<1, 3>();
        du_dtheta[m] = Tensor<1, 3>();
      }
    u[0][0]         = f * (c * (kappa - ct));
    u[0][1]         = f * (s * (kappa - ct));
    du_dtheta[0][0] = f * (-0.5 * s * (kappa - ct) + c * st);
    du_dtheta[0][1] = f * (0.5 * c * (kappa - ct) + s * st);
    u[1][0]         = f * (s * (kappa + 2 + ct));
    u[1][1]         = f * (-(c * (kappa - 2 + ct)));
    du_dtheta[1][0] = f * (0.5 * c * (kappa + 2 + ct) - s * st);
    du_dtheta[1][1] = f * (0.5 * s * (kappa - 2 + ct) + c * st);
    u[2][2]         = 2. / mu * g * s;
    du_dtheta[2][2] = 2. / mu * g * 0.5 * c;

    for (unsigned int m = 0; m < 3; ++m)
      {
        grad[m] = Tensor<2, 3>();
        for (unsigned int i = 0; i < 3; ++i)
          {
            const double du_dr = u[m][i] / (2 * r);
            grad[m][i][0]      = ct * du_dr - st / r * du_dtheta[m][i];
            grad[m][i][1]      = st * du_dr + ct / r * du_dtheta[m][i];
          }
      }
  }



  SymmetricTensor<2, 3>
  WilliamsField::stress(const double r, const double theta) const
  {
    const double k = 1 / std::sqrt(2 * numbers::PI * r);
    const double c = std::cos(theta / 2), s = std::sin(theta / 2);
    const double s3 = std::sin(1.5 * theta), c3 = std::cos(1.5 * theta);
    SymmetricTensor<2, 3> sigma;
    sigma[0][0] = k_I * k * c * (1 - s * s3) - k_II * k * s * (2 + c * c3);
    sigma[1][1] = k_I * k * c * (1 + s * s3) + k_II * k * s * c * c3;
    sigma[0][1] = k_I * k * s * c * c3 + k_II * k * c * (1 - s * s3);
    sigma[0][2] = -k_III * k * s;
    sigma[1][2] = k_III * k * c;
    return sigma;
  }



  template <int dim>
  WilliamsSolution<dim>::WilliamsSolution(const WilliamsField  &field,
                                          const Point<dim>     &tip,
                                          const Tensor<1, dim> &e1,
                                          const Tensor<1, dim> &e2)
    : Function<dim>(dim)
    , field(field)
    , tip(tip)
  {
    rotation[0] = e1 / e1.norm();
    rotation[1] = e2 / e2.norm();
    if (dim == 3)
      {
        Tensor<1, 3> a, b;
        for (unsigned int d = 0; d < dim; ++d)
          {
            a[d] = rotation[0][d];
            b[d] = rotation[1][d];
          }
        const Tensor<1, 3> e3 = cross_product_3d(a, b);
        for (unsigned int d = 0; d < dim; ++d)
          rotation[dim - 1][d] = e3[d];
      }
  }



  template <int dim>
  std::pair<double, double>
  WilliamsSolution<dim>::polar(const Point<dim> &p) const
  {
    const Tensor<1, dim> x = rotation * (p - tip);
    return {std::hypot(x[0], x[1]), std::atan2(x[1], x[0])};
  }



  template <int dim>
  void
  WilliamsSolution<dim>::vector_value(const Point<dim> &p,
                                      Vector<double>   &values) const
  {
    const auto [r, theta]    = polar(p);
    const Tensor<1, 3> local = field.displacement(r, theta);
    // Global components: u = R^T u_local.
    for (unsigned int i = 0; i < dim; ++i)
      {
        values[i] = 0;
        for (unsigned int k = 0; k < dim; ++k)
          values[i] += rotation[k][i] * local[k];
      }
  }



  template <int dim>
  double
  WilliamsSolution<dim>::value(const Point<dim>  &p,
                               const unsigned int component) const
  {
    Vector<double> values(dim);
    vector_value(p, values);
    return values[component];
  }



  template <int dim>
  void
  WilliamsSolution<dim>::vector_gradient(
    const Point<dim>            &p,
    std::vector<Tensor<1, dim>> &gradients) const
  {
    const auto [r, theta]    = polar(p);
    const Tensor<2, 3> local = field.displacement_gradient(r, theta);
    // grad u = R^T (grad' u') R.
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          double value = 0;
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              value += rotation[k][i] * local[k][l] * rotation[l][j];
          gradients[i][j] = value;
        }
  }



  template <int dim>
  Tensor<1, dim>
  WilliamsSolution<dim>::gradient(const Point<dim>  &p,
                                  const unsigned int component) const
  {
    std::vector<Tensor<1, dim>> gradients(dim);
    vector_gradient(p, gradients);
    return gradients[component];
  }



  template class WilliamsSolution<2>;
  template class WilliamsSolution<3>;
} // namespace xcrack
