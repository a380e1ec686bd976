#ifndef xcrack_linear_solver_cg_amg_h
#define xcrack_linear_solver_cg_amg_h

#include <xcrack/linear_solver/amg_krylov.h>

namespace xcrack
{
  namespace LinearSolver
  {
    /**
     * `cg amg`: conjugate gradients preconditioned by algebraic multigrid.
     * Memory scales linearly with the DoFs, so it is the choice for large
     * symmetric positive definite systems (uncracked or mildly enriched
     * bodies, penalty contact); CG needs a definite symmetric matrix and
     * refuses the others.
     */
    template <int dim>
    class CgAmg : public AmgKrylov<dim>
    {
    public:
      bool
      accepts(const MatrixProperty property) const override;

    protected:
      void
      iterate(
        const TrilinosWrappers::SparseMatrix    &matrix,
        TrilinosWrappers::MPI::Vector           &x,
        const TrilinosWrappers::MPI::Vector     &rhs,
        SolverControl                           &control,
        const TrilinosWrappers::PreconditionAMG &preconditioner) const override;

      std::string
      method() const override;
    };
  } // namespace LinearSolver
} // namespace xcrack

#endif
