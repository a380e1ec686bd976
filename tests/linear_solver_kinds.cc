// Requirement: the linear solvers (Linear solver/Type) solve the kinds of
// system they accept and say which they refuse: `direct` (MUMPS) takes a
// symmetric positive definite system, a symmetric saddle point (Lagrange
// multipliers: zeros on the diagonal) and an unsymmetric one (the tangent
// of friction), each to round-off; `cg amg` only the definite one;
// `gmres amg` the definite and the unsymmetric ones, not the saddle
// point. A second right-hand side reuses the factorisation or the
// preconditioner (solve_again()).

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/linear_solver/interface.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>

using namespace dealii;
using namespace xcrack::LinearSolver;

std::ofstream logfile;

// A string of n nodes (tridiagonal, plus a little of the identity), with,
// for the saddle point, m multipliers that hold every (n / m)-th node at a
// value, and, for the unsymmetric kind, a convection-like skew part.
constexpr unsigned int n = 60, m = 6;

void
fill(const MatrixProperty            kind,
     TrilinosWrappers::SparseMatrix &matrix,
     TrilinosWrappers::MPI::Vector  &rhs)
{
  const unsigned int size = n + (kind == MatrixProperty::symmetric ? m : 0);
  IndexSet           all(size);
  all.add_range(0, size);
  DynamicSparsityPattern                                  dsp(size, size);
  std::map<std::pair<unsigned int, unsigned int>, double> entries;
  for (unsigned int i = 0; i < n; ++i)
    {
      entries[{i, i}] = 2.01;
      if (i + 1 < n)
        {
          const double skew   = (kind == MatrixProperty::general ? 0.4 : 0.);
          entries[{i, i + 1}] = -1 + skew;
          entries[{i + 1, i}] = -1 - skew;
        }
    }
  if (kind == MatrixProperty::symmetric)
    for (unsigned int k = 0; k < m; ++k)
      {
        entries[{n + k, k * (n / m) + 3}] = 1;
        entries[{k * (n / m) + 3, n + k}] = 1;
      }
  for (const auto &[ij, value] : entries)
    dsp.add(ij.first, ij.second);
  matrix.reinit(all, all, dsp, MPI_COMM_WORLD);
  for (const auto &[ij, value] : entries)
    matrix.set(ij.first, ij.second, value);
  matrix.compress(VectorOperation::insert);
  rhs.reinit(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < size; ++i)
    rhs[i] = (i < n ? std::sin(0.3 * i) : 0.1 * (i - n));
  rhs.compress(VectorOperation::insert);
}

double
relative_residual(const TrilinosWrappers::SparseMatrix &matrix,
                  const TrilinosWrappers::MPI::Vector  &x,
                  const TrilinosWrappers::MPI::Vector  &rhs)
{
  TrilinosWrappers::MPI::Vector r(rhs);
  matrix.vmult(r, x);
  r -= rhs;
  return r.l2_norm() / rhs.l2_norm();
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  logfile.open("output");
  for (const std::string name : {"direct", "cg amg", "gmres amg"})
    {
      ParameterHandler prm;
      declare_parameters(prm);
      prm.set("Type", name);
      prm.set("Relative tolerance", "1e-12");
      auto solver =
        xcrack::Plugins::PluginList<Interface<2>>::create(name, "Type");
      solver->parse_parameters(prm);
      for (const MatrixProperty kind : {MatrixProperty::spd,
                                        MatrixProperty::symmetric,
                                        MatrixProperty::general})
        {
          logfile << name << ", " << to_string(kind) << ": ";
          if (!solver->accepts(kind))
            {
              logfile << "refused" << std::endl;
              continue;
            }
          TrilinosWrappers::SparseMatrix matrix;
          TrilinosWrappers::MPI::Vector  rhs;
          fill(kind, matrix, rhs);
          const System                  system{matrix, kind, [&]() {
                                return std::vector<std::vector<bool>>(
                                  1, std::vector<bool>(rhs.size(), true));
                              }};
          TrilinosWrappers::MPI::Vector x(rhs), y(rhs), other(rhs);
          x = 0;
          y = 0;
          for (unsigned int i = 0; i < other.size(); ++i)
            other[i] = (i % 7 == 0 ? 1. : 0.);
          other.compress(VectorOperation::insert);
          solver->solve(system, x, rhs);
          solver->solve_again(y, other);
          logfile << "residuals below 1e-10: "
                  << (relative_residual(matrix, x, rhs) < 1e-10 &&
                          relative_residual(matrix, y, other) < 1e-10 ?
                        "yes" :
                        "NO")
                  << std::endl;
          solver->release();
        }
    }
}
