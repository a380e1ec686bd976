#include <xcrack/input_error.h>
#include <xcrack/nonlinear_solver.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

namespace xcrack
{
  void
  NonlinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    {
      prm.declare_entry("Maximum iterations",
                        "30",
                        Patterns::Integer(1),
                        "Newton steps allowed per load state. A solve that "
                        "needs more stops the run (exit status 3) with the "
                        "residual and the statuses still changing. Scenes "
                        "without contact are linear: one step.");
      prm.declare_entry("Tolerance",
                        "1e-8",
                        Patterns::Double(0, 1),
                        "A solve has converged when an assembly at its "
                        "iterate changes no contact status and the residual "
                        "|b - A u| is below this times |b|.");
    }
    prm.leave_subsection();
  }



  void
  NonlinearSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    max_iterations = prm.get_integer("Maximum iterations");
    tolerance      = prm.get_double("Tolerance");
    prm.leave_subsection();
  }



  NonlinearSolver::Result
  NonlinearSolver::solve(const Problem &problem, const std::string &what) const
  {
    const auto relative = [](const std::pair<double, double> &norms) {
      return (norms.second > 0 ? norms.first / norms.second :
              norms.first > 0  ? std::numeric_limits<double>::infinity() :
                                 0.);
    };
    Result result;
    problem.assemble(true);
    while (true)
      {
        result.linear_iterations += problem.solve();
        ++result.iterations;
        if (problem.linear)
          {
            result.residual = relative(problem.residual());
            return result;
          }
        problem.assemble(false);
        const auto [changed, where] =
          (problem.changed_statuses ? problem.changed_statuses() :
                                      std::make_pair(0u, std::string()));
        result.residual = relative(problem.residual());
        if (changed == 0 && result.residual <= tolerance)
          return result;
        if (result.iterations >= max_iterations)
          {
            std::ostringstream message;
            message << "the Newton iterations of " << what
                    << " did not converge in " << max_iterations
                    << " steps (Nonlinear solver/Maximum iterations): "
                    << "residual " << std::scientific << std::setprecision(2)
                    << result.residual << " of the load (Tolerance "
                    << tolerance << ")";
            if (changed > 0)
              message << ", " << changed << " statuses still changing"
                      << (where.empty() ? "" : " (" + where + ")");
            message << ". A penalty coefficient far above the material's "
                       "stiffness, or a load that opens and closes the same "
                       "lips back and forth, can do this.";
            throw NumericalError(message.str());
          }
      }
  }
} // namespace xcrack
