// Requirement: a crack kept as a set of facets (FacetSurface, what the
// `crack mesh` level-set update grows) gives the level sets of the surface
// it draws, with facets that share no vertices:
// - a 2D crack that turned by 120 degrees (along +x from (0, 0) to (3, 0),
//   then to the tip (3 - 0.5, sqrt(0.75)) = (2.5, 0.866)): lsn is the
//   signed distance to the polyline where the nearest point is inside a
//   segment, and has the right side everywhere but beyond the ends (no
//   spurious zero on the convex side of the turn); lst < 0 wherever the
//   nearest point of the polyline is not the tip (the plane through the
//   tip normal to its direction cuts the first segment at x = 1: lst =
//   0.313 at (0.2, -0.1) by that rule), lst = (p - tip) . e1 ahead of the
//   tip;
// - a 3D square crack [0, 1]^2 at z = 0 as four triangles from two
//   "cells" (one split along each diagonal: no shared edges inside), its
//   front the edge x = 1 (e1 = +x): lsn = z, lst = x - 1 for x > 1 and
//   -(1 - x) for x < 1 at random points above the square, and the
//   tangent extension (lsn = z) beyond the front;
// - the surface written to VTU and read back through boost serialization
//   gives the same level sets.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <xcrack/crack/facet_surface.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <tuple>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}



void
turned_2d()
{
  using Facet = FacetSurface<2>::Facet;
  FacetSurface<2> surface;
  const Point<2>  a(0, 0), b(3, 0), tip(2.5, std::sqrt(0.75));
  // The lsn > 0 side: +y along the first segment, the same side (towards
  // the inside of the turn) along the second.
  const Tensor<1, 2> t = (tip - b) / (tip - b).norm();
  Tensor<1, 2>       n2;
  n2[0] = -t[1];
  n2[1] = t[0];
  // Split the first segment in two pieces, as two cells would.
  surface.add({Facet{{{a, Point<2>(1.5, 0)}}, Tensor<1, 2>({0, 1}), 0},
               Facet{{{Point<2>(1.5, 0), b}}, Tensor<1, 2>({0, 1}), 0},
               Facet{{{b, tip}}, n2, 1}});
  surface.set_fronts({{{tip, t}}});

  // The exact nearest point of the polyline: its distance, and the side
  // where it is decided (-1 or 1), 0 where the nearest point is an end.
  const auto exact = [&](const Point<2> &p) {
    double best = 1e100, side = 0;
    bool   inside = false;
    for (const auto &[x, y, n] : {std::make_tuple(a, b, Tensor<1, 2>({0, 1})),
                                  std::make_tuple(b, tip, n2)})
      {
        const Tensor<1, 2> e = y - x;
        const double w = std::clamp((p - x) * e / e.norm_square(), 0., 1.);
        const double d = p.distance(x + w * e);
        if (d < best - 1e-12)
          {
            best   = d;
            inside = (w > 0 && w < 1);
            // Inside a segment its normal decides; at the turn's corner
            // the point is on its convex (lsn < 0) side; at the ends none.
            side = (w > 0 && w < 1 ? ((p - x) * n > 0 ? 1. : -1.) :
                    (x == b && w == 0) || (y == b && w == 1) ? -1. :
                                                               0.);
          }
      }
    return std::make_tuple(best, side, inside);
  };
  double       error      = 0;
  unsigned int wrong_side = 0, behind_positive = 0, n = 0;
  for (int i = -20; i <= 80; ++i)
    for (int j = -20; j <= 30; ++j)
      {
        const Point<2> p(0.05 * i + 0.013, 0.05 * j + 0.007);
        const double   value           = surface.lsn(p);
        const auto [d, side, c_inside] = exact(p);
        if (side != 0)
          {
            // At the corner lsn is the distance to a tangent line.
            if (c_inside)
              error = std::max(error, std::abs(value - side * d));
            wrong_side += (value * side <= 0);
            ++n;
          }
        const Point<2> c = surface.nearest(p).first;
        if (c.distance(tip) > 1e-9 && surface.lst(p) >= 0)
          ++behind_positive;
      }
  logfile << "2D, 120-degree turn: " << n
          << " points nearest to the inside or the corner, |lsn - signed "
             "distance| <= 1e-12 inside: "
          << yes(error <= 1e-12) << std::endl;
  logfile << "  points on the wrong side: " << wrong_side << std::endl;
  logfile << "  points behind the tip with lst >= 0: " << behind_positive
          << std::endl;
  const Point<2> below(0.2, -0.1);
  logfile << std::setprecision(6) << "  at (0.2, -0.1): lsn "
          << surface.lsn(below) << ", lst " << surface.lst(below)
          << " (plane through the tip: " << (below - tip) * t << ")"
          << std::endl;
  const Point<2> ahead = tip + 0.3 * t + 0.1 * n2;
  logfile << "  ahead of the tip: lsn " << surface.lsn(ahead) << " (0.1), lst "
          << surface.lst(ahead) << " (0.3)" << std::endl;
}



void
square_3d()
{
  using Facet = FacetSurface<3>::Facet;
  FacetSurface<3>    surface;
  const Tensor<1, 3> up({0, 0, 1});
  const Point<3>     p00(0, 0, 0), p10(0.5, 0, 0), p20(1, 0, 0), p01(0, 1, 0),
    p11(0.5, 1, 0), p21(1, 1, 0);
  // Two cells [0, 0.5] x [0, 1] and [0.5, 1] x [0, 1], split along
  // different diagonals; normals up, corners in either order.
  surface.add({Facet{{{p00, p10, p11}}, up, 0},
               Facet{{{p00, p11, p01}}, up, 0},
               Facet{{{p10, p21, p11}}, up, 0},
               Facet{{{p10, p20, p21}}, up, 1}});
  const Tensor<1, 3> e1({1, 0, 0});
  surface.set_fronts({{{p20, e1}, {p21, e1}}});

  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> u(-0.5, 1.5), w(-0.3, 0.3);
  double                                 lsn_error = 0, lst_error = 0;
  for (unsigned int k = 0; k < 4000; ++k)
    {
      const Point<3> p(u(rng), std::clamp(u(rng), 0., 1.), w(rng));
      // lsn: z over the square and beyond the front (the tangent
      // extension); lst: the distance to x = 1 in the surface.
      if (p[0] >= 0)
        lsn_error = std::max(lsn_error, std::abs(surface.lsn(p) - p[2]));
      if (p[0] >= 0)
        lst_error = std::max(lst_error, std::abs(surface.lst(p) - (p[0] - 1)));
    }
  logfile << "3D square of 4 triangles: max |lsn - z| = " << std::scientific
          << std::setprecision(1) << lsn_error
          << ", max |lst - (x - 1)| = " << lst_error << std::defaultfloat
          << std::endl;

  // Through a checkpoint: the same level sets.
  const std::vector<char> bytes = Utilities::pack(surface, false);
  const auto     copy = Utilities::unpack<FacetSurface<3>>(bytes, false);
  const Point<3> p(1.2, 0.4, -0.1), q(0.3, 0.7, 0.2);
  logfile << "  packed and unpacked: " << copy.facets().size()
          << " facets, same level sets: "
          << yes(copy.lsn(p) == surface.lsn(p) &&
                 copy.lst(p) == surface.lst(p) &&
                 copy.lsn(q) == surface.lsn(q) && copy.lst(q) == surface.lst(q))
          << std::endl;
  std::ostringstream vtu_text;
  surface.write_vtu(vtu_text);
  std::istringstream vtu(vtu_text.str());
  std::string        line;
  std::getline(vtu, line);
  std::getline(vtu, line);
  logfile << "  written: " << line << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  turned_2d();
  square_3d();
}
