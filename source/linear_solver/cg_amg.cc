#include <deal.II/lac/solver_cg.h>

#include <xcrack/linear_solver/cg_amg.h>

namespace xcrack
{
  namespace LinearSolver
  {
    template <int dim>
    bool
    CgAmg<dim>::accepts(const MatrixProperty property) const
    {
      return property == MatrixProperty::spd;
    }



    template <int dim>
    void
    CgAmg<dim>::iterate(
      const TrilinosWrappers::SparseMatrix    &matrix,
      TrilinosWrappers::MPI::Vector           &x,
      const TrilinosWrappers::MPI::Vector     &rhs,
      SolverControl                           &control,
      const TrilinosWrappers::PreconditionAMG &preconditioner) const
    {
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.solve(matrix, x, rhs, preconditioner);
    }



    template <int dim>
    std::string
    CgAmg<dim>::method() const
    {
      return "CG";
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           CgAmg,
                           "cg amg",
                           "conjugate gradients with algebraic multigrid, "
                           "for symmetric positive definite systems (no "
                           "Lagrange multipliers, no friction).")
  } // namespace LinearSolver
} // namespace xcrack
