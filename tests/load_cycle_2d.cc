// Requirement: Delta K and the cycles come from the maximum and the minimum
// of the load cycle (LoadCycle), on a growing inclined centre crack
// (mixed mode, 30 degrees, Paris law) in 2D:
// - a minimum given as a load set of its own (Propagation/Minimum loads,
//   half the tractions: solved and its K's extracted) grows the crack as
//   Load ratio = 0.5 does (K_min = R K_max by linearity, not solved): the
//   same Delta K and cycles at every step to 1e-9;
// - R = -1 without contact: the compressive half of the cycle adds nothing
//   to mode I (Delta K_I = K_I,max), while K_II ranges over the whole
//   cycle (Delta K_II = 2 K_II,max): Delta K_eq = sqrt(K_I^2 + 4 K_II^2),
//   against sqrt(K_I^2 + K_II^2) for R = 0, to round-off;
// - the minimum of a linear scene takes one Newton step, the maximum too;
// - with frictionless penalty contact, R = -1 gives the Delta K of R = -1
//   without contact within 0.5 % on the straight crack (the minimum
//   solved, closed at the tips).

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

xcrack::Statistics
run(const std::string &cycle)
{
  std::ostringstream in;
  in << "set Dimension = 2\nset Output directory = results\n"
     << "subsection Output\n set Write vtu = false\n"
     << " set Timing summary = false\n set Detailed screen = false\nend\n"
     << "subsection Mesh\n set Subdivisions = 12, 12\n"
     << " set Lower corner = -1, -1\n set Upper corner = 1, 1\nend\n"
     << "subsection Boundary conditions\n"
     << " set Neumann = 2: 0; -1 | 3: 0; 1\n"
     << " set Pinned points = 0, -1: xy | 0, 1: x\nend\n"
     << "subsection Cracks\n set Number of cracks = 1\n"
     << " subsection Crack 1\n  set Start point = -0.1732, -0.1\n"
     << "  set End point = 0.1732, 0.1\n end\nend\n"
     << "subsection Enrichment\n set Tip enrichment = geometric\n"
     << " set Enrichment radius = 0.1\nend\n"
     << "subsection Fracture parameters\n set Crown unit = absolute\n"
     << " set Crown radii = 0.1, 0.25\nend\n"
     << "subsection Propagation\n set Number of steps = 2\n"
     << " set Maximum advance = 0.05\n"
     << " subsection Growth law\n  subsection Paris\n   set C = 1e-3\n"
     << "   set m = 3\n  end\n end\n"
     << cycle << "end\n";
  ParameterHandler prm;
  xcrack::declare_all_parameters(prm);
  xcrack::read_parameter_string(prm, in.str());
  xcrack::Simulator<2> simulator(prm, MPI_COMM_WORLD);
  simulator.run();
  return simulator.get_statistics();
}

double
largest_difference(const xcrack::Statistics &a,
                   const xcrack::Statistics &b,
                   const std::string        &column)
{
  double d = 0;
  for (unsigned int r = 0; r < a.n_rows(); ++r)
    d = std::max(d,
                 std::abs(a.get(column, r) - b.get(column, r)) /
                   std::abs(a.get(column, r)));
  return d;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  logfile.open("output");

  const auto ratio = run(" set Load ratio = 0.5\n");
  const auto own   = run(" subsection Minimum loads\n"
                         "  set Neumann = 2: 0; -0.5 | 3: 0; 0.5\n end\n");
  logfile << "own minimum loads against R = 0.5 (" << own.n_rows()
          << " steps): the same delta_K and cycles to 1e-9: "
          << yes(own.n_rows() == ratio.n_rows() &&
                 largest_difference(ratio, own, "delta_K") < 1e-9 &&
                 largest_difference(ratio, own, "cycles") < 1e-9)
          << std::endl;
  logfile << "Newton steps of the maximum and of the solved minimum: "
          << own.get("newton_iterations", 0) << ", "
          << own.get("minimum_newton_iterations", 0) << std::endl;

  const auto   reversed = run(" set Load ratio = -1\n");
  const auto   zero     = run(" set Load ratio = 0\n");
  const double k_I = zero.get("K_I_1", 0), k_II = zero.get("K_II_1", 0);
  logfile << std::fixed << std::setprecision(4)
          << "K_II / K_I at step 0: " << k_II / k_I << std::endl;
  logfile << "delta_K(R = -1) / delta_K(R = 0) = "
          << reversed.get("delta_K", 0) / zero.get("delta_K", 0)
          << ", sqrt(K_I^2 + 4 K_II^2) / sqrt(K_I^2 + K_II^2) = "
          << std::sqrt((k_I * k_I + 4 * k_II * k_II) /
                       (k_I * k_I + k_II * k_II))
          << std::endl;
  logfile << "the same K_max: "
          << yes(std::abs(reversed.get("K_max", 0) - zero.get("K_max", 0)) <
                 1e-12 * zero.get("K_max", 0))
          << std::endl;

  // With frictionless contact the compressive half is solved: the straight
  // crack's lips close (K_I,min = 0: closed at the tips, rather than a
  // negative K_I clamped) and slide (K_II,min = -K_II,max): at the first
  // step the same Delta K, to the penalty's error. (Once the crack has
  // kinked, its closed lips carry the normal stress and change its mode II
  // under compression: the later steps differ, as they should.)
  const auto   contact = run(" set Load ratio = -1\n end\nsubsection Contact\n"
                             " set Formulation = penalty\n subsection Penalty\n"
                             "  set Penalty coefficient = 1e4\n end\n");
  const double first_step =
    std::abs(contact.get("delta_K", 0) / reversed.get("delta_K", 0) - 1);
  logfile << "R = -1 with contact: Newton steps of the minimum "
          << int(contact.get("minimum_newton_iterations", 0))
          << ", delta_K at step 0 within 0.5 % of the run without contact: "
          << yes(first_step < 5e-3) << std::endl;
}
