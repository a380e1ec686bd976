#ifndef xcrack_linear_solver_h
#define xcrack_linear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

class Amesos_Mumps;
class Epetra_Export;
class Epetra_LinearProblem;

namespace xcrack
{
  using namespace dealii;

  /**
   * The linear solver of the elasticity system (`subsection Linear solver`).
   *
   * - `direct` (default): MUMPS through Trilinos Amesos, distributed over
   *   the MPI ranks. Robust for the badly conditioned matrices of enriched
   *   spaces, and the reference for every other choice.
   * - `cg amg`: conjugate gradients preconditioned by Trilinos ML algebraic
   *   multigrid, with the rigid translations as near-null space. Memory
   *   scales linearly, so it is the choice for large uncracked or mildly
   *   enriched problems.
   *
   * On several ranks `cg amg` solves on rows of its own (`Partition =
   * balanced`). The assembly shares the mesh by work (`Parallel/Partition`),
   * which leaves the rank with the front fewer rows, while the cost of AMG
   * and CG follows each rank's matrix entries: the matrix is moved to rows
   * that give every rank the same number of entries before AMG is set up,
   * and the solution moved back (doc/performance.md, "Two ranks"). MUMPS
   * maps the factorization onto the ranks itself and reads the matrix as
   * assembled.
   *
   * The factorization (or the AMG hierarchy) of the last solve() is kept
   * until release() or the next solve(), so that further right-hand sides
   * with the same matrix (the dual problems of K's error estimate) cost a
   * substitution (or a preconditioned CG run) only.
   */
  class LinearSolver
  {
  public:
    LinearSolver();
    ~LinearSolver();

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Solve @p matrix x = @p rhs. @p constant_modes are the rigid
     * translations of the displacement space, one per component, on the
     * locally owned DoFs (AMG's near-null space). Returns the number
     * of iterations (1 for the direct solver). Throws if the iterative
     * solver does not converge.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const std::vector<std::vector<bool>> &constant_modes);

    /**
     * Solve the matrix of the last solve() (which must still exist,
     * unchanged) for another right-hand side @p rhs, reusing its
     * factorization or preconditioner. Returns the iterations.
     */
    unsigned int
    solve_again(TrilinosWrappers::MPI::Vector       &x,
                const TrilinosWrappers::MPI::Vector &rhs);

    /// Free what solve() kept for solve_again() (the factor is the largest
    /// object of a direct solve).
    void
    release();

    /// The matrix entries this rank held in the last cg amg solve (after
    /// `Partition = balanced` moved them): the balance of the solve.
    unsigned long long
    n_local_entries() const;

    std::string type = "direct";
    /// Fill-reducing ordering of the direct solver: "metis", "auto" or
    /// "pord".
    std::string ordering = "metis";
    /// cg amg on several ranks: "balanced" (rows moved so that each rank
    /// holds the same number of entries) or "assembly" (the rows each rank
    /// assembled).
    std::string  partition          = "balanced";
    double       relative_tolerance = 1e-10;
    unsigned int max_iterations     = 2000;

  private:
    /// MUMPS through Amesos, symmetric; std::runtime_error on failure.
    void
    solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                 TrilinosWrappers::MPI::Vector        &x,
                 const TrilinosWrappers::MPI::Vector  &rhs);

    /// CG with the preconditioner of the last solve(), on the balanced rows
    /// if there are any (x and rhs are moved there and x back).
    unsigned int
    solve_cg(TrilinosWrappers::MPI::Vector       &x,
             const TrilinosWrappers::MPI::Vector &rhs) const;

    /// Set balanced_matrix and to_balanced from @p matrix (`Partition =
    /// balanced`); returns @p constant_modes on the balanced rows.
    std::vector<std::vector<bool>>
    balance_rows(const TrilinosWrappers::SparseMatrix &matrix,
                 const std::vector<std::vector<bool>> &constant_modes);

    /// What the last solve() leaves for solve_again().
    const TrilinosWrappers::SparseMatrix              *last_matrix = nullptr;
    std::unique_ptr<Epetra_LinearProblem>              problem;
    std::unique_ptr<Amesos_Mumps>                      factorization;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    /// `Partition = balanced`: the matrix on its balanced rows, and the map
    /// from the assembled rows to those (null where the rows stay).
    std::unique_ptr<TrilinosWrappers::SparseMatrix> balanced_matrix;
    std::unique_ptr<Epetra_Export>                  to_balanced;
  };
} // namespace xcrack

#endif
