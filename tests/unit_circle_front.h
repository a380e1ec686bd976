#ifndef xcrack_tests_unit_circle_front_h
#define xcrack_tests_unit_circle_front_h

#include <xcrack/crack/crack_geometry.h>

#include <cmath>
#include <vector>

/// Points of the unit circle z = 0 clockwise (e1 = e2 x e3 points outwards,
/// as on a crack's front), the last repeating the first when @p closed;
/// @p n_segments over the angle @p span. Shared by the tests of the front's
/// geometry.
inline std::vector<xcrack::FrontPoint<3>>
unit_circle_front(const unsigned int n_segments,
                  const double       span,
                  const bool         closed)
{
  using namespace dealii;
  std::vector<xcrack::FrontPoint<3>> points(n_segments + 1);
  for (unsigned int i = 0; i <= n_segments; ++i)
    {
      const double t = -span * (closed && i == n_segments ? 0 : i) / n_segments;
      xcrack::FrontPoint<3> &p = points[i];
      p.position               = Point<3>(std::cos(t), std::sin(t), 0);
      p.e1                     = Tensor<1, 3>({std::cos(t), std::sin(t), 0});
      p.e2                     = Tensor<1, 3>({0, 0, 1});
      p.e3                     = Tensor<1, 3>({std::sin(t), -std::cos(t), 0});
      if (i > 0)
        p.s =
          points[i - 1].s + points[i - 1].position.distance(points[i].position);
    }
  return points;
}

#endif
