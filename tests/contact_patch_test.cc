// Requirement: the contact patch test. A straight crack splits a block
// under uniform compression (sigma_nn = -1 on the top face, the sides held
// in their normal direction with the exact data, the bottom on rollers):
// the closed lips must transmit the uniform stress, the upper piece
// resting on them (without contact it floats and the run stops). With
// `Contact/Formulation = penalty` the lips interpenetrate by p h / (c E)
// and the error of the solution falls like 1 / c, the penalty
// coefficient: three coefficients a hundred times apart give errors a
// hundred times apart (2D Q1, 2D Q2, 3D Q1, the crack through no node),
// each solve taking one Newton step (the lips start closed, and the
// assembly at the solution confirms them closed everywhere). With
// `augmented lagrangian` the multipliers take up the pressure and the lips
// stop interpenetrating: the error falls to the Newton loop's tolerance
// (1e-8 of the load; below 1e-7, where the penalty with the same
// coefficient leaves 3e-2 and 3e-4) for coefficients 10 and 1000, in two
// Newton steps: the penalty's uniform pressure is the exact one, and the
// first Uzawa update makes it the multiplier (at most three allowed). With
// `lagrange` the lips are held exactly on every multiplier space (vital
// nodes, edges, cells: each holds the constant pressure): the error is the
// linear solve's round-off (1e-8, where the penalty at c = 1e6 leaves
// 3e-7) and the pressure 1 to 1e-9 at every lip point, in one Newton step.

#include <deal.II/base/mpi.h>

#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace dealii;

std::ofstream logfile;

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

template <int dim>
xcrack::Statistics
run(const unsigned int degree,
    const std::string &formulation,
    const double       c,
    const std::string &space = "")
{
  // E = 1, nu = 0.3, uniaxial stress sigma_nn = -1 along the last axis,
  // plane strain in 2D (eps_xx = nu (1 + nu) / E, eps_yy = -(1 - nu^2) /
  // E); in 3D eps_xx = eps_yy = nu / E, eps_zz = -1 / E.
  std::ostringstream in;
  in << "set Dimension = " << dim << "\nset Output directory = results\n"
     << "subsection Output\n set Write vtu = false\n"
     << " set Timing summary = false\nend\n"
     << "subsection Discretization\n set Degree = " << degree << "\nend\n"
     << "subsection Contact\n set Formulation = " << formulation << "\n";
  if (formulation == "lagrange")
    in << " subsection Lagrange\n  set Multiplier space = " << space
       << "\n end\nend\n";
  else
    in << (formulation == "augmented lagrangian" ?
             " subsection Augmented Lagrangian\n  set Augmentation" :
             " subsection Penalty\n  set Penalty")
       << " coefficient = " << c << "\n end\nend\n";
  if (dim == 2)
    in << "subsection Mesh\n set Subdivisions = 4, 4\n"
       << " set Lower corner = -1, -1\n set Upper corner = 1, 1\nend\n"
       << "subsection Boundary conditions\n"
       << " set Dirichlet = 0: 0.39 * x; 0 | 1: 0.39 * x; 0 | 2: 0; 0\n"
       << " set Dirichlet components = 0: x | 1: x | 2: y\n"
       << " set Neumann = 3: 0; -1\nend\n"
       << "subsection Exact solution\n"
       << " set Displacement = 0.39 * x; -0.91 * (y + 1)\nend\n"
       << "subsection Cracks\n set Number of cracks = 1\n"
       << " subsection Crack 1\n  set Start point = -1.5, 0.13\n"
       << "  set End point = 1.5, 0.13\n  set Tips = none\n end\nend\n";
  else
    in << "subsection Mesh\n set Subdivisions = 3, 3, 3\n"
       << " set Lower corner = -1, -1, -1\n set Upper corner = 1, 1, 1\nend\n"
       << "subsection Boundary conditions\n"
       << " set Dirichlet = 0: 0.3 * x; 0; 0 | 1: 0.3 * x; 0; 0 | "
          "2: 0; 0.3 * y; 0 | 3: 0; 0.3 * y; 0 | 4: 0; 0; 0\n"
       << " set Dirichlet components = 0: x | 1: x | 2: y | 3: y | 4: z\n"
       << " set Neumann = 5: 0; 0; -1\nend\n"
       << "subsection Exact solution\n"
       << " set Displacement = 0.3 * x; 0.3 * y; -(z + 1)\nend\n"
       << "subsection Cracks\n set Number of cracks = 1\n"
       << " subsection Crack 1\n  set Shape = penny\n  set Radius = 10\n"
       << "  set Center = 0, 0, 0.13\n  set Normal = 0, 0, 1\n end\nend\n";
  ParameterHandler prm;
  xcrack::declare_all_parameters(prm);
  xcrack::read_parameter_string(prm, in.str());
  xcrack::Simulator<dim> simulator(prm, MPI_COMM_WORLD);
  simulator.run();
  return simulator.get_statistics();
}

template <int dim>
void
check(const unsigned int degree)
{
  double previous = 0;
  for (const double c : {1e2, 1e4, 1e6})
    {
      const auto   stats = run<dim>(degree, "penalty", c);
      const double error = stats.get("L2_error", 0);
      logfile << dim << "D Q" << degree << ", penalty coefficient "
              << std::scientific << std::setprecision(0) << c
              << std::defaultfloat << ": " << stats.get("newton_iterations", 0)
              << " Newton step(s), closed fraction of the lips "
              << stats.get("contact_closed", 0) << ", L2 error times c "
              << std::setprecision(2) << error * c;
      if (previous > 0)
        logfile << ", error 100 times smaller than the previous one (within "
                   "10 %): "
                << yes(std::abs(previous / error / 100 - 1) < 0.1);
      logfile << std::endl;
      previous = error;
    }
}

template <int dim>
void
check_augmented(const unsigned int degree)
{
  for (const double c : {1e1, 1e3})
    {
      const auto         stats = run<dim>(degree, "augmented lagrangian", c);
      const unsigned int steps = stats.get("newton_iterations", 0);
      logfile << dim << "D Q" << degree
              << ", augmented Lagrangian, coefficient " << c
              << ": L2 error below 1e-7: "
              << yes(stats.get("L2_error", 0) < 1e-7) << ", " << steps
              << " Newton steps";
      logfile << ", at most 3: " << yes(steps <= 3) << std::endl;
    }
}

template <int dim>
void
check_lagrange(const unsigned int degree)
{
  for (const std::string space : {"vital nodes", "edges", "cells"})
    {
      const auto         stats = run<dim>(degree, "lagrange", 0, space);
      const unsigned int steps = stats.get("newton_iterations", 0);
      logfile << dim << "D Q" << degree << ", Lagrange multipliers on " << space
              << ": L2 error below 1e-7: "
              << yes(stats.get("L2_error", 0) < 1e-7)
              << ", pressure uniform (min and max within 1e-9 of 1): "
              << yes(std::abs(stats.get("contact_pressure_min", 0) - 1) <
                       1e-9 &&
                     std::abs(stats.get("contact_pressure_max", 0) - 1) < 1e-9)
              << ", " << steps << " Newton step(s)" << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  logfile.open("output");
  check<2>(1);
  check<2>(2);
  check<3>(1);
  check_augmented<2>(1);
  check_augmented<2>(2);
  check_augmented<3>(1);
  check_lagrange<2>(1);
  check_lagrange<2>(2);
  check_lagrange<3>(1);
  try
    {
      run<2>(1, "none", 1);
      logfile << "without contact: NO error" << std::endl;
    }
  catch (const std::exception &)
    {
      logfile << "without contact the upper piece floats: the run stops"
              << std::endl;
    }
}
