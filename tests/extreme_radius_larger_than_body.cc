// Requirement (extremes): an enrichment radius larger than the body puts the
// branch functions on every node. The exact Case 1 field then lies in the
// discrete space; with the branch DoFs on the Dirichlet boundary fitted to
// the data, it is reproduced up to conditioning and quadrature (energy
// error 5e-5 and 6e-5 on these meshes, printed here only as thresholds: the
// digits are round-off and differ between builds), against 1.4e-1 with
// radius 0.25 on the same mesh; K_I = 1 to 1e-5.

#include <deal.II/base/mpi.h>

#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <cmath>
#include <fstream>

using namespace dealii;

std::ofstream logfile("output");

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

const xcrack::Statistics &
run(const double radius, std::unique_ptr<xcrack::Simulator<2>> &p)
{
  ParameterHandler prm;
  xcrack::declare_all_parameters(prm);
  xcrack::read_parameter_string(
    prm,
    "include " SOURCE_DIR "/../prm/benchmarks/exact_mode_I_2d.prm\n"
    "set Output directory = results\n"
    "subsection Output\n set Timing summary = false\nend\n"
    "subsection Mesh refinement\n set Number of meshes = 2\nend\n"
    "subsection Enrichment\n set Enrichment radius = " +
      std::to_string(radius) + "\nend\n");
  p = std::make_unique<xcrack::Simulator<2>>(prm, MPI_COMM_WORLD);
  p->run();
  return p->get_statistics();
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize      mpi(argc, argv, 1);
  std::unique_ptr<xcrack::Simulator<2>> everywhere, zone;
  const auto                           &all  = run(10, everywhere);
  const auto                           &part = run(0.25, zone);
  for (unsigned int r = 0; r < all.n_rows(); ++r)
    logfile << "mesh " << r << ": " << all.get("cells", r)
            << " cells, every node enriched: energy error below 1e-4 "
            << yes(all.get("energy_error", r) < 1e-4)
            << ", L2 error below 1e-5 " << yes(all.get("L2_error", r) < 1e-5)
            << ", K_I = 1 to 1e-5 "
            << yes(std::abs(all.get("K_I_1", r) - 1) < 1e-5)
            << "; radius 0.25: energy error above 1e-2 "
            << yes(part.get("energy_error", r) > 1e-2) << std::endl;
}
