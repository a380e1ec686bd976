// Requirement: the level-set fields are the crack (one rank and two):
// - interpolated from a tilted penny, their cell interpolants (CellLevelSets,
//   what the enrichment functions evaluate) are within O(h^2) of the
//   analytic level sets near the front (second order, error / h^2 near
//   0.3);
// - carried across refinement and coarsening of the p4est mesh, the fields
//   of a straight 2D crack (linear level sets) stay exact at every vertex,
//   the new ones included;
// - stored with the mesh (Triangulation::save) and read back onto the
//   coarse mesh (load), they are bit for bit the fields that were saved;
// - where the crack passes through vertices (and its tip lies on one) the
//   fields are exactly zero, not the round-off of the shape's geometry,
//   whose sign would decide how the cells around are classified.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/xfem/cell_level_sets.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>

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

/// The largest |value - reference| over the cells near the front: centres
/// and a corner-near point, lsn and lst.
template <int dim>
double
interpolation_error(const LevelSetFields<dim> &fields,
                    const CrackGeometry<dim>  &shape,
                    const Triangulation<dim>  &tria,
                    const double               h)
{
  const std::vector<double> lsn   = fields.vertex_values(0, true);
  const std::vector<double> lst   = fields.vertex_values(0, false);
  double                    error = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() &&
        std::hypot(shape.lsn(cell->center()), shape.lst(cell->center())) <
          2 * h)
      {
        std::array<double, GeometryInfo<dim>::vertices_per_cell> n, t;
        for (const unsigned int v : cell->vertex_indices())
          {
            n[v] = lsn[cell->vertex_index(v)];
            t[v] = lst[cell->vertex_index(v)];
          }
        const CellLevelSets<dim> local(cell, n, t);
        for (const Point<dim> &x :
             {cell->center(), 0.8 * cell->vertex(0) + 0.2 * cell->center()})
          error = std::max({error,
                            std::abs(local.lsn(x) - shape.lsn(x)),
                            std::abs(local.lst(x) - shape.lst(x))});
      }
  return Utilities::MPI::max(error, MPI_COMM_WORLD);
}

void
check_penny()
{
  const CrackSet<3> cracks =
    make_cracks<3>("  set Shape = penny\n  set Center = 0.03, -0.02, 0.01\n"
                   "  set Normal = 0.2, 0.1, 1\n  set Radius = 0.6\n");
  logfile << "Tilted penny, a = 0.6, in [-1,1]^3: interpolation error of the "
             "cells' level sets near the front"
          << std::endl;
  double previous = 0;
  for (unsigned int n : {8u, 16u, 32u})
    {
      parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
      GridGenerator::subdivided_hyper_cube(tria, n, -1, 1);
      LevelSetFields<3> fields(tria);
      fields.initialize(cracks.shapes());
      const double h     = 2. / n;
      const double error = interpolation_error(fields, cracks[0], tria, h);
      // Pre-asymptotic on the first mesh (a penny of radius 0.6 in cells
      // of 0.25); then error / h^2 settles near 0.3.
      logfile << "  h = " << std::setprecision(4) << h;
      if (previous > 0)
        logfile << ": error / h^2 below 0.5: " << yes(error < 0.5 * h * h)
                << ", order above 1.8: "
                << yes(std::log2(previous / error) > 1.8);
      logfile << std::endl;
      previous = error;
    }
}

void
check_transfer_and_checkpoint()
{
  // A straight crack: lsn and lst are linear, so every interpolant is exact.
  const CrackSet<2> cracks =
    make_cracks<2>("  set Start point = -2, 0.13\n  set End point = 0.37, "
                   "0.41\n  set Tips = end\n");
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(tria, 4, -1, 1);
  tria.refine_global(2);
  LevelSetFields<2> fields(tria);
  fields.initialize(cracks.shapes());

  const auto worst = [&](const LevelSetFields<2> &f) {
    const std::vector<double> lsn = f.vertex_values(0, true);
    const std::vector<double> lst = f.vertex_values(0, false);
    double                    e   = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          e = std::max({e,
                        std::abs(lsn[cell->vertex_index(v)] -
                                 cracks[0].lsn(cell->vertex(v))),
                        std::abs(lst[cell->vertex_index(v)] -
                                 cracks[0].lst(cell->vertex(v)))});
    return Utilities::MPI::max(e, MPI_COMM_WORLD);
  };

  // Refine near the tip and coarsen far from it, twice.
  for (unsigned int pass = 0; pass < 2; ++pass)
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const double r = cell->center().distance(Point<2>(0.37, 0.41));
            if (r < 0.4)
              cell->set_refine_flag();
            else if (r > 1.2)
              cell->set_coarsen_flag();
          }
      tria.prepare_coarsening_and_refinement();
      fields.prepare_for_coarsening_and_refinement();
      tria.execute_coarsening_and_refinement();
      fields.interpolate();
    }
  logfile << "Straight 2D crack carried across two refinements and "
             "coarsenings ("
          << tria.n_global_active_cells()
          << " cells): exact at every vertex (1e-13): "
          << yes(worst(fields) < 1e-13) << std::endl;

  // Save and load.
  const std::string name = "fields_checkpoint";
  fields.prepare_for_serialization();
  tria.save(name);
  parallel::distributed::Triangulation<2> loaded(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(loaded, 4, -1, 1);
  loaded.load(name);
  LevelSetFields<2> read(loaded);
  read.deserialize(1);
  // The loaded mesh numbers its cells (and the fields' DoFs) in its own
  // order: compare the values by the position of their vertex.
  const auto by_position = [](const LevelSetFields<2> &f) {
    std::map<std::pair<double, double>, std::pair<double, double>> values;
    const std::vector<double> lsn = f.vertex_values(0, true);
    const std::vector<double> lst = f.vertex_values(0, false);
    for (const auto &cell :
         f.get_dof_handler().get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          values[{cell->vertex(v)[0], cell->vertex(v)[1]}] = {
            lsn[cell->vertex_index(v)], lst[cell->vertex_index(v)]};
    return values;
  };
  const bool same =
    (loaded.n_global_active_cells() == tria.n_global_active_cells()) &&
    by_position(fields) == by_position(read);
  logfile << "Saved with the mesh and loaded: the same fields, bit for bit: "
          << yes(!Utilities::MPI::logical_or(!same, MPI_COMM_WORLD))
          << std::endl;
}

void
check_round_off_zeros()
{
  // Along y = x / 3 from (-0.75, -0.25) to the tip (0.375, 0.125), on a
  // mesh of h = 1/8: the line passes through the vertices with x a multiple
  // of 3/8, and the normal through the tip, 3 x + y = 5/4, through others:
  // all exact binary numbers, as are both equations there.
  const CrackSet<2> cracks =
    make_cracks<2>("  set Start point = -0.75, -0.25\n  set End point = "
                   "0.375, 0.125\n  set Tips = end\n");
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_cube(tria, 16, -1, 1);
  LevelSetFields<2> fields(tria);
  fields.initialize(cracks.shapes());
  const std::vector<double> lsn   = fields.vertex_values(0, true);
  const std::vector<double> lst   = fields.vertex_values(0, false);
  bool                      zeros = true, others = true;
  unsigned int              n_on_line = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int v : cell->vertex_indices())
        {
          const Point<2> &x       = cell->vertex(v);
          const bool      on_line = (3 * x[1] == x[0]);
          // lst vanishes on the normal to the crack through its tip.
          const bool   at_tip = (3 * x[0] + x[1] == 1.25);
          const double value  = lsn[cell->vertex_index(v)];
          const double along  = lst[cell->vertex_index(v)];
          zeros  = zeros && (!on_line || value == 0) && (!at_tip || along == 0);
          others = others && (on_line || value != 0) && (at_tip || along != 0);
          // Each vertex counted once: by the cell it is vertex 0 of.
          n_on_line += (on_line && v == 0 && x[0] <= 0.375 && x[0] >= -0.75);
        }
  logfile << "Crack along y = x / 3 through "
          << Utilities::MPI::sum(n_on_line, MPI_COMM_WORLD)
          << " vertices, its tip on one: lsn exactly zero on the line and "
             "lst on the normal through the tip: "
          << yes(!Utilities::MPI::logical_or(!zeros, MPI_COMM_WORLD))
          << "; nonzero elsewhere: "
          << yes(!Utilities::MPI::logical_or(!others, MPI_COMM_WORLD))
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    logfile.open("output");
  check_penny();
  check_transfer_and_checkpoint();
  check_round_off_zeros();
}
