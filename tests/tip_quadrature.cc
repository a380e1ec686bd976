// Requirement: the rule of the cells the crack front touches integrates the
// crack-tip fields accurately. Checked on the unit square (cube) with a
// straight front in several positions (inside, on a vertex, on an edge; in
// 3D along an axis and tilted so that it leaves through side faces):
// - the measure, and H = sign(lsn) (so no sub-cell straddles a lip), to 1e-12;
// - a quartic polynomial, to 1e-12;
// - 1/r (the integrand of |grad F|^2 for the branch functions,
//   |grad F1|^2 = 1/(4r)) against closed forms where they exist, and
//   otherwise against the same rule on the 2^dim sub-cells (self-convergence).

#include <deal.II/base/mpi.h>

#include <xcrack/xfem/cell_quadrature.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

template <int dim>
using Field = std::function<double(const Point<dim> &)>;

/// Integral of @p f over the cube lower + [0,h]^dim with the rule built from
/// the vertex values of @p lsn and @p lst; with @p levels > 0 over its 2^dim
/// children instead, recursively.
template <int dim>
double
integrate(const Field<dim> &f,
          const Field<dim> &lsn,
          const Field<dim> &lst,
          const Point<dim> &lower,
          const double      h,
          const unsigned    n_points,
          const unsigned    levels = 0)
{
  if (levels > 0)
    {
      double sum = 0;
      for (unsigned int c = 0; c < (1u << dim); ++c)
        {
          Point<dim> child = lower;
          for (unsigned int d = 0; d < dim; ++d)
            child[d] += ((c >> d) & 1) * h / 2;
          sum += integrate(f, lsn, lst, child, h / 2, n_points, levels - 1);
        }
      return sum;
    }
  std::vector<double> n_values, t_values;
  for (unsigned int v = 0; v < (1u << dim); ++v)
    {
      Point<dim> x = lower;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += ((v >> d) & 1) * h;
      n_values.push_back(lsn(x));
      t_values.push_back(lst(x));
    }
  const Quadrature<dim> rule =
    CellQuadrature::tip_cell_rule<dim>(n_values, t_values, n_points);
  double sum = 0;
  for (unsigned int q = 0; q < rule.size(); ++q)
    {
      Point<dim> x = lower;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += h * rule.point(q)[d];
      sum += f(x) * rule.weight(q) * std::pow(h, dim);
    }
  return sum;
}

/// The integral of 1/|x| over [0,a] x [0,b].
double
inverse_r_rectangle(const double a, const double b)
{
  if (a == 0 || b == 0)
    return 0;
  const double d = std::hypot(a, b);
  return a * std::log((b + d) / a) + b * std::log((a + d) / b);
}

/// The integral of 1/|x - t| over the unit square.
double
inverse_r_square(const Point<2> &t)
{
  return inverse_r_rectangle(t[0], t[1]) + inverse_r_rectangle(1 - t[0], t[1]) +
         inverse_r_rectangle(t[0], 1 - t[1]) +
         inverse_r_rectangle(1 - t[0], 1 - t[1]);
}

void
check(const std::string &what,
      const double       value,
      const double       exact,
      const double       tolerance)
{
  const double error = std::abs(value - exact) / std::max(1., std::abs(exact));
  logfile << "  " << what << ": " << std::setprecision(10) << value
          << (error <= tolerance ? "  ok" : "  WRONG") << " (tolerance "
          << std::setprecision(1) << tolerance << ")" << std::endl;
}

template <int dim>
void
check_front(const std::string &name,
            const Field<dim>  &lsn,
            const Field<dim>  &lst,
            const double       lower_side_measure,
            const double       inverse_r_exact)
{
  logfile << name << std::endl;
  const Point<dim> origin;
  const Field<dim> one = [](const Point<dim> &) { return 1.; };
  const Field<dim> H   = [&](const Point<dim> &x) {
    return lsn(x) >= 0 ? 1. : -1.;
  };
  const Field<dim> quartic = [](const Point<dim> &x) {
    return x[0] * x[0] * x[1] * x[1] * (dim == 3 ? x[2] + 1 : 1.);
  };
  const Field<dim> inverse_r = [&](const Point<dim> &x) {
    return 1. / std::hypot(lsn(x), lst(x));
  };
  check("measure", integrate(one, lsn, lst, origin, 1., 6), 1., 1e-12);
  check("integral of H",
        integrate(H, lsn, lst, origin, 1., 6),
        1 - 2 * lower_side_measure,
        1e-12);
  check("integral of x^2 y^2 (z + 1)",
        integrate(quartic, lsn, lst, origin, 1., 6),
        (dim == 2 ? 1. / 9 : 1.5 / 9),
        1e-12);
  if (inverse_r_exact > 0)
    {
      check("integral of 1/r, 6 points",
            integrate(inverse_r, lsn, lst, origin, 1., 6),
            inverse_r_exact,
            1e-8);
      check("integral of 1/r, 3 points",
            integrate(inverse_r, lsn, lst, origin, 1., 3),
            inverse_r_exact,
            1e-4);
    }
  else
    {
      const double reference =
        integrate(inverse_r, lsn, lst, origin, 1., 10, 2);
      check("integral of 1/r, 6 points, against 64 sub-cells with 10",
            integrate(inverse_r, lsn, lst, origin, 1., 6),
            reference,
            1e-6);
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 2D: crack along y = ty, x < tx, tip at (tx, ty).
  for (const auto &tip :
       {Point<2>(0.3, 0.6), Point<2>(0, 0), Point<2>(0.5, 0), Point<2>(1, 0.5)})
    {
      std::ostringstream name;
      name << "2D, tip at (" << tip << ")";
      check_front<2>(
        name.str(),
        [&](const Point<2> &x) { return x[1] - tip[1]; },
        [&](const Point<2> &x) { return x[0] - tip[0]; },
        tip[1],
        inverse_r_square(tip));
    }
  // 2D, inclined crack: lsn and lst rotated by 30 degrees about (0.4, 0.45).
  {
    const double   c = std::cos(numbers::PI / 6), s = std::sin(numbers::PI / 6);
    const Field<2> lsn = [&](const Point<2> &x) {
      return -s * (x[0] - 0.4) + c * (x[1] - 0.45);
    };
    const Field<2> lst = [&](const Point<2> &x) {
      return c * (x[0] - 0.4) + s * (x[1] - 0.45);
    };
    // Below the crack line: the trapezoid under y = 0.45 + tan30 (x - 0.4)
    // for x in [0, 0.4] plus the part of the square right of the tip with
    // lsn < 0 as well (the extension of the plane ahead of the tip).
    const double t = s / c;
    check_front<2>("2D, crack inclined at 30 degrees",
                   lsn,
                   lst,
                   0.45 - t * 0.4 + t * 0.5,
                   inverse_r_square(Point<2>(0.4, 0.45)));
  }

  // 3D: the same tip extruded along z, and a front tilted so that it leaves
  // the cube through a side face.
  check_front<3>(
    "3D, front along z through (0.3, 0.6)",
    [](const Point<3> &x) { return x[1] - 0.6; },
    [](const Point<3> &x) { return x[0] - 0.3; },
    0.6,
    inverse_r_square(Point<2>(0.3, 0.6)));
  check_front<3>(
    "3D, front along z on the edge x = y = 0",
    [](const Point<3> &x) { return x[1]; },
    [](const Point<3> &x) { return x[0]; },
    0.,
    inverse_r_square(Point<2>(0, 0)));
  {
    // Front x = 0.2 + 0.6 z, y = 0.55: direction (0.6, 0, 1)/|.|.
    const double   norm = std::hypot(1., 0.6);
    const Field<3> lsn  = [](const Point<3> &x) { return x[1] - 0.55; };
    const Field<3> lst  = [=](const Point<3> &x) {
      return (x[0] - 0.2 - 0.6 * x[2]) / norm;
    };
    check_front<3>("3D, front tilted in the crack plane, leaving through x = 1",
                   lsn,
                   lst,
                   0.55,
                   0.);
  }
}
