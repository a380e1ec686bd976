#ifndef xcrack_condition_number_h
#define xcrack_condition_number_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * The 2-norm condition number lambda_max / lambda_min of @p matrix
   * restricted to the DoFs that @p constraints leave free (the rows of
   * constrained DoFs only carry a placeholder diagonal). Dense eigenvalues:
   * meant for small problems, to measure how cuts close to nodes degrade an
   * enriched matrix. One MPI rank only (returns NaN otherwise).
   */
  double
  condition_number(const TrilinosWrappers::SparseMatrix &matrix,
                   const AffineConstraints<double>      &constraints);
} // namespace xcrack

#endif
