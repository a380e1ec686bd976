#ifndef xcrack_nonlinear_solver_h
#define xcrack_nonlinear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <utility>

namespace xcrack
{
  using namespace dealii;

  /**
   * The nonlinear driver of a load state's solve (`subsection Nonlinear
   * solver`): a semi-smooth (generalised) Newton method on all the
   * nonlinearities at once, as deal.II's step-42 solves contact with
   * plasticity, rather than Code_Aster's nesting of friction thresholds
   * (fixed point) around contact statuses (active set) around Newton.
   *
   * Why one loop: with the contact conditions written as nonsmooth
   * equations (a penalty's max(0, -gap), Alart and Curnier's or Hueber and
   * Wohlmuth's complementarity functions for multipliers and friction),
   * each Newton step updates statuses, slip directions and thresholds
   * together, and converges locally superlinearly; nesting pays a whole
   * inner loop for every outer update. Where a step's statuses match those
   * of the system it solved, a piecewise linear problem (frictionless
   * penalty contact) is solved exactly.
   *
   * Each step assembles the linearised system A(u_k) u_{k+1} = b(u_k) at
   * the current iterate (Assembly::Contribution) and solves it for the next
   * iterate. The solve has converged when an assembly at the new iterate
   * changes no status and its residual |b - A u| is below `Tolerance` times
   * |b|. A problem of linear terms only is converged after its first solve
   * (no second assembly: a linear scene costs one assembly and one solve).
   * When it does not converge in `Maximum iterations`, the run stops with a
   * NumericalError (exit status 3) that gives the residual and the statuses
   * still changing: never a silent cycle between two sets of statuses.
   */
  class NonlinearSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// What the driver needs of a problem, as callbacks.
    struct Problem
    {
      /// Assemble A and b at the current iterate (@p first: the iterate is
      /// the start, zero).
      std::function<void(const bool first)> assemble;
      /// Solve A u = b of the last assembly for the next iterate, which
      /// becomes the current one; returns the linear solver's iterations.
      std::function<unsigned int()> solve;
      /// (|b - A u|, |b|) of the last assembly at the current iterate, over
      /// the unknowns that are not constrained.
      std::function<std::pair<double, double>()> residual;
      /**
       * The statuses that the last assembly changed from those the current
       * iterate was solved with (contact: closed, open, stick, slip): their
       * number and a description of where for a message. Null: none ever.
       */
      std::function<std::pair<unsigned int, std::string>()> changed_statuses;
      /// Whether every term is linear (A and b do not depend on u).
      bool linear = true;
    };

    /// What a solve did.
    struct Result
    {
      /// Newton steps (solves of a linearised system).
      unsigned int iterations = 0;
      /// The linear solver's iterations, summed over the steps.
      unsigned int linear_iterations = 0;
      /// |b - A u| / |b| at the solution.
      double residual = 0;
    };

    /**
     * Solve @p problem; @p what names it in the message of a failure ("the
     * maximum load of step 3"). Throws NumericalError if it does not
     * converge.
     */
    Result
    solve(const Problem &problem, const std::string &what) const;

    /// Newton steps allowed per solve.
    unsigned int max_iterations = 30;
    /// |b - A u| / |b| at which a solve whose statuses settled stops.
    double tolerance = 1e-8;
  };
} // namespace xcrack

#endif
