#include <xcrack/xfem/branch_functions.h>

#include <cmath>

namespace xcrack
{
  template <int dim>
  BranchFunction<dim>::BranchFunction(const LevelSetFunctions<dim> &crack,
                                      const unsigned int            index)
    : crack(crack)
    , index(index)
  {
    AssertIndexRange(index, n_functions);
  }



  template <int dim>
  void
  BranchFunction<dim>::set_cutoff(const double inner, const double outer)
  {
    Assert(0 <= inner && inner < outer, ExcMessage("Bad cut-off radii."));
    cutoff_inner = inner;
    cutoff_outer = outer;
  }



  namespace
  {
    /// The cut-off chi(r) and its derivative (chi = 1 without cut-off).
    std::pair<double, double>
    cutoff(const double r, const double inner, const double outer)
    {
      if (outer == 0 || r <= inner)
        return {1., 0.};
      if (r >= outer)
        return {0., 0.};
      const double t = (r - inner) / (outer - inner);
      return {1 - 3 * t * t + 2 * t * t * t,
              (-6 * t + 6 * t * t) / (outer - inner)};
    }

    /// theta = atan2(lsn, lst) with lsn = 0 counted on the + side (+pi on
    /// the lips), whatever the sign of the zero.
    double
    polar_angle(const double lsn, const double lst)
    {
      return std::atan2(lsn == 0 ? 0. : lsn, lst);
    }
  } // namespace



  template <int dim>
  std::array<double, 3>
  BranchFunction<dim>::polar_values(const double r, const double theta) const
  {
    const double sqrt_r = std::sqrt(r);
    const double s2 = std::sin(theta / 2), c2 = std::cos(theta / 2);
    const double s = std::sin(theta), c = std::cos(theta);
    double       f = 0, df_dtheta = 0;
    switch (index)
      {
        case 0:
          f         = s2;
          df_dtheta = 0.5 * c2;
          break;
        case 1:
          f         = c2;
          df_dtheta = -0.5 * s2;
          break;
        case 2:
          f         = s2 * s;
          df_dtheta = 0.5 * c2 * s + s2 * c;
          break;
        default:
          f         = c2 * s;
          df_dtheta = -0.5 * s2 * s + c2 * c;
          break;
      }
    // F = sqrt(r) f(theta): dF/dr = F / (2r).
    return {{sqrt_r * f, (r > 0 ? 0.5 * f / sqrt_r : 0.), sqrt_r * df_dtheta}};
  }



  template <int dim>
  double
  BranchFunction<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    const double n = crack.lsn(p), t = crack.lst(p);
    const double r = std::hypot(n, t);
    return polar_values(r, polar_angle(n, t))[0] *
           cutoff(r, cutoff_inner, cutoff_outer).first;
  }



  template <int dim>
  Tensor<1, dim>
  BranchFunction<dim>::gradient(const Point<dim> &p, const unsigned int) const
  {
    const double n = crack.lsn(p), t = crack.lst(p);
    const double r = std::hypot(n, t);
    if (r == 0)
      return Tensor<1, dim>(); // singular; quadrature points avoid the front

    const auto [grad_n, grad_t]     = crack.gradients(p);
    const auto           values     = polar_values(r, polar_angle(n, t));
    const Tensor<1, dim> grad_r     = (n * grad_n + t * grad_t) / r;
    const Tensor<1, dim> grad_theta = (t * grad_n - n * grad_t) / (r * r);
    const auto [chi, dchi]          = cutoff(r, cutoff_inner, cutoff_outer);
    return chi * (values[1] * grad_r + values[2] * grad_theta) +
           values[0] * dchi * grad_r;
  }



  template class BranchFunction<2>;
  template class BranchFunction<3>;
} // namespace xcrack
