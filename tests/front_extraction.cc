// Requirement: the crack drawn from the Q1 level-set fields (CrackSurface)
// is the analytic crack up to the interpolation error, on one rank or two:
// - a tilted penny in a cube: one closed front, its points within O(h^2) of
//   the circle (interpolation error of the Q1 fields), frames within O(h) of
//   the analytic ones (e2 the normal, e1 radial, e3 = e1 x e2 tangent and
//   pointing along increasing s), length and lip area converging to 2 pi a and
//   pi a^2 at second order;
// - a semi-elliptical surface crack: one open front from one face of the
//   body to the same face, ends on it;
// - a 2D edge crack: one tip, exactly where it is, with e1 along the crack
//   and e2 turned by +90 degrees; lip length exact;
// - a straight front along a row of cell edges, the cells on one side of
//   half of it refined (adaptive refinement does this): the coarse cells'
//   segments pass through hanging nodes, and the front stays one front,
//   straight from face to face.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/grid_generator.h>

#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/crack_surface.h>
#include <xcrack/crack/level_set_fields.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile;

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

template <int dim>
CrackSet<dim>
make_cracks(const std::string &description)
{
  ParameterHandler prm;
  CrackSet<dim>::declare_parameters(prm);
  prm.parse_input_from_string("subsection Cracks\n set Number of cracks = 1\n"
                              " subsection Crack 1\n" +
                              description + " end\nend\n");
  CrackSet<dim> cracks;
  cracks.parse_parameters(prm);
  return cracks;
}

void
check_penny()
{
  logfile << "Tilted penny, a = 0.6, in [-1,1]^3" << std::endl;
  const double   a = 0.6;
  const Point<3> centre(0.03, -0.02, 0.01);
  Tensor<1, 3>   normal({0.2, 0.1, 1.});
  normal /= normal.norm();
  const CrackSet<3> cracks =
    make_cracks<3>("  set Shape = penny\n  set Center = 0.03, -0.02, 0.01\n"
                   "  set Normal = 0.2, 0.1, 1\n  set Radius = 0.6\n");

  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(mesh, 8, -1, 1);
  double previous_distance = 0, previous_length = 0, previous_area = 0;
  for (unsigned int level = 0; level < 3; ++level)
    {
      if (level > 0)
        mesh.refine_global();
      const double      h = 2. / (8 << level);
      LevelSetFields<3> level_sets(mesh);
      CrackSurface<3>   surface;
      level_sets.initialize(cracks.shapes());
      surface.extract(level_sets, 0);

      const auto &fronts   = surface.fronts();
      double      distance = 0, frame = 0, orientation = 1;
      for (const auto &front : fronts)
        for (unsigned int k = 0; k < front.size(); ++k)
          {
            const FrontPoint<3> &p  = front[k];
            const Tensor<1, 3>   x  = p.position - centre;
            const Tensor<1, 3>   in = x - (x * normal) * normal;
            const Tensor<1, 3>   e1 = in / in.norm();
            const Tensor<1, 3>   e3 = cross_product_3d(e1, normal);
            distance                = std::max(
              {distance, std::abs(x * normal), std::abs(in.norm() - a)});
            frame = std::max({frame,
                              (p.e1 - e1).norm(),
                              (p.e2 - normal).norm(),
                              (p.e3 - e3).norm()});
            if (k + 1 < front.size())
              orientation =
                std::min(orientation,
                         (front[k + 1].position - p.position) * p.e3);
          }
      const double length = surface.front_length();
      const double area   = surface.measure();
      const double length_error =
        std::abs(length - 2 * numbers::PI * a) / (2 * numbers::PI * a);
      const double area_error =
        std::abs(area - numbers::PI * a * a) / (numbers::PI * a * a);
      logfile << std::setprecision(3) << "h = " << h << ": " << fronts.size()
              << " front(s), closed "
              << yes(fronts.size() == 1 && fronts[0].front().position.distance(
                                             fronts[0].back().position) < 1e-12)
              << ", points on the circle within h^2/2 "
              << yes(distance < 0.5 * h * h) << ", frames within h "
              << yes(frame < h) << ", s along e3 " << yes(orientation > 0)
              << std::endl;
      logfile << std::scientific << "  front length error " << length_error
              << ", lip area error " << area_error << std::defaultfloat
              << std::endl;
      if (level > 0)
        logfile << std::fixed << std::setprecision(1)
                << "  orders: point distance "
                << std::log2(previous_distance / distance) << ", length "
                << std::log2(previous_length / length_error) << ", area "
                << std::log2(previous_area / area_error) << std::defaultfloat
                << std::endl;
      previous_distance = distance;
      previous_length   = length_error;
      previous_area     = area_error;
    }
}

void
check_surface_crack()
{
  logfile << "Semi-elliptical surface crack a = 0.5, b = 0.3 at the face z = 1"
          << std::endl;
  const CrackSet<3> cracks = make_cracks<3>(
    "  set Shape = ellipse\n  set Center = 0.01, 0, 1\n"
    "  set Normal = 0, 1, 0\n  set In-plane direction = 1, 0, 0\n"
    "  set Semi-axes = 0.5, 0.3\n");
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(mesh, 16, -1, 1);
  LevelSetFields<3> level_sets(mesh);
  CrackSurface<3>   surface;
  level_sets.initialize(cracks.shapes());
  surface.extract(level_sets, 0);
  const auto &fronts = surface.fronts();
  logfile << fronts.size() << " front(s)";
  if (fronts.size() == 1)
    {
      const auto &f = fronts[0];
      logfile << ", open "
              << yes(f.front().position.distance(f.back().position) > 0.5)
              << ", ends on z = 1 "
              << yes(std::abs(f.front().position[2] - 1) < 1e-12 &&
                     std::abs(f.back().position[2] - 1) < 1e-12)
              << std::setprecision(4)
              << ", ends at x = " << f.front().position[0] << " and "
              << f.back().position[0] << ", length " << f.back().s << ", area "
              << surface.measure();
    }
  logfile << std::endl;
}

void
check_edge_crack_2d()
{
  logfile << "2D edge crack from (-1, 0.1) to (0.3, 0.1)" << std::endl;
  const CrackSet<2> cracks =
    make_cracks<2>("  set Start point = -1, 0.1\n  set End point = 0.3, 0.1\n"
                   "  set Tips = end\n");
  parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(mesh, 20, -1, 1);
  LevelSetFields<2> level_sets(mesh);
  CrackSurface<2>   surface;
  level_sets.initialize(cracks.shapes());
  surface.extract(level_sets, 0);
  const auto &fronts = surface.fronts();
  logfile << fronts.size() << " tip(s)";
  for (const auto &f : fronts)
    logfile << std::setprecision(10) << " at (" << f[0].position << ")"
            << ", e1 = (" << f[0].e1 << "), e2 = (" << f[0].e2 << ")";
  logfile << ", lip length " << surface.measure() << std::endl;
}

void
check_front_along_edges()
{
  logfile << "Half plane y = 0, x < 0 in [-1,1]^3, front along cell edges, "
             "refined on one side of half of it"
          << std::endl;
  const CrackSet<3> cracks = make_cracks<3>(
    "  set Shape = half plane\n  set Center = 0, 0, 0\n"
    "  set Normal = 0, 1, 0\n  set In-plane direction = 1, 0, 0\n");
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(mesh, 4, -1, 1);
  for (const auto &cell : mesh.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center()[0] > 0 &&
        cell->center()[1] > 0 && cell->center()[2] > 0)
      cell->set_refine_flag();
  mesh.execute_coarsening_and_refinement();
  LevelSetFields<3> level_sets(mesh);
  CrackSurface<3>   surface;
  level_sets.initialize(cracks.shapes());
  surface.extract(level_sets, 0);
  const auto &fronts = surface.fronts();
  logfile << fronts.size() << " front(s)";
  if (fronts.size() == 1)
    {
      bool on_line = true;
      for (const auto &p : fronts[0])
        on_line = on_line && std::hypot(p.position[0], p.position[1]) < 1e-12;
      logfile << ", " << fronts[0].size() << " points on x = y = 0 "
              << yes(on_line) << ", from z = " << fronts[0].front().position[2]
              << " to z = " << fronts[0].back().position[2] << ", length "
              << fronts[0].back().s;
    }
  logfile << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    logfile.open("output");
  check_penny();
  check_surface_crack();
  check_edge_crack_2d();
  check_front_along_edges();
}
