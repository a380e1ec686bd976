// Requirement: the K error estimate's recovery sets the singular part
// aside only where the foot on the front is continuous (issue 16; doc/
// verification.md, "The singular part's cut-off along a curved front").
// KErrorEstimator::singular_cutoff() on the unit circle of 64 segments
// (the penny's front), with r_sup = 0.75 (the k tolerance penny's crown):
// - along a straight front (h_s = 1) it is the distance's cut-off alone: 1
//   up to r_sup, the smooth step's 1/2 at 1.5 r_sup, 0 from 2 r_sup on;
// - outside the circle (convex side) and straight above the front it is 1
//   at 0.5 from the front;
// - inside (concave side) it falls with h_s: 1 at 0.2 from the front, 0
//   past half the radius of curvature (0.55, 0.7), and 0 on the
//   penny's axis 0.3 to 0.9 above and below the centre, where the foot is
//   any point of the front and where, before, the estimate of K's fourth
//   harmonic came from (the distance's cut-off alone gives 0.13 to 0.70
//   there: the check fails without the h_s factor);
// - walked from the front to the centre in 2000 steps it changes by less
//   than 0.01 per step (no jump).

#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/k_error_estimator.h>

#include "unit_circle_front.h"
#include <cmath>
#include <fstream>
#include <iomanip>
#include <vector>

using namespace xcrack;

std::ofstream logfile("output");

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "NO";
  }
} // namespace

int
main()
{
  const double r_sup = 0.75;
  const auto   points =
    unit_circle_front(64, 2 * M_PI, true); // (the curve refers to them)
  const FrontCurve<3> curve(points, 0.5 * r_sup);
  // The estimator's cut-off at x, as KErrorEstimator::near_fronts() reads
  // it.
  const auto chi = [&](const Point<3> &x) {
    const auto         projection = curve.project(x);
    const Tensor<1, 3> xl         = projection.R * (x - projection.foot);
    return KErrorEstimator<3>::singular_cutoff(x.distance(projection.foot),
                                               r_sup,
                                               projection.jacobian_s(xl));
  };
  const auto cutoff = &KErrorEstimator<3>::singular_cutoff;

  logfile << "straight front (h_s = 1): 1 at 0.5 r_sup and at r_sup: "
          << yes(cutoff(0.5 * r_sup, r_sup, 1) == 1 &&
                 cutoff(r_sup, r_sup, 1) == 1)
          << "; 1/2 at 1.5 r_sup: "
          << yes(std::abs(cutoff(1.5 * r_sup, r_sup, 1) - 0.5) < 1e-12)
          << "; 0 at 2 r_sup and beyond: "
          << yes(cutoff(2 * r_sup, r_sup, 1) == 0 &&
                 cutoff(3 * r_sup, r_sup, 1) == 0)
          << '\n';

  // A point at angle 0.3 of the front, moved along (cos, sin, 0) to
  // radius rho and up by z.
  const auto at = [](const double rho, const double z) {
    return Point<3>(rho * std::cos(0.3), rho * std::sin(0.3), z);
  };
  logfile << "convex side, 0.5 from the front: 1: "
          << yes(std::abs(chi(at(1.5, 0)) - 1) < 1e-12)
          << "; 0.5 straight above the front: 1: "
          << yes(std::abs(chi(at(1, 0.5)) - 1) < 1e-12) << '\n';

  logfile << "concave side: 1 at 0.2 from the front: "
          << yes(std::abs(chi(at(0.8, 0)) - 1) < 1e-12)
          << "; 0 at 0.55 and at 0.7: "
          << yes(chi(at(0.45, 0)) == 0 && chi(at(0.3, 0)) == 0) << '\n';

  bool   axis_zero     = true;
  double distance_only = 1;
  for (const double z : {-0.9, -0.6, -0.3, 0.3, 0.6, 0.9})
    {
      const Point<3> x(0.01, 0.02, z);
      axis_zero             = axis_zero && chi(x) == 0;
      const auto projection = curve.project(x);
      distance_only         = std::min(distance_only,
                               KErrorEstimator<3>::singular_cutoff(
                                 x.distance(projection.foot), r_sup, 1));
    }
  logfile << "the penny's axis, 0.3 to 0.9 above and below its centre: 0: "
          << yes(axis_zero)
          << " (the distance's cut-off alone: at least 0.05 there: "
          << yes(distance_only > 0.05) << ")\n";

  const unsigned int n_steps = 2000;
  double             jump    = 0;
  double             last    = chi(at(1, 0));
  for (unsigned int i = 1; i <= n_steps; ++i)
    {
      const double value = chi(at(1 - double(i) / n_steps, 0));
      jump               = std::max(jump, std::abs(value - last));
      last               = value;
    }
  logfile << "walked from the front to the centre in " << n_steps
          << " steps: changes below 0.01 per step: " << yes(jump < 0.01)
          << '\n';
  return 0;
}
