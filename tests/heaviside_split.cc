// Requirement: a crack that splits the body completely is represented
// exactly by the Heaviside (jump) enrichment on a mesh that does not know
// the crack: with the lower part clamped and the upper part moved rigidly,
// the discrete solution is the discontinuous exact one to round-off, in 2D
// and 3D, for Q1 and Q2, on meshes refined in regions (hanging nodes on
// split cells and at the border of the enriched zone), on one or two ranks.
// Without the crack the same mesh misses the jump. At the extremes: a crack
// exactly through a row of nodes, or 1e-8 of an edge above or below it, is
// still reproduced to round-off (the condition number grows like h/delta);
// at 1e-12 the barely cut supports lose their enrichment (volume criterion)
// and the error stays below 1e-9 with a condition number of a plain mesh;
// with fit to vertex a crack within the tolerance runs through the nodes.

#include <deal.II/base/mpi.h>

#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace dealii;

std::ofstream logfile;

struct Case
{
  std::string  name;
  unsigned int dim;
  unsigned int degree;
  unsigned int meshes;
  double       tolerance;
};

std::string
input(const Case &c, const bool with_crack)
{
  std::ostringstream in;
  // The crack plane: tilted, through no vertex of the meshes used.
  const std::string side =
    (c.dim == 2 ? "y > 0.51 + 0.05*x" : "z > 0.31 + 0.1*x + 0.05*y");
  const std::string rigid = side + " ? 0.01 : 0; " + side +
                            (c.dim == 2 ? " ? 0.1 : 0" : " ? -0.02 : 0; ") +
                            (c.dim == 2 ? "" : side + " ? 0.1 : 0");
  in
    << "set Dimension = " << c.dim << "\nset Output directory = results\n"
    << "subsection Output\n set Write vtu = false\n set Timing summary = false\nend\n"
    << "subsection Discretization\n set Degree = " << c.degree << "\nend\n"
    << "subsection Mesh refinement\n set Number of meshes = " << c.meshes
    << "\n set Strategy = region\n";
  if (c.dim == 2)
    in
      << " subsection Region\n  set Region = 0.2 - abs(x - 0.5)\n end\nend\n"
      << "subsection Mesh\n set Subdivisions = 8, 8\nend\n"
      << "subsection Boundary conditions\n set Dirichlet = 2: 0; 0 | 3: 0.01; 0.1\nend\n";
  else
    in
      << " subsection Region\n  set Region = 0.15 - abs(z - 0.31 - 0.1*x - 0.05*y)\n end\nend\n"
      << "subsection Mesh\n set Upper corner = 1, 1, 1\n set Subdivisions = 4, 4, 4\nend\n"
      << "subsection Boundary conditions\n"
      << " set Dirichlet = 4: 0; 0; 0 | 5: 0.01; -0.02; 0.1\nend\n";
  // The exact solution jumps at the crack as given: fit to vertex (which
  // moves it by up to 1e-2 h where it passes that close to a node) is off
  // here; check_near_nodes() and check_fitted_3d() test it.
  in << "subsection Enrichment\n set Fit to vertex tolerance = 0\nend\n";
  in << "subsection Exact solution\n set Displacement = " << rigid << "\nend\n";
  if (with_crack)
    {
      in
        << "subsection Cracks\n set Number of cracks = 1\n subsection Crack 1\n";
      if (c.dim == 2)
        in << "  set Start point = -0.1, 0.505\n  set End point = 1.1, 0.565\n"
           << "  set Tips = none\n";
      else
        // A penny far larger than the body: its front is outside.
        in << "  set Shape = penny\n  set Center = 0, 0, 0.31\n"
           << "  set Normal = -0.1, -0.05, 1\n  set Radius = 10\n";
      in << " end\nend\n";
    }
  return in.str();
}

template <int dim>
const xcrack::Statistics &
run(const std::string                       &text,
    std::unique_ptr<xcrack::Simulator<dim>> &p,
    const MPI_Comm                           comm = MPI_COMM_WORLD)
{
  ParameterHandler prm;
  xcrack::declare_all_parameters(prm);
  xcrack::read_parameter_string(prm, text);
  p = std::make_unique<xcrack::Simulator<dim>>(prm, comm);
  p->run();
  return p->get_statistics();
}

template <int dim>
void
check(const Case &c)
{
  std::unique_ptr<xcrack::Simulator<dim>> problem, plain_problem;
  const auto &stats = run<dim>(input(c, true), problem);
  for (unsigned int r = 0; r < stats.n_rows(); ++r)
    logfile << c.name << ", mesh " << r << ": " << stats.get("cells", r)
            << " cells, " << stats.get("enriched_dofs", r)
            << " enriched dofs, rigid split reproduced (relative L2 error < "
            << c.tolerance
            << "): " << (stats.get("L2_error", r) < c.tolerance ? "yes" : "NO")
            << std::endl;
  const auto &plain = run<dim>(input(c, false), plain_problem);
  logfile << c.name << ", without the crack: the jump is missed (relative L2 "
          << "error > 0.1): "
          << (plain.get("L2_error", plain.n_rows() - 1) > 0.1 ? "yes" : "NO")
          << std::endl;
}

// The condition number is computed on one rank: every rank solves these
// small problems on its own, in its own output directory.
//
// With fit to vertex (tolerance tau, a fraction of h), a crack within tau h
// of the row is moved onto it: the enriched DoFs and the condition number
// of a crack through the nodes, and the rigid split with its jump at the
// row (y = 0.5) to round-off. A crack beyond tau h stays where it is.
void
check_near_nodes()
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  struct Offset
  {
    double offset;
    double fit; // Enrichment/Fit to vertex tolerance
  };
  for (const auto [offset, fit] : {Offset{0., 0.},
                                   Offset{1e-8, 0.},
                                   Offset{-1e-8, 0.},
                                   Offset{1e-12, 0.},
                                   Offset{1e-8, 1e-2},
                                   Offset{-1e-8, 1e-2},
                                   Offset{1e-3, 1e-2},
                                   Offset{-1e-3, 1e-2},
                                   Offset{2e-3, 1e-2}})
    {
      // Where the discrete jump should be: the row if the crack is fitted.
      const bool         fitted = std::abs(offset) <= fit * 0.125;
      std::ostringstream y, jump;
      y << std::setprecision(17) << 0.5 + offset;
      jump << std::setprecision(17) << (fitted ? 0.5 : 0.5 + offset);
      std::ostringstream in;
      in << "set Dimension = 2\nset Output directory = results-" << rank << "\n"
         << "subsection Output\n set Write vtu = false\n"
         << " set Timing summary = false\n"
         << " set Condition number up to dofs = 1000\nend\n"
         << "subsection Mesh\n set Subdivisions = 8, 8\nend\n"
         << "subsection Boundary conditions\n"
         << " set Dirichlet = 2: 0; 0 | 3: 0.01; 0.1\nend\n"
         << "subsection Enrichment\n set Fit to vertex tolerance = " << fit
         << "\nend\n"
         << "subsection Exact solution\n set Displacement = y >= " << jump.str()
         << " ? 0.01 : 0; y >= " << jump.str() << " ? 0.1 : 0\nend\n"
         << "subsection Cracks\n set Number of cracks = 1\n"
         << " subsection Crack 1\n  set Start point = -0.1, " << y.str()
         << "\n  set End point = 1.1, " << y.str()
         << "\n  set Tips = none\n end\nend\n";
      std::unique_ptr<xcrack::Simulator<2>> problem;
      const auto &stats = run<2>(in.str(), problem, MPI_COMM_SELF);
      logfile << "crack at " << offset << " from a row of nodes (h = 0.125)"
              << (fit > 0 ?
                    ", fit to vertex " + std::to_string(fit).substr(0, 4) +
                      (fitted ? " (fitted)" : " (not fitted)") :
                    std::string())
              << ": " << stats.get("enriched_dofs", 0)
              << " enriched dofs, condition number ~ 10^"
              << std::lround(std::log10(stats.get("condition_number", 0)))
              << ", relative L2 error < 1e-9: "
              << (stats.get("L2_error", 0) < 1e-9 ? "yes" : "NO") << std::endl;
    }
}

// Fit to vertex in 3D, on all ranks (the fitted vertices are agreed over
// the partition): a plane crack tilted by 1e-4 against the node plane
// z = 0.5 (within 1e-2 h of it on every mesh) is moved onto that plane, and
// the rigid split with its jump at z = 0.5 is reproduced to round-off on a
// mesh refined around it (hanging nodes on the fitted plane).
void
check_fitted_3d()
{
  const std::string  side = "z >= 0.5";
  std::ostringstream in;
  in
    << "set Dimension = 3\nset Output directory = results\n"
    << "subsection Output\n set Write vtu = false\n"
    << " set Timing summary = false\nend\n"
    << "subsection Mesh\n set Upper corner = 1, 1, 1\n"
    << " set Subdivisions = 4, 4, 4\nend\n"
    << "subsection Mesh refinement\n set Number of meshes = 3\n"
    << " set Strategy = region\n subsection Region\n  set Region = 0.3 - x - abs(z - 0.5)\n end\nend\n"
    << "subsection Boundary conditions\n"
    << " set Dirichlet = 4: 0; 0; 0 | 5: 0.01; -0.02; 0.1\nend\n"
    << "subsection Exact solution\n set Displacement = " << side
    << " ? 0.01 : 0; " << side << " ? -0.02 : 0; " << side
    << " ? 0.1 : 0\nend\n"
    << "subsection Enrichment\n set Fit to vertex tolerance = 0.01\nend\n"
    << "subsection Cracks\n set Number of cracks = 1\n subsection Crack 1\n"
    << "  set Shape = penny\n  set Center = 0, 0, 0.5\n"
    << "  set Normal = 1e-4, 5e-5, 1\n  set Radius = 10\n end\nend\n";
  std::unique_ptr<xcrack::Simulator<3>> problem;
  const auto                           &stats = run<3>(in.str(), problem);
  for (unsigned int r = 0; r < stats.n_rows(); ++r)
    logfile << "3D Q1, crack tilted 1e-4 off a node plane, fit to vertex "
            << "0.01, mesh " << r << ": " << stats.get("cells", r) << " cells, "
            << stats.get("enriched_dofs", r)
            << " enriched dofs, rigid split at the node plane reproduced "
            << "(relative L2 error < 1e-12): "
            << (stats.get("L2_error", r) < 1e-12 ? "yes" : "NO") << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    logfile.open("output");
  else
    logfile.setstate(std::ios::badbit);

  check<2>({"2D Q1", 2, 1, 3, 1e-12});
  check<2>({"2D Q2", 2, 2, 2, 1e-10});
  check<3>({"3D Q1", 3, 1, 3, 1e-12});
  // Q2 suffers most from supports barely cut by the crack (no conditioning
  // treatment yet): the tolerance says how much.
  check<3>({"3D Q2", 3, 2, 2, 1e-8});
  check_near_nodes();
  check_fitted_3d();
}
