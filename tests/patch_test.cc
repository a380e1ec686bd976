// Requirement: a uniform stress state is reproduced to round-off by Q1 and Q2
// elements on distorted meshes read from Gmsh files, in 2D and 3D, with a
// clamped face, a roller face (one component prescribed, traction on the
// others) and traction faces; by the direct and by the CG+AMG solver.

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <fstream>
#include <iomanip>
#include <sstream>

using namespace dealii;

std::ofstream logfile("output");

// The strain of the linear displacement below: a general constant strain.
template <int dim>
SymmetricTensor<2, dim>
strain()
{
  SymmetricTensor<2, dim> e;
  e[0][0] = 0.2;
  e[1][1] = -0.1;
  e[0][1] = 0.075;
  if (dim == 3)
    {
      e[2][2] = 0.15;
      e[0][2] = 0.005;
      e[1][2] = 0.05;
    }
  return e;
}

std::string
displacement(const unsigned int dim)
{
  // Strain above plus a rigid motion.
  if (dim == 2)
    return "0.1 + 0.2*x + 0.05*y; -0.3 + 0.1*x - 0.1*y";
  return "0.1 + 0.2*x + 0.05*y - 0.02*z; -0.3 + 0.1*x - 0.1*y + 0.04*z; "
         "0.2 + 0.03*x + 0.06*y + 0.15*z";
}

template <int dim>
void
check(const unsigned int degree, const std::string &solver)
{
  const double                  E = 1., nu = 0.3;
  const double                  mu     = E / (2 * (1 + nu));
  const double                  lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const SymmetricTensor<2, dim> sigma =
    lambda * trace(strain<dim>()) * unit_symmetric_tensor<dim>() +
    2 * mu * strain<dim>();

  // Traction sigma.n on the face with outward normal sign * e_d.
  const auto traction = [&](const unsigned int d, const double sign) {
    std::ostringstream t;
    t << std::setprecision(17);
    for (unsigned int i = 0; i < dim; ++i)
      t << (i ? "; " : "") << sign * sigma[i][d];
    return t.str();
  };

  std::ostringstream neumann;
  neumann << "1: " << traction(0, 1) << " | 2: " << traction(1, -1)
          << " | 3: " << traction(1, 1);
  if (dim == 3)
    neumann << " | 4: " << traction(2, -1) << " | 5: " << traction(2, 1);

  std::ostringstream input;
  input << "set Dimension = " << dim << "\n"
        << "set Output directory = results\n"
        << "subsection Output\n set Write vtu = false\n"
        << " set Timing summary = false\nend\n"
        << "subsection Mesh\n set Type = file\n set File name = " SOURCE_DIR
        << "/mesh/distorted_" << dim << "d.msh\nend\n"
        << "subsection Material\n set Young's modulus = " << E
        << "\n set Poisson's ratio = " << nu << "\nend\n"
        << "subsection Discretization\n set Degree = " << degree << "\nend\n"
        << "subsection Linear solver\n set Type = " << solver
        << "\n set Relative tolerance = 1e-13\nend\n"
        << "subsection Boundary conditions\n"
        << " set Dirichlet = 0: " << displacement(dim)
        << " | 2: " << displacement(dim) << "\n"
        << " set Dirichlet components = 2: y\n"
        << " set Neumann = " << neumann.str() << "\nend\n"
        << "subsection Exact solution\n set Displacement = "
        << displacement(dim) << "\nend\n";

  ParameterHandler prm;
  xcrack::declare_all_parameters(prm);
  xcrack::read_parameter_string(prm, input.str());
  xcrack::Simulator<dim> problem(prm);
  problem.run();

  const auto &stats = problem.get_statistics();
  // The energy error is limited to about 1e-12 by the finite-difference
  // gradient of the parsed exact solution, the L2 error only by round-off.
  const double l2_tolerance     = (solver == "direct" ? 1e-13 : 1e-9);
  const double energy_tolerance = (solver == "direct" ? 1e-11 : 1e-9);
  logfile << dim << "D Q" << degree << ", " << solver << " solver, "
          << stats.get("cells", 0) << " cells: relative L2 error < "
          << l2_tolerance << ": "
          << (stats.get("L2_error", 0) < l2_tolerance ? "yes" : "NO") << ", "
          << "relative energy error < " << energy_tolerance << ": "
          << (stats.get("energy_error", 0) < energy_tolerance ? "yes" : "NO")
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      check<2>(degree, "direct");
      check<3>(degree, "direct");
    }
  check<2>(1, "cg amg");
  check<3>(1, "cg amg");

  // The table scripts read: its header must keep the fixed column names.
  std::ifstream csv("results/statistics.csv");
  std::string   header;
  std::getline(csv, header);
  logfile << "statistics.csv columns: " << header << std::endl;
}
