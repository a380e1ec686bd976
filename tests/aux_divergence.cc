// Requirement: the divergence of the auxiliary stresses along a curved 3D
// front (aux_stress_divergence, the interaction integral's non-equilibrium
// term) is the divergence of the fields that aux_gradients() gives at the
// feet FrontCurve::project() finds: it agrees with central differences of
// those fields over 1e-6 r (a projection of each of six shifted points) at
// points of the crown around the front, at every distance and angle, on a
// planar circle (the turning of e1 alone) and on a wavy, tilted front (e2
// turns too), for the three modes; on a straight front both vanish. The
// differences are relative to sqrt(1 / r), the size of the divergence along
// a front of unit curvature; dropping either part of the analytic form (the
// turning term's gradient at a fixed frame, or the foot's motion) makes them
// of order 1.

#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/front_curve.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <vector>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

namespace
{
  /// A closed front through @p position(t), t in [0, 2 pi), @p n points,
  /// with normals @p normal(t) (e2) and e1 = e2 x e3.
  std::vector<FrontPoint<3>>
  front(const std::function<Point<3>(double)>     &position,
        const std::function<Tensor<1, 3>(double)> &normal,
        const unsigned int                         n)
  {
    std::vector<FrontPoint<3>> points(n + 1);
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double   t = -2 * numbers::PI * (i % n) / n;
        FrontPoint<3> &p = points[i];
        p.position       = position(t);
        const double dt  = 1e-6;
        Tensor<1, 3> e3  = position(t - dt) - position(t + dt);
        e3 /= e3.norm();
        p.e2 = normal(t);
        p.e2 -= (p.e2 * e3) * e3;
        p.e2 /= p.e2.norm();
        p.e3 = e3;
        p.e1 = cross_product_3d(p.e2, e3);
        if (i > 0)
          p.s = points[i - 1].s + points[i - 1].position.distance(p.position);
      }
    return points;
  }

  /// The divergence of C : eps of the unit fields at the feet of project(),
  /// by central differences over @p delta (the angle on x's branch).
  void
  reference(const WilliamsField &unit,
            const FrontCurve<3> &curve,
            const Point<3>      &x,
            const double         angle,
            const double         delta,
            Tensor<1, 3> (&divergence)[3])
  {
    const double mu     = unit.mu,
                 lambda = mu * (3 - unit.kappa) / (unit.kappa - 1);
    for (auto &d : divergence)
      d = Tensor<1, 3>();
    for (unsigned int j = 0; j < 3; ++j)
      for (const double sign : {1., -1.})
        {
          Point<3> y = x;
          y[j] += sign * delta;
          const auto         p  = curve.project(y);
          const Tensor<1, 3> yl = p.R * (y - p.foot);
          double             a  = std::atan2(yl[1], yl[0]);
          if (a - angle > numbers::PI)
            a -= 2 * numbers::PI;
          else if (a - angle < -numbers::PI)
            a += 2 * numbers::PI;
          Tensor<2, 3> g[3];
          aux_gradients<3, 3>(unit, p, yl, std::hypot(yl[0], yl[1]), a, g);
          for (unsigned int m = 0; m < 3; ++m)
            {
              const SymmetricTensor<2, 3> eps = symmetrize(g[m]);
              for (unsigned int i = 0; i < 3; ++i)
                divergence[m][i] +=
                  sign * (lambda * trace(eps) * (i == j) + 2 * mu * eps[i][j]) /
                  (2 * delta);
            }
        }
  }

  /// Compares both at 400 points of a crown r < 0.4 around @p points.
  void
  compare(const std::string &name, const std::vector<FrontPoint<3>> &points)
  {
    WilliamsField unit;
    unit.mu                   = 1 / 2.6;
    unit.kappa                = 3 - 4 * 0.3;
    const double        r_sup = 0.4;
    const FrontCurve<3> curve(points, 0.5 * r_sup);
    std::vector<double> differences;
    double              largest    = 0;
    unsigned int        n_fallback = 0;
    for (unsigned int k = 0; k < 400; ++k)
      {
        // Points spread over the front, the radius and the angle (lips
        // included, from both sides).
        const double   s     = curve.length * (k + 0.37) / 400;
        const double   r     = r_sup * (0.02 + 0.96 * std::fmod(k * 0.618, 1.));
        const double   theta = numbers::PI * (2 * std::fmod(k * 0.382, 1.) - 1);
        const auto     at    = curve.at(s);
        const Point<3> x =
          at.position + r * (std::cos(theta) * at.e1 + std::sin(theta) * at.e2);
        const auto projection = curve.project(x);
        if (projection.kind != FrontCurve<3>::Projection::Kind::normal_plane)
          {
            ++n_fallback;
            continue;
          }
        const Tensor<1, 3> xl    = projection.R * (x - projection.foot);
        const double       angle = std::atan2(xl[1], xl[0]);
        Tensor<1, 3>       analytic[3], central[3];
        aux_stress_divergence<3>(
          unit, curve, x, projection, xl, angle, analytic);
        reference(unit, curve, x, angle, 1e-6 * r, central);
        for (unsigned int m = 0; m < 3; ++m)
          {
            // Relative to the size of the auxiliary stress gradient along a
            // front of unit curvature, sqrt(1 / r): a straight front gives 0.
            const double scale = 1 / std::sqrt(r);
            differences.push_back((analytic[m] - central[m]).norm() / scale);
            largest = std::max(largest, central[m].norm() / scale);
          }
      }
    std::sort(differences.begin(), differences.end());
    const double median = differences[differences.size() / 2];
    logfile << name << ": " << differences.size() / 3
            << " points (fallback feet skipped: " << n_fallback
            << "), largest |div| sqrt(r) " << std::setprecision(2) << std::fixed
            << largest
            << "; median difference < 1e-7: " << (median < 1e-7 ? "yes" : "no")
            << "; every point < 1e-5: "
            << (differences.back() < 1e-5 ? "yes" : "no") << '\n';
  }
} // namespace

int
main()
{
  // The unit circle in z = 0, 64 segments: e1 turns along s, e2 does not.
  compare(
    "circle",
    front([](const double t) { return Point<3>(std::cos(t), std::sin(t), 0); },
          [](const double) {
            return Tensor<1, 3>({0, 0, 1});
          },
          64));
  // An ellipse tilted about x and waving out of its plane, normals tilting
  // with it: e2 turns along s as well (twist).
  compare(
    "wavy tilted ellipse",
    front(
      [](const double t) {
        const double z = 0.15 * std::sin(3 * t);
        return Point<3>(1.2 * std::cos(t),
                        0.9 * std::sin(t) * std::cos(0.3) - z * std::sin(0.3),
                        0.9 * std::sin(t) * std::sin(0.3) + z * std::cos(0.3));
      },
      [](const double t) {
        const Tensor<1, 3> n({0.2 * std::cos(2 * t), 0.1 * std::sin(t), 1});
        return Tensor<1, 3>({n[0],
                             n[1] * std::cos(0.3) - n[2] * std::sin(0.3),
                             n[1] * std::sin(0.3) + n[2] * std::cos(0.3)});
      },
      96));
  // A straight front (an open line, x in [-2, 2]): no divergence at all.
  {
    std::vector<FrontPoint<3>> line(9);
    for (unsigned int i = 0; i < line.size(); ++i)
      {
        line[i].position = Point<3>(-2 + 0.5 * i, 0, 0);
        line[i].s        = 0.5 * i;
        line[i].e1       = Tensor<1, 3>({0, 1, 0});
        line[i].e2       = Tensor<1, 3>({0, 0, 1});
        line[i].e3       = Tensor<1, 3>({1, 0, 0});
      }
    WilliamsField unit;
    unit.mu    = 1 / 2.6;
    unit.kappa = 1.8;
    const FrontCurve<3> curve(line, 0.2);
    double              largest = 0;
    for (const Point<3> &x : {Point<3>(0.1, 0.2, 0.1),
                              Point<3>(-1.3, -0.3, 0.01),
                              Point<3>(1.7, 0.05, -0.2)})
      {
        const auto         p  = curve.project(x);
        const Tensor<1, 3> xl = p.R * (x - p.foot);
        Tensor<1, 3>       d[3];
        aux_stress_divergence<3>(
          unit, curve, x, p, xl, std::atan2(xl[1], xl[0]), d);
        for (const auto &v : d)
          largest = std::max(largest, v.norm());
      }
    logfile << "straight front: |div| < 1e-9: "
            << (largest < 1e-9 ? "yes" : "no") << '\n';
  }
}
