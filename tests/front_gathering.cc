// Requirement: the partition of unity along crack fronts that DOF gathering
// ties the branch DoFs with (FrontGathering):
// - a point projects on the nearest front with its abscissa s and distance
//   (closed front: s in [0, length); 2D tip: s = 0, distance to the tip);
// - the masters' target abscissae are about the spacing apart (at least two
//   on an open front, including its ends; at least three around a closed
//   one; one per 2D tip);
// - the weights at any point are the P1 hats of the masters' abscissae:
//   nonnegative, adding up to one, equal to one at a master (so a master's
//   constraint would be the identity), linear in between, across s = 0 on a
//   closed front, constant beyond the ends of an open one.

#include <deal.II/base/numbers.h>

#include <xcrack/xfem/front_gathering.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile;

template <int dim>
void
print_weights(const FrontGathering<dim>                    &gathering,
              const typename FrontGathering<dim>::Location &where)
{
  double sum = 0;
  logfile << "  front " << where.front << " s " << where.s << " distance "
          << where.distance << ": weights";
  for (const auto &[k, w] : gathering.weights(where))
    {
      logfile << " (" << k << ", " << w << ")";
      sum += w;
      AssertThrow(w >= 0 && w <= 1, ExcMessage("A weight outside [0, 1]."));
    }
  logfile << ", sum " << sum << std::endl;
  AssertThrow(std::abs(sum - 1) < 1e-14,
              ExcMessage("Weights do not add to 1."));
}



/// A circle of radius 1 in the plane z = 0 (closed: the last point repeats
/// the first) and a straight front along z from z = -1 to z = 1 at x = 3.
std::vector<std::vector<FrontPoint<3>>>
fronts_3d()
{
  std::vector<std::vector<FrontPoint<3>>> fronts(2);
  const unsigned int                      n = 64;
  for (unsigned int i = 0; i <= n; ++i)
    {
      const double  phi = 2 * numbers::PI * (i % n) / n;
      FrontPoint<3> p;
      p.position = Point<3>(std::cos(phi), std::sin(phi), 0);
      fronts[0].push_back(p);
    }
  for (unsigned int i = 0; i <= 8; ++i)
    {
      FrontPoint<3> p;
      p.position = Point<3>(3, 0, -1 + 0.25 * i);
      fronts[1].push_back(p);
    }
  for (auto &front : fronts)
    for (unsigned int i = 1; i < front.size(); ++i)
      front[i].s =
        front[i - 1].s + front[i].position.distance(front[i - 1].position);
  return fronts;
}



void
check_3d()
{
  logfile << "3D: a closed circle (radius 1, 64 chords) and an open line"
          << std::endl;
  FrontGathering<3> gathering(fronts_3d());
  AssertThrow(gathering.closed(0) && !gathering.closed(1),
              ExcMessage("Closed/open fronts not recognised."));
  const double length = 64 * 2 * std::sin(numbers::PI / 64);
  for (const double spacing : {1.0, 10.0})
    for (unsigned int f = 0; f < 2; ++f)
      {
        const auto t = gathering.targets(f, spacing);
        logfile << "  spacing " << spacing << ", front " << f << ": "
                << t.size() << " targets, first " << t.front() << ", last "
                << t.back() << std::endl;
      }

  // Projections: a point above the circle at angle pi/4 (at distance 0.5
  // in the plane and 0.2 above it), one next to the line, one beyond its
  // upper end, the centre of a chord ending at the closing point.
  const double phi = numbers::PI / 4;
  const auto   a =
    gathering.locate(Point<3>(1.5 * std::cos(phi), 1.5 * std::sin(phi), 0.2));
  logfile << "  above the circle at pi/4: front " << a.front << ", s/length "
          << a.s / length << ", distance " << a.distance << std::endl;
  AssertThrow(a.front == 0 && std::abs(a.s / length - 0.125) < 1e-12 &&
                std::abs(a.distance - std::hypot(0.5, 0.2)) < 1e-3,
              ExcMessage("Wrong projection on the circle."));
  const auto b = gathering.locate(Point<3>(3.1, 0.1, 0.3));
  const auto c = gathering.locate(Point<3>(3, 0, 1.5));
  logfile << "  next to the line: front " << b.front << ", s " << b.s
          << ", distance " << b.distance << "; beyond its end: s " << c.s
          << ", distance " << c.distance << std::endl;
  const auto d =
    gathering.locate(Point<3>(0.5 * (1 + std::cos(2 * numbers::PI * 63 / 64)),
                              0.5 * std::sin(2 * numbers::PI * 63 / 64),
                              0));
  logfile << "  on the closing chord: s/length " << d.s / length << std::endl;
  AssertThrow(d.s < length && d.s > 0.98 * length,
              ExcMessage("The closing chord is not at the end of [0, L)."));

  // Masters at s = 0.1, 2, 4 (circle) and 0.5, 1.5 (line).
  gathering.set_nodes(0, {0.1, 2., 4.});
  gathering.set_nodes(1, {0.5, 1.5});
  logfile << "weights, masters at s = 0.1, 2, 4 (circle), 0.5, 1.5 (line)"
          << std::endl;
  for (const double s : {0.1, 1.05, 2., 3.5, 4., 5., 6.2, 0.05})
    print_weights(gathering, {0, s, 0.});
  for (const double s : {0., 0.5, 1., 1.5, 2.})
    print_weights(gathering, {1, s, 0.});
  const auto w = gathering.weights({0, 5., 0.});
  // Across s = 0: from 4 to 0.1 + length.
  const double t = (5. - 4.) / (0.1 + length - 4.);
  AssertThrow(w.size() == 2 && w[0].first == 2 && w[1].first == 0 &&
                std::abs(w[1].second - t) < 1e-14,
              ExcMessage("Wrong weights across s = 0."));
}



void
check_2d()
{
  logfile << "2D: two tips" << std::endl;
  std::vector<std::vector<FrontPoint<2>>> tips(2);
  tips[0].resize(1);
  tips[1].resize(1);
  tips[0][0].position = Point<2>(-1, 0);
  tips[1][0].position = Point<2>(1, 0.5);
  FrontGathering<2> gathering(tips);
  for (unsigned int f = 0; f < 2; ++f)
    {
      AssertThrow(gathering.targets(f, 0.1).size() == 1,
                  ExcMessage("A 2D tip has one master."));
      gathering.set_nodes(f, {0.});
    }
  const auto where = gathering.locate(Point<2>(0.8, 0.3));
  AssertThrow(where.front == 1, ExcMessage("Not the nearest tip."));
  print_weights(gathering, where);
}



int
main()
{
  logfile.open("output");
  logfile << std::setprecision(6);
  check_3d();
  check_2d();
  logfile << "OK" << std::endl;
}
