#ifndef xcrack_linear_solver_amg_krylov_h
#define xcrack_linear_solver_amg_krylov_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <xcrack/linear_solver/interface.h>

#include <memory>
#include <string>
#include <vector>

class Epetra_Export;

namespace xcrack
{
  namespace LinearSolver
  {
    /**
     * What the iterative solvers share: Trilinos ML algebraic multigrid with
     * the rigid translations as near-null space, on rows of their own on
     * several ranks (`Partition = balanced`), and a Krylov method that a
     * derived class supplies (iterate()).
     *
     * Why the rows move: the assembly shares the mesh by work
     * (`Parallel/Partition`), which leaves the rank with the front fewer
     * rows, while the cost of AMG and of a Krylov iteration follows each
     * rank's matrix entries. The matrix is moved to rows that give every
     * rank the same number of entries before AMG is set up, and the solution
     * moved back (doc/performance.md, "Two ranks").
     */
    template <int dim>
    class AmgKrylov : public Interface<dim>
    {
    public:
      AmgKrylov();
      ~AmgKrylov() override;

      /// Read the entries the iterative solvers share (declared by
      /// LinearSolver::declare_parameters()).
      void
      parse_parameters(ParameterHandler &prm) override;

      unsigned int
      solve(const System                        &system,
            TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &rhs) override;

      unsigned int
      solve_again(TrilinosWrappers::MPI::Vector       &x,
                  const TrilinosWrappers::MPI::Vector &rhs) override;

      void
      release() override;

      std::string
      iterative_method() const override;

      /// The matrix entries this rank held in the last solve (after
      /// `Partition = balanced` moved them): the balance of the solve.
      unsigned long long
      n_local_entries() const;

    protected:
      /**
       * Run the Krylov method on @p matrix x = @p rhs with @p control and
       * @p preconditioner; throws SolverControl::NoConvergence.
       */
      virtual void
      iterate(
        const TrilinosWrappers::SparseMatrix    &matrix,
        TrilinosWrappers::MPI::Vector           &x,
        const TrilinosWrappers::MPI::Vector     &rhs,
        SolverControl                           &control,
        const TrilinosWrappers::PreconditionAMG &preconditioner) const = 0;

      /// The method's name, for messages ("CG", "GMRES").
      virtual std::string
      method() const = 0;

    private:
      /// The Krylov method with the preconditioner of the last solve(), on
      /// the balanced rows if there are any (x and rhs are moved there and
      /// x back).
      unsigned int
      run(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &rhs) const;

      /// Set balanced_matrix and to_balanced from @p matrix (`Partition =
      /// balanced`); returns @p constant_modes on the balanced rows.
      std::vector<std::vector<bool>>
      balance_rows(const TrilinosWrappers::SparseMatrix &matrix,
                   const std::vector<std::vector<bool>> &constant_modes);

      /// "balanced" or "assembly".
      std::string  partition          = "balanced";
      double       relative_tolerance = 1e-10;
      unsigned int max_iterations     = 2000;

      /// What the last solve() leaves for solve_again().
      const TrilinosWrappers::SparseMatrix              *last_matrix = nullptr;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      /// `Partition = balanced`: the matrix on its balanced rows, and the
      /// map from the assembled rows to those (null where the rows stay).
      std::unique_ptr<TrilinosWrappers::SparseMatrix> balanced_matrix;
      std::unique_ptr<Epetra_Export>                  to_balanced;
    };
  } // namespace LinearSolver
} // namespace xcrack

#endif
