// Requirement: the graded Gauss rule of the cells near a crack front that it
// does not touch (Enrichment/Near-front quadrature tolerance) reaches the
// tolerance it was built for. CellQuadrature::front_distance gives the
// distance from the reference cube to a front line beside it (straight,
// along an axis or oblique, ahead of the cell or with the lips passing over
// it); CellQuadrature::graded_gauss_points then picks the order, and the
// integrals of the functions the stiffness and the interaction integral
// meet there, |grad F|^2 = 1/(4 r) and the half-angle dF1/dx = -sin(theta/2)
// / (2 sqrt r) (it changes sign across the lips, which lie outside the
// cell), are within the tolerance of a 60-point Gauss reference at
// distances 0.1 to 1 and tolerances 1e-3 to 1e-6.

#include <deal.II/base/quadrature_lib.h>

#include <xcrack/xfem/cell_quadrature.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <string>
#include <vector>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

namespace
{
  /// A straight front through @p tip along e3 = e1 x e2, the crack behind it
  /// (lst < 0 against e1) in the plane normal to @p e2.
  struct Front
  {
    Point<3>     tip;
    Tensor<1, 3> e1, e2;

    double
    lsn(const Point<3> &x) const
    {
      return (x - tip) * e2;
    }
    double
    lst(const Point<3> &x) const
    {
      return (x - tip) * e1;
    }
    /// r and the angle from e1 (the lips at +-pi).
    std::pair<double, double>
    polar(const Point<3> &x) const
    {
      return {std::hypot(lst(x), lsn(x)), std::atan2(lsn(x), lst(x))};
    }
  };

  double
  integrate(const Quadrature<3>                           &rule,
            const std::function<double(const Point<3> &)> &f)
  {
    double sum = 0;
    for (unsigned int q = 0; q < rule.size(); ++q)
      sum += f(rule.point(q)) * rule.weight(q);
    return sum;
  }
} // namespace

int
main()
{
  const double s = 1 / std::sqrt(2.);
  struct Case
  {
    std::string name;
    /// The front at this distance from the cube.
    std::function<Front(double)> front;
  };
  const std::vector<Case> cases = {
    // Ahead of the cell, the crack running away from it.
    {"ahead, along z",
     [](const double d) {
       return Front{Point<3>(1 + d, 0.4, 0.5),
                    Tensor<1, 3>({-1, 0, 0}),
                    Tensor<1, 3>({0, 1, 0})};
     }},
    // The lips over the cell (at height 1 + d), the front beyond its end.
    {"lips over the cell",
     [](const double d) {
       return Front{Point<3>(1 + d, 1 + d, 0.3),
                    Tensor<1, 3>({1, 0, 0}),
                    Tensor<1, 3>({0, 1, 0})};
     }},
    // Oblique: beside an edge of the cube, tilted, the cube ahead of it.
    {"beside an edge, oblique", [s](const double d) {
       return Front{Point<3>(1 + d * s, 1 + d * s, 0.5),
                    Tensor<1, 3>({-s, -s, 0}),
                    Tensor<1, 3>({-s * 0.8, s * 0.8, 0.6})};
     }}};

  const QGauss<3> reference_rule(60);
  for (const Case &c : cases)
    for (const double d : {0.1, 0.3, 1.0})
      {
        const Front front = c.front(d);
        // The level sets at the cube's vertices (deal.II's numbering).
        std::vector<double> lsn(8), lst(8);
        for (unsigned int v = 0; v < 8; ++v)
          {
            const Point<3> x(v & 1, (v >> 1) & 1, (v >> 2) & 1);
            lsn[v] = front.lsn(x);
            lst[v] = front.lst(x);
          }
        // The exact distance: from the front line to the cube, by sampling
        // the line finely.
        double exact = 1e300;
        for (int k = -20000; k <= 20000; ++k)
          {
            Tensor<1, 3> e3 = cross_product_3d(front.e1, front.e2);
            e3 /= e3.norm();
            Point<3> x = front.tip + (k * 1e-4) * e3, y = x;
            for (unsigned int i = 0; i < 3; ++i)
              y[i] = std::clamp(y[i], 0., 1.);
            exact = std::min(exact, x.distance(y));
          }
        const double distance = CellQuadrature::front_distance<3>(lsn, lst);
        logfile << c.name << ", d = " << std::setprecision(1) << std::fixed << d
                << ": distance within 1e-6: "
                << (std::abs(distance - exact) < 1e-6 ? "yes" : "no");

        const auto energy = [&](const Point<3> &x) {
          return 1 / (4 * front.polar(x).first);
        };
        const auto half_angle = [&](const Point<3> &x) {
          const auto [r, theta] = front.polar(x);
          return -std::sin(theta / 2) / (2 * std::sqrt(r));
        };
        for (const double tolerance : {1e-3, 1e-6})
          {
            const unsigned int n =
              CellQuadrature::graded_gauss_points(distance, tolerance);
            const QGauss<3> rule(n);
            bool            met = true;
            for (const auto &f :
                 std::vector<std::function<double(const Point<3> &)>>{
                   energy, half_angle})
              {
                // Relative to the integral of |f|: the half-angle
                // function's own integral may vanish by symmetry.
                const double exact_integral = integrate(reference_rule, f);
                const double size =
                  integrate(reference_rule,
                            [&](const Point<3> &x) { return std::abs(f(x)); });
                met = met && std::abs(integrate(rule, f) - exact_integral) <=
                               tolerance * size;
              }
            logfile << "; tolerance " << std::scientific << std::setprecision(0)
                    << tolerance << ": " << n
                    << " points, met: " << (met ? "yes" : "no") << std::fixed;
          }
        logfile << '\n';
      }
}
