#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <xcrack/linear_solver.h>

#include <stdexcept>

namespace xcrack
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry("Type",
                        "direct",
                        Patterns::Selection("direct|cg amg"),
                        "direct: parallel sparse LU (MUMPS); cg amg: "
                        "conjugate gradients with algebraic multigrid.");
      prm.declare_entry("Relative tolerance",
                        "1e-10",
                        Patterns::Double(0, 1),
                        "cg amg: stop when |r| < tolerance |b|.");
      prm.declare_entry("Maximum iterations",
                        "2000",
                        Patterns::Integer(1),
                        "cg amg: give up after this many iterations.");
    }
    prm.leave_subsection();
  }



  void
  LinearSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      type               = prm.get("Type");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
    }
    prm.leave_subsection();
  }



  unsigned int
  LinearSolver::solve(
    const TrilinosWrappers::SparseMatrix &matrix,
    TrilinosWrappers::MPI::Vector        &x,
    const TrilinosWrappers::MPI::Vector  &rhs,
    const std::vector<std::vector<bool>> &constant_modes) const
  {
    if (type == "direct")
      {
        SolverControl                  control(1, 0);
        TrilinosWrappers::SolverDirect solver(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        try
          {
            solver.solve(matrix, x, rhs);
          }
        catch (const std::exception &)
          {
            // MUMPS reports a (numerically) singular matrix as an Amesos
            // error code; say what that means for an xcrack run.
            throw std::runtime_error(
              "the direct solver failed: the stiffness matrix is singular. "
              "Check that the Dirichlet data fix every part of the body. "
              "With a crack this also happens when it passes exactly "
              "through mesh nodes or very close to them (the conditioning "
              "treatment of such cuts is not implemented yet): move the "
              "crack slightly.");
          }
        return 1;
      }

    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    data.constant_modes        = constant_modes;
    amg.initialize(matrix, data);

    SolverControl                           control(max_iterations,
                          relative_tolerance * rhs.l2_norm(),
                          false,
                          false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    cg.solve(matrix, x, rhs, amg);
    return control.last_step();
  }
} // namespace xcrack
