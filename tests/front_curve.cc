// Requirement: the foot of a point on a 3D front (FrontCurve::project) is
// continuous along the front, where the nearest point of the polyline jumps
// across the bisector planes of its vertices (doc/verification.md, "The
// divergence term and the foot on the front"). On a unit circle of 64
// segments, points walked along arcs inside it (the concave side, in and
// off the crack plane) and outside: the largest change of the foot's
// abscissa between neighbouring points over the typical one stays near 1
// for the normal-plane foot, while the nearest point's is 7 to 13 inside;
// the foot lies in its normal plane, (x - p(s)) . e3(s) = 0 to round-off.
// Farther than half the radius of curvature inside, the nearest point stays
// (its distance is the polyline's); beyond an end of an open front the
// projection says at_end.

#include <xcrack/fracture/front_curve.h>

#include "unit_circle_front.h"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <vector>

using namespace xcrack;

std::ofstream logfile("output");

namespace
{
  /// Abscissa of the nearest point of the polyline to @p x, by brute force.
  double
  nearest_abscissa(const std::vector<FrontPoint<3>> &points, const Point<3> &x)
  {
    double best = 1e300, s = 0;
    for (unsigned int i = 0; i + 1 < points.size(); ++i)
      {
        const Tensor<1, 3> ab = points[i + 1].position - points[i].position;
        const double       t =
          std::clamp(((x - points[i].position) * ab) / (ab * ab), 0., 1.);
        const double d = (x - (points[i].position + t * ab)).norm();
        if (d < best)
          {
            best = d;
            s    = points[i].s + t * (points[i + 1].s - points[i].s);
          }
      }
    return s;
  }
} // namespace

int
main()
{
  const auto          points = unit_circle_front(64, 2 * M_PI, true);
  const FrontCurve<3> curve(points, 0.25);
  logfile << "closed front: " << curve.closed << ", length " << std::fixed
          << std::setprecision(6) << curve.length << '\n';

  const unsigned int n_walk = 4000;
  // The change of s between neighbours on the front itself.
  const double typical = curve.length / n_walk;
  for (const auto &[radius, height] : std::vector<std::pair<double, double>>{
         {0.8, 0}, {0.9, 0.05}, {1.2, 0.1}})
    {
      double       largest_foot = 0, largest_nearest = 0, residual = 0;
      double       s_old = 0, nearest_old = 0;
      const double pitch = 0.37; // off the vertices' angles
      for (unsigned int k = 0; k <= n_walk; ++k)
        {
          const double   t = -(pitch + 2 * M_PI * k / n_walk);
          const Point<3> x(radius * std::cos(t), radius * std::sin(t), height);
          const auto     projection = curve.project(x);
          const double   nearest    = nearest_abscissa(points, x);
          const Tensor<1, 3> e3     = curve.at(projection.s).e3;
          residual = std::max(residual, std::abs((x - projection.foot) * e3));
          if (k > 0)
            {
              // Changes modulo the length: the walk crosses s = 0.
              const auto change = [&](const double a, const double b) {
                const double d = std::abs(a - b);
                return std::min(d, curve.length - d);
              };
              largest_foot =
                std::max(largest_foot, change(projection.s, s_old));
              largest_nearest =
                std::max(largest_nearest, change(nearest, nearest_old));
            }
          s_old       = projection.s;
          nearest_old = nearest;
        }
      logfile << "arc r = " << std::setprecision(2) << radius
              << ", z = " << height
              << ": largest change of s / typical, normal-plane foot "
              << std::setprecision(1) << largest_foot / typical
              << ", nearest point " << std::setprecision(0)
              << largest_nearest / typical << "; continuous (< 1.5): "
              << (largest_foot / typical < 1.5 ? "yes" : "no")
              << "; |(x - p(s)) . e3(s)| < 1e-12: "
              << (residual < 1e-12 ? "yes" : "no") << '\n';
    }

  // Inside half the radius of curvature (h_s = 1 - 0.7 < 1/2): the nearest
  // point stays.
  {
    const Point<3> x(0.3 * std::cos(-1.0), 0.3 * std::sin(-1.0), 0.02);
    const auto     projection = curve.project(x);
    const double   nearest    = nearest_abscissa(points, x);
    logfile << "point at r = 0.3: foot is the nearest point: "
            << (std::abs(projection.s - nearest) < 1e-12 ? "yes" : "no")
            << '\n';
  }

  // An open front (a half circle): a point in its normal planes and points
  // beyond its ends.
  {
    const auto          half = unit_circle_front(32, M_PI, false);
    const FrontCurve<3> open(half, 0.25);
    const Point<3>      inside(0.9 * std::cos(-1.0), 0.9 * std::sin(-1.0), 0);
    const auto          a = open.project(inside);
    logfile << "open front: closed " << open.closed << "; r = 0.9 inside: "
            << "at_end " << a.at_end << ", |(x - p(s)) . e3(s)| < 1e-12: "
            << (std::abs((inside - a.foot) * open.at(a.s).e3) < 1e-12 ? "yes" :
                                                                        "no")
            << '\n';
    for (const Point<3> &beyond : {Point<3>(1.0, 0.3, 0), Point<3>(-1, 0.3, 0)})
      {
        const auto b = open.project(beyond);
        logfile << "  beyond an end at " << std::setprecision(1) << beyond
                << ": at_end " << b.at_end << ", s = " << std::setprecision(4)
                << b.s << '\n';
      }
  }
}
