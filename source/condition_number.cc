#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <xcrack/condition_number.h>

#include <cmath>
#include <limits>
#include <vector>

namespace xcrack
{
  double
  condition_number(const TrilinosWrappers::SparseMatrix &matrix,
                   const AffineConstraints<double>      &constraints)
  {
    if (Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()) > 1)
      return std::numeric_limits<double>::quiet_NaN();

    // Number the free DoFs consecutively.
    const unsigned int        n = matrix.m();
    std::vector<unsigned int> free_index(n);
    unsigned int              n_free = 0;
    for (unsigned int i = 0; i < n; ++i)
      free_index[i] = constraints.is_constrained(i) ?
                        numbers::invalid_unsigned_int :
                        n_free++;

    LAPACKFullMatrix<double> dense(n_free, n_free);
    for (auto entry = matrix.begin(); entry != matrix.end(); ++entry)
      {
        const unsigned int r = free_index[entry->row()];
        const unsigned int c = free_index[entry->column()];
        if (r != numbers::invalid_unsigned_int &&
            c != numbers::invalid_unsigned_int)
          dense(r, c) = entry->value();
      }
    dense.compute_eigenvalues();

    double lambda_min = std::numeric_limits<double>::max(), lambda_max = 0;
    for (unsigned int i = 0; i < n_free; ++i)
      {
        const double lambda = std::abs(dense.eigenvalue(i));
        lambda_min          = std::min(lambda_min, lambda);
        lambda_max          = std::max(lambda_max, lambda);
      }
    return lambda_max / lambda_min;
  }
} // namespace xcrack
