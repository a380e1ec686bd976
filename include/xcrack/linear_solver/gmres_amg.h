#ifndef xcrack_linear_solver_gmres_amg_h
#define xcrack_linear_solver_gmres_amg_h

#include <xcrack/linear_solver/amg_krylov.h>

namespace xcrack
{
  namespace LinearSolver
  {
    /**
     * `gmres amg`: restarted GMRES preconditioned by the same algebraic
     * multigrid as `cg amg`. For the unsymmetric tangents of Coulomb
     * friction on large 3D runs, where a direct solver's factors do not fit:
     * the friction terms live on the lips only, so the matrix stays close to
     * the elasticity one that AMG handles. A saddle point (Lagrange
     * multipliers, zeros on the diagonal) defeats AMG's smoothers: refused.
     */
    template <int dim>
    class GmresAmg : public AmgKrylov<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

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

    private:
      /// Krylov vectors kept before a restart.
      unsigned int restart = 100;
    };
  } // namespace LinearSolver
} // namespace xcrack

#endif
