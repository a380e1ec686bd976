#include <deal.II/lac/solver_gmres.h>

#include <xcrack/linear_solver/gmres_amg.h>

namespace xcrack
{
  namespace LinearSolver
  {
    template <int dim>
    void
    GmresAmg<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("GMRES restart",
                        "100",
                        Patterns::Integer(2),
                        "gmres amg: the Krylov vectors kept before a restart "
                        "(memory: that many vectors of the system's size).");
    }



    template <int dim>
    void
    GmresAmg<dim>::parse_parameters(ParameterHandler &prm)
    {
      AmgKrylov<dim>::parse_parameters(prm);
      restart = prm.get_integer("GMRES restart");
    }



    template <int dim>
    bool
    GmresAmg<dim>::accepts(const MatrixProperty property) const
    {
      return property != MatrixProperty::symmetric;
    }



    template <int dim>
    void
    GmresAmg<dim>::iterate(
      const TrilinosWrappers::SparseMatrix    &matrix,
      TrilinosWrappers::MPI::Vector           &x,
      const TrilinosWrappers::MPI::Vector     &rhs,
      SolverControl                           &control,
      const TrilinosWrappers::PreconditionAMG &preconditioner) const
    {
      typename SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data;
      data.max_n_tmp_vectors = restart + 2;
      // Right preconditioning: the residual the control tests is the true
      // one, as for CG.
      data.right_preconditioning = true;
      SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(control, data);
      gmres.solve(matrix, x, rhs, preconditioner);
    }



    template <int dim>
    std::string
    GmresAmg<dim>::method() const
    {
      return "GMRES";
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           GmresAmg,
                           "gmres amg",
                           "restarted GMRES with algebraic multigrid, for "
                           "symmetric positive definite and unsymmetric "
                           "(friction) systems; not for saddle points.")
  } // namespace LinearSolver
} // namespace xcrack
