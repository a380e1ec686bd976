// Requirement: a crack given as a surface mesh (MeshCrack) has the level
// sets of the shape it samples, and its front is the part of its boundary
// inside the body:
// - a half-plane crack meshed beyond the body (quadrilaterals, Gmsh 2.2):
//   lsn and lst equal the analytic ones to round-off inside the body, the
//   edges outside or on the body's surface are mouths, the front is the
//   straight line inside, its frame that of doc/benchmarks.md;
// - a penny triangulated with 64 sectors (Gmsh 4.1, and the same mesh as
//   legacy VTK): lsn exact (planar) and lst within the chord error
//   a (1 - cos(pi/64)) of the circle's; a closed front of 64 edges;
//   the band leaves the sides right far away;
// - a kinked 2D polyline: lsn and lst by hand, one tip inside the body;
// - bad files get messages naming the entry and the culprit.

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/mesh_crack.h>
#include <xcrack/input_error.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

/// Largest level-set differences between two cracks at random points of
/// the cube [-1,1]^3 (or square).
template <int dim>
std::pair<double, double>
compare(const CrackGeometry<dim> &a,
        const CrackGeometry<dim> &b,
        const double              size = 1)
{
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> coordinate(-size, size);
  double                                 dn = 0, dt = 0;
  for (unsigned int i = 0; i < 2000; ++i)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = coordinate(rng);
      dn = std::max(dn, std::abs(a.lsn(p) - b.lsn(p)));
      dt = std::max(dt, std::abs(a.lst(p) - b.lst(p)));
    }
  return {dn, dt};
}

void
check_half_plane()
{
  logfile << "Half plane {y = 0, x < 0} meshed on [-1.5, 0] x [-1.5, 1.5]"
          << std::endl;
  // Quadrilaterals of 0.25 in the plane y = 0; node (i, k) at
  // x = -1.5 + 0.25 i, z = -1.5 + 0.25 k. Ordered so that the normal is +y.
  {
    std::ofstream out("half_plane.msh");
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << 7 * 13 << '\n';
    for (unsigned int k = 0; k < 13; ++k)
      for (unsigned int i = 0; i < 7; ++i)
        out << 1 + i + 7 * k << ' ' << -1.5 + 0.25 * i << " 0 "
            << -1.5 + 0.25 * k << '\n';
    out << "$EndNodes\n$Elements\n" << 6 * 12 << '\n';
    unsigned int id = 1;
    for (unsigned int k = 0; k < 12; ++k)
      for (unsigned int i = 0; i < 6; ++i)
        {
          const unsigned int n = 1 + i + 7 * k;
          // (x, z) counter-clockwise seen from +y is clockwise in (x, z):
          // corners n, n + 7, n + 8, n + 1 give the normal z x x = +y.
          out << id++ << " 3 2 0 1 " << n << ' ' << n + 7 << ' ' << n + 8 << ' '
              << n + 1 << '\n';
        }
    out << "$EndElements\n";
  }
  MeshCrack<3>     crack("half_plane.msh", "Crack 1/File name", 0);
  Triangulation<3> mesh;
  GridGenerator::hyper_cube(mesh, -1, 1);
  crack.locate_in(mesh);
  const HalfPlaneCrack exact(Point<3>(),
                             Tensor<1, 3>({0, 1, 0}),
                             Tensor<1, 3>({1, 0, 0}));
  const auto [dn, dt] = compare<3>(crack, exact);
  logfile << crack.n_facets() << " triangles, " << crack.n_front_elements()
          << " front edges (8 expected: |z| < 1 on x = 0)" << std::endl
          << "lsn, lst equal the half plane's to 1e-14: "
          << yes(dn < 1e-14 && dt < 1e-14) << std::endl;
  const auto front = crack.front(0, BoundingBox<3>());
  double     frame = 0;
  for (const auto &p : front)
    frame = std::max({frame,
                      std::abs(p.position[0]) + std::abs(p.position[1]),
                      (p.e1 - Tensor<1, 3>({1, 0, 0})).norm(),
                      (p.e2 - Tensor<1, 3>({0, 1, 0})).norm(),
                      (p.e3 - Tensor<1, 3>({0, 0, 1})).norm()});
  logfile << front.size() << " front points from z = " << front[0].position[2]
          << " to " << front.back().position[2] << ", s = " << front.back().s
          << ", frame (1,0,0), (0,1,0), (0,0,1): " << yes(frame < 1e-14)
          << std::endl;
}

void
check_penny()
{
  logfile << "Penny a = 0.6 in z = 0.1, 64 sectors, 8 rings" << std::endl;
  const double       a = 0.6, z = 0.1;
  const unsigned int n_sectors = 64, n_rings = 8;
  // Nodes: the centre, then ring r (1..8) sector s at radius a r / 8.
  std::vector<Point<3>>                  nodes{Point<3>(0, 0, z)};
  std::vector<std::vector<unsigned int>> cells;
  for (unsigned int r = 1; r <= n_rings; ++r)
    for (unsigned int s = 0; s < n_sectors; ++s)
      {
        const double phi = 2 * numbers::PI * s / n_sectors;
        nodes.emplace_back(a * r / n_rings * std::cos(phi),
                           a * r / n_rings * std::sin(phi),
                           z);
      }
  const auto node = [&](unsigned int r, unsigned int s) {
    return r == 0 ? 0u : 1 + (r - 1) * n_sectors + s % n_sectors;
  };
  for (unsigned int s = 0; s < n_sectors; ++s)
    {
      cells.push_back({node(0, 0), node(1, s), node(1, s + 1)});
      for (unsigned int r = 1; r < n_rings; ++r)
        cells.push_back(
          {node(r, s), node(r + 1, s), node(r + 1, s + 1), node(r, s + 1)});
    }
  {
    // Gmsh 4.1: one node block, one block per element type.
    std::ofstream out("penny.msh");
    out << std::setprecision(17) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
        << "$Entities\n0 0 1 0\n1 -1 -1 -1 1 1 1 0 0\n$EndEntities\n"
        << "$Nodes\n1 " << nodes.size() << " 1 " << nodes.size() << "\n2 1 0 "
        << nodes.size() << '\n';
    for (unsigned int i = 0; i < nodes.size(); ++i)
      out << i + 1 << '\n';
    for (const auto &p : nodes)
      out << p << '\n';
    out << "$EndNodes\n$Elements\n2 " << cells.size() << " 1 " << cells.size()
        << "\n2 1 2 " << n_sectors << '\n';
    unsigned int id = 1;
    for (const auto &c : cells)
      if (c.size() == 3)
        out << id++ << ' ' << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1
            << '\n';
    out << "2 1 3 " << cells.size() - n_sectors << '\n';
    for (const auto &c : cells)
      if (c.size() == 4)
        out << id++ << ' ' << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1
            << ' ' << c[3] + 1 << '\n';
    out << "$EndElements\n";
  }
  {
    std::ofstream out("penny.vtk");
    out << std::setprecision(17)
        << "# vtk DataFile Version 4.2\npenny\nASCII\nDATASET POLYDATA\n"
        << "POINTS " << nodes.size() << " double\n";
    for (const auto &p : nodes)
      out << p << '\n';
    out << "POLYGONS " << cells.size() << ' ' << 4 * cells.size() << '\n';
    for (const auto &c : cells)
      {
        out << c.size();
        for (const unsigned int v : c)
          out << ' ' << v;
        out << '\n';
      }
  }
  Triangulation<3> mesh;
  GridGenerator::hyper_cube(mesh, -1, 1);
  const EllipticalCrack exact(
    Point<3>(0, 0, z), Tensor<1, 3>({0, 0, 1}), Tensor<1, 3>({1, 0, 0}), a, a);
  const double chord = a * (1 - std::cos(numbers::PI / n_sectors));
  for (const std::string file : {"penny.msh", "penny.vtk"})
    {
      MeshCrack<3> crack(file, "Crack 1/File name", 0);
      crack.locate_in(mesh);
      const auto [dn, dt] = compare<3>(crack, exact);
      const auto front    = crack.front(0, BoundingBox<3>());
      logfile << file << ": " << crack.n_facets() << " triangles, "
              << crack.n_front_elements() << " front edges, " << front.size()
              << " front points, closed "
              << yes(front[0].position.distance(front.back().position) == 0)
              << ", length / (2 pi a) " << std::setprecision(6)
              << front.back().s / (2 * numbers::PI * a) << std::endl
              << "  lsn exact to 1e-14 " << yes(dn < 1e-14)
              << ", lst within the chord error " << std::setprecision(3)
              << chord << ": " << yes(dt <= chord * (1 + 1e-12)) << std::endl;
    }

  // The band: beyond 0.2 of the crack's box only the sides are computed.
  MeshCrack<3> full("penny.msh", "Crack 1/File name", 0);
  MeshCrack<3> banded("penny.msh", "Crack 1/File name", 0.2);
  full.locate_in(mesh);
  banded.locate_in(mesh);
  bool                                   sides = true, same = true;
  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (unsigned int i = 0; i < 2000; ++i)
    {
      const Point<3> p(coordinate(rng), coordinate(rng), coordinate(rng));
      const double   ox = std::max(std::abs(p[0]) - a, 0.),
                   oy   = std::max(std::abs(p[1]) - a, 0.);
      const bool near =
        std::sqrt(ox * ox + oy * oy + (p[2] - z) * (p[2] - z)) < 0.2;
      sides = sides && (banded.lsn(p) > 0) == (p[2] > z);
      if (near)
        same =
          same && banded.lsn(p) == full.lsn(p) && banded.lst(p) == full.lst(p);
    }
  logfile << "Band 0.2: sides right everywhere " << yes(sides)
          << ", values as without band inside it " << yes(same) << std::endl;
}

void
check_polyline_2d()
{
  logfile << "2D polyline (-1.5, 0) - (0, 0) - (0.3, 0.3)" << std::endl;
  {
    std::ofstream out("kinked.msh");
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n"
        << "1 -1.5 0 0\n2 0 0 0\n3 0.3 0.3 0\n$EndNodes\n"
        << "$Elements\n3\n1 15 2 0 1 1\n2 1 2 0 1 1 2\n3 1 2 0 1 2 3\n"
        << "$EndElements\n";
  }
  MeshCrack<2>     crack("kinked.msh", "Crack 1/File name", 0);
  Triangulation<2> mesh;
  GridGenerator::hyper_cube(mesh, -1, 1);
  crack.locate_in(mesh);
  const auto tips = crack.front(0, BoundingBox<2>());
  logfile << tips.size() << " tip at (" << tips[0].position << "), e1 = ("
          << tips[0].e1 << ")" << std::endl;
  // On the first segment: lsn = y. Ahead of the tip along the last
  // segment's direction: lst = distance, lsn = 0. Above the kink: the
  // vertex normal (the mean of the two segments') decides.
  const double   c = std::sqrt(0.5);
  const Point<2> ahead(0.3 + 0.2 * c, 0.3 + 0.2 * c);
  logfile << std::setprecision(10)
          << "lsn(-0.5, 0.2) = " << crack.lsn(Point<2>(-0.5, 0.2))
          << ", lsn(ahead) = " << crack.lsn(ahead) + 0.
          << ", lst(ahead) = " << crack.lst(ahead) << ", lst(tip - 0.1 e1) = "
          << crack.lst(tips[0].position - 0.1 * tips[0].e1)
          << ", lsn above the kink > 0: "
          << yes(crack.lsn(Point<2>(-0.01, 0.05)) > 0) << std::endl;
}

void
check_errors()
{
  logfile << "Bad crack meshes" << std::endl;
  const auto attempt = [](const std::string &file, const std::string &text) {
    if (!text.empty())
      std::ofstream(file) << text;
    try
      {
        MeshCrack<3> crack(file, "Cracks/Crack 1/File name", 0);
        logfile << "  " << file << ": accepted (WRONG)" << std::endl;
      }
    catch (const InputError &e)
      {
        logfile << "  " << e.what() << std::endl;
      }
  };
  attempt("missing.msh", "");
  attempt("crack.stl", "solid x\n");
  attempt("binary.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
  attempt("lines.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n"
          "$EndNodes\n$Elements\n1\n1 1 2 0 1 1 2\n$EndElements\n");
  attempt("unknown_node.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n"
          "$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n");
  // Three triangles on one edge: a branched crack.
  attempt("branched.vtk",
          "# vtk DataFile Version 4.2\nb\nASCII\nDATASET POLYDATA\n"
          "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
          "POLYGONS 3 12\n3 0 1 2\n3 0 1 3\n3 0 1 4\n");
  attempt("degenerate.vtk",
          "# vtk DataFile Version 4.2\nd\nASCII\nDATASET POLYDATA\n"
          "POINTS 3 double\n0 0 0\n1 0 0\n2 0 0\nPOLYGONS 1 4\n3 0 1 2\n");
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_half_plane();
  check_penny();
  check_polyline_2d();
  check_errors();
}
