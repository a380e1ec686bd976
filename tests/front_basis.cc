// Requirement: the bases on which K(s) is discretised along a 3D front give
// back, from the moments b_j = int K psi_j ds that the virtual extensions
// measure, the K they can represent:
// - Legendre (open front): every polynomial up to the degree, exactly;
// - its periodic form on a closed front: every trigonometric polynomial up
//   to the degree, exactly (and the values at s = 0 and s = L agree);
// - Lagrange: every piecewise-linear K on the segments exactly, a smooth K
//   with an error falling like l^2;
// - regularised Lagrange: constants exactly, a linear K exactly away from
//   the ends, a quadratic K with the bias K'' (2 l)^2 / 12 of the average
//   over four segments, and no oscillation: a K alternating from node to
//   node is averaged away.

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <xcrack/fracture/front_basis.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile;

/// The moments of @p k on the basis, by a fine Gauss rule.
std::vector<double>
moments(const FrontBasis                    &basis,
        const double                         length,
        const std::function<double(double)> &k)
{
  const QGauss<1>     gauss(10);
  const unsigned int  n_cells = 2000;
  std::vector<double> b(basis.n_test_functions(), 0.);
  for (unsigned int c = 0; c < n_cells; ++c)
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double s = (c + gauss.point(q)[0]) * length / n_cells;
        const double w = gauss.weight(q) * length / n_cells;
        for (unsigned int j = 0; j < b.size(); ++j)
          b[j] += k(s) * basis.test_function(j, s) * w;
      }
  return b;
}

/// Largest |K_node - k(s_node)| over the nodes (optionally leaving out
/// @p skip nodes at each end).
double
node_error(const FrontBasis                    &basis,
           const double                         length,
           const std::function<double(double)> &k,
           const unsigned int                   skip = 0)
{
  const std::vector<double> values =
    basis.values_at_nodes(moments(basis, length, k));
  double error = 0;
  for (unsigned int i = skip; i + skip < values.size(); ++i)
    error = std::max(error, std::abs(values[i] - k(basis.nodes()[i])));
  return error;
}

const char *
below(const double error, const double tolerance)
{
  return error < tolerance ? "yes" : "NO";
}

int
main()
{
  logfile.open("output");
  logfile << std::setprecision(4);
  const double L  = 2.5;
  const double pi = numbers::PI;

  {
    const FrontBasis basis(FrontBasis::Type::legendre, 3, L, false, 10);
    logfile << "legendre degree 3, open front, " << basis.n_test_functions()
            << " functions, " << basis.nodes().size() << " nodes" << std::endl;
    const auto cubic = [](double s) { return 1 - 2 * s + 0.5 * s * s * s; };
    logfile << "  cubic K exact (1e-10): "
            << below(node_error(basis, L, cubic), 1e-10) << std::endl;
    const auto quartic = [](double s) { return s * s * s * s; };
    logfile << "  quartic K not representable, error > 1e-3: "
            << below(1e-3, node_error(basis, L, quartic)) << std::endl;
  }
  {
    const FrontBasis basis(FrontBasis::Type::legendre, 2, L, true, 12);
    logfile << "legendre degree 2 on a closed front (Fourier), "
            << basis.n_test_functions() << " functions, "
            << basis.nodes().size() << " nodes" << std::endl;
    const auto trig = [&](double s) {
      return 1 + std::cos(2 * pi * s / L) - 0.5 * std::sin(4 * pi * s / L);
    };
    logfile << "  trigonometric K of degree 2 exact (1e-10): "
            << below(node_error(basis, L, trig), 1e-10) << std::endl;
  }
  {
    logfile << "lagrange, open front" << std::endl;
    const auto linear_pieces = [&](double s) {
      return std::abs(s - 0.5 * L); // kink at a node for 10 segments
    };
    const FrontBasis basis(FrontBasis::Type::lagrange, 0, L, false, 10);
    logfile << "  piecewise-linear K exact (1e-10): "
            << below(node_error(basis, L, linear_pieces), 1e-10) << std::endl;
    const auto   smooth = [&](double s) { return std::sin(2 * s); };
    const double e1 =
      node_error(FrontBasis(FrontBasis::Type::lagrange, 0, L, false, 10),
                 L,
                 smooth);
    const double e2 =
      node_error(FrontBasis(FrontBasis::Type::lagrange, 0, L, false, 20),
                 L,
                 smooth);
    logfile << "  smooth K: error rate from 10 to 20 segments "
            << std::round(std::log2(e1 / e2) * 10) / 10 << std::endl;
  }
  {
    logfile << "lagrange regularized" << std::endl;
    const unsigned int n = 16;
    const double       l = L / n;
    const FrontBasis   open(
      FrontBasis::Type::lagrange_regularized, 0, L, false, n);
    logfile << "  constant exact (1e-12): "
            << below(node_error(open, L, [](double) { return 3.; }), 1e-12)
            << std::endl;
    logfile << "  linear K exact two nodes away from the ends (1e-12): "
            << below(node_error(
                       open, L, [](double s) { return 1 + s; }, 2),
                     1e-12)
            << std::endl;
    const double bias = node_error(
      open, L, [](double s) { return s * s; }, 2);
    logfile << "  quadratic K: bias / (K'' (2 l)^2 / 12) = "
            << bias / (2 * (2 * l) * (2 * l) / 12) << std::endl;
    // A saw tooth through the nodes of a closed front (even count): the
    // wide hats see only its mean.
    const FrontBasis closed(
      FrontBasis::Type::lagrange_regularized, 0, L, true, n);
    const auto saw = [&](double s) {
      const double t    = s / l;
      const double k    = std::round(t);
      const double sign = (static_cast<long>(k) % 2 == 0 ? 1. : -1.);
      return sign * (1 - 2 * std::abs(t - k));
    };
    const std::vector<double> values =
      closed.values_at_nodes(moments(closed, L, saw));
    double largest = 0;
    for (const double v : values)
      largest = std::max(largest, std::abs(v));
    logfile << "  saw tooth of amplitude 1 smoothed to below 1e-10: "
            << below(largest, 1e-10) << std::endl;
    const FrontBasis          plain(FrontBasis::Type::lagrange, 0, L, true, n);
    const std::vector<double> kept =
      plain.values_at_nodes(moments(plain, L, saw));
    logfile << "  (the consistent mass matrix keeps it: amplitude "
            << std::round(std::abs(kept[0]) * 1e4) / 1e4 << ")" << std::endl;
  }
}
