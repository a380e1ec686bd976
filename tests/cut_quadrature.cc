// Requirement: the rules of the cells a crack splits integrate each side
// exactly: the area (volume) below a tilted crack in the unit square (cube)
// to 1e-13, and a cubic polynomial over that side to 1e-13, summed over the
// split cells and the Gauss rules of the others.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/xfem/enrichment.h>

#include <cmath>
#include <fstream>
#include <memory>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

/// Integrate 1 and x y (z) over {lsn < 0} in the unit box.
template <int dim>
std::pair<double, double>
integrate_below(const CrackGeometry<dim> &crack)
{
  Triangulation<dim> tria;
  GridGenerator::subdivided_hyper_cube(tria, 3);
  tria.refine_global(1);
  DoFHandler<dim>      dof_handler(tria);
  EnrichmentParameters parameters;
  parameters.heaviside_volume_tolerance = 0;
  parameters.fit_to_vertex              = 0; // the crack as given
  LevelSetFields<dim> fields(tria);
  fields.initialize({&crack});
  Enrichment<dim> enrichment(1, 1, parameters);
  enrichment.set_fe_indices(dof_handler, fields);
  dof_handler.distribute_dofs(enrichment.get_fe_collection());

  const FE_Q<dim> fe(1);
  double          area = 0, moment = 0;
  unsigned int    n_split = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      const bool            split = enrichment.is_split(cell);
      const Quadrature<dim> rule =
        split ? enrichment.split_cell_quadrature(cell, 3) : QGauss<dim>(3);
      n_split += split;
      FEValues<dim> fe_values(fe,
                              rule,
                              update_quadrature_points | update_JxW_values);
      fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const Point<dim> &x = fe_values.quadrature_point(q);
          if (crack.lsn(x) >= 0)
            continue;
          double xyz = 1;
          for (unsigned int d = 0; d < dim; ++d)
            xyz *= x[d];
          area += fe_values.JxW(q);
          moment += xyz * fe_values.JxW(q);
        }
    }
  logfile << dim << "D: " << n_split << " split cells, ";
  return {area, moment};
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Below y = 0.3 + 0.2 x: area 0.4, int x y = 0.0475.
  const SegmentCrack line(Point<2>(-1, 0.1), Point<2>(2, 0.7), false, false);
  const auto [a2, m2] = integrate_below<2>(line);
  logfile << "area below the crack exact to 1e-13: "
          << (std::abs(a2 - 0.4) < 1e-13 ? "yes" : "NO")
          << ", integral of x y exact to 1e-13: "
          << (std::abs(m2 - 0.0475) < 1e-13 ? "yes" : "NO") << std::endl;

  // Below z = 0.3 + 0.1 x + 0.05 y: volume 0.375,
  // int x y z = (0.0225 + 0.00125 + 0.0003125 + 0.01 + 0.005 + 1/900) / 2.
  const EllipticalCrack plane(Point<3>(0, 0, 0.3),
                              Tensor<1, 3>({-0.1, -0.05, 1}),
                              Tensor<1, 3>({1, 0, 0.1}),
                              100,
                              100);
  const double          exact = (0.0390625 + 1. / 900) / 2;
  const auto [a3, m3]         = integrate_below<3>(plane);
  logfile << "volume below the crack exact to 1e-13: "
          << (std::abs(a3 - 0.375) < 1e-13 ? "yes" : "NO")
          << ", integral of x y z exact to 1e-13: "
          << (std::abs(m3 - exact) < 1e-13 ? "yes" : "NO") << std::endl;
}
