// Requirement: CG + AMG on several ranks solves on rows balanced by matrix
// entries (Linear solver/Partition = balanced), not on the rows each rank
// assembled: Parallel/Partition = work leaves the rank with the front few,
// dense rows (on the penny, 33k rows and 1.2M entries against 65k and 2.7M).
// Here the first rank assembles a tenth of the rows of a graph Laplacian,
// the denser ones (the other rank holds 1.37 times the mean entries);
// balanced, the ranks hold the same entries to 1 %, and the solution and a
// second right-hand side (solve_again(), as the K error estimate's dual
// solves) are those of the assembled rows, in as many CG iterations to one
// (AMG's aggregates follow the rows). Two ranks.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/linear_solver/cg_amg.h>
#include <xcrack/linear_solver/interface.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <vector>

using namespace dealii;

std::ofstream logfile;

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

// A 60 x 50 grid, numbered row by row: its first 300 nodes are joined to
// their neighbours up to two steps away in x and y, the others to their
// four nearest. The graph Laplacian plus a small multiple of the identity
// (SPD, and AMG's kind of matrix).
constexpr unsigned int nx = 60, ny = 50, n = nx * ny, n_dense = 300;

std::vector<unsigned int>
neighbours(const unsigned int i)
{
  const int                 reach = (i < n_dense ? 2 : 1);
  const int                 x = i % nx, y = i / nx;
  std::vector<unsigned int> list;
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy)
      if ((dx == 0) != (dy == 0) || (reach == 2 && dx != 0 && dy != 0))
        if (x + dx >= 0 && x + dx < int(nx) && y + dy >= 0 && y + dy < int(ny))
          list.push_back((y + dy) * nx + x + dx);
  return list;
}

struct Solution
{
  std::vector<double> first, second;
  unsigned int        iterations_first, iterations_second;
  unsigned long long  entries;
};

Solution
solve(const std::string &partition, const MPI_Comm comm)
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  // The first rank owns a tenth of the rows.
  IndexSet owned(n);
  owned.add_range(rank == 0 ? 0 : n / 10, rank == 0 ? n / 10 : n);

  // Symmetric: an edge from a dense node is an edge of its neighbour too.
  std::vector<std::vector<unsigned int>> graph(n);
  for (unsigned int i = 0; i < n; ++i)
    for (const unsigned int j : neighbours(i))
      {
        graph[i].push_back(j);
        graph[j].push_back(i);
      }
  for (auto &list : graph)
    {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  DynamicSparsityPattern dsp(n, n, owned);
  for (const auto i : owned)
    {
      dsp.add(i, i);
      for (const unsigned int j : graph[i])
        dsp.add(i, j);
    }
  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(owned, owned, dsp, comm);
  TrilinosWrappers::MPI::Vector rhs(owned, comm), x(owned, comm);
  for (const auto i : owned)
    {
      matrix.set(i, i, graph[i].size() + 1e-2);
      for (const unsigned int j : graph[i])
        matrix.set(i, j, -1.);
      rhs[i] = std::sin(0.1 * i);
    }
  matrix.compress(VectorOperation::insert);
  rhs.compress(VectorOperation::insert);

  ParameterHandler prm;
  xcrack::LinearSolver::declare_parameters(prm);
  prm.set("Type", "cg amg");
  prm.set("Partition", partition);
  prm.set("Relative tolerance", "1e-12");
  xcrack::LinearSolver::CgAmg<2> solver;
  solver.parse_parameters(prm);
  const xcrack::LinearSolver::System system{
    matrix, xcrack::LinearSolver::MatrixProperty::spd, [&]() {
      return std::vector<std::vector<bool>>(
        1, std::vector<bool>(owned.n_elements(), true));
    }};
  Solution solution;
  solution.iterations_first = solver.solve(system, x, rhs);
  solution.entries          = solver.n_local_entries();
  // Gathered in the order of the ranks (the first owns the first rows).
  for (const auto &part :
       Utilities::MPI::all_gather(comm,
                                  std::vector<double>(x.begin(), x.end())))
    solution.first.insert(solution.first.end(), part.begin(), part.end());
  TrilinosWrappers::MPI::Vector other(owned, comm), y(owned, comm);
  for (const auto i : owned)
    other[i] = (i % 7 == 0 ? 1. : 0.);
  other.compress(VectorOperation::insert);
  solution.iterations_second = solver.solve_again(y, other);
  for (const auto &part :
       Utilities::MPI::all_gather(comm,
                                  std::vector<double>(y.begin(), y.end())))
    solution.second.insert(solution.second.end(), part.begin(), part.end());
  return solution;
}

// The largest rank's share over the mean share.
double
imbalance(const unsigned long long entries, const MPI_Comm comm)
{
  const std::vector<unsigned long long> all =
    Utilities::MPI::all_gather(comm, entries);
  const double total = std::accumulate(all.begin(), all.end(), 0.);
  return *std::max_element(all.begin(), all.end()) / (total / all.size());
}

double
difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double largest = 0, scale = 0;
  for (unsigned int i = 0; i < a.size(); ++i)
    {
      largest = std::max(largest, std::abs(a[i] - b[i]));
      scale   = std::max(scale, std::abs(a[i]));
    }
  return largest / scale;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    logfile.open("output");

  const Solution assembled = solve("assembly", comm);
  const Solution balanced  = solve("balanced", comm);
  logfile << std::fixed << std::setprecision(2)
          << "entries of the largest rank over the mean: assembled rows "
          << imbalance(assembled.entries, comm) << ", balanced rows <= 1.01: "
          << yes(imbalance(balanced.entries, comm) <= 1.01) << std::endl;
  logfile << "CG iterations, assembled and balanced rows: "
          << assembled.iterations_first << ", " << balanced.iterations_first
          << std::endl;
  logfile << "the same solution (to 1e-9 of its largest value): "
          << yes(difference(assembled.first, balanced.first) < 1e-9)
          << std::endl;
  logfile << "second right-hand side, iterations: "
          << assembled.iterations_second << ", " << balanced.iterations_second
          << "; the same solution: "
          << yes(difference(assembled.second, balanced.second) < 1e-9)
          << std::endl;
}
