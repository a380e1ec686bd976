// Requirement: the nonlinear driver (NonlinearSolver) solves a problem of
// linear terms by one step, a piecewise linear one (a string pressed onto
// an obstacle by a penalty, the kind of problem frictionless penalty
// contact is) by a semi-smooth Newton whose last step changes no status and
// leaves a residual below the tolerance, to the solution of the final
// active set exactly; and a solve that needs more steps than allowed stops
// with a NumericalError that gives the residual and the number of statuses
// still changing, rather than cycling silently.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <xcrack/input_error.h>
#include <xcrack/nonlinear_solver.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <vector>

using namespace dealii;

std::ofstream logfile("output");

// A string of n unknowns (tridiagonal stiffness) under a uniform load
// pushing it down onto an obstacle at -gap, held by a penalty k:
// A u - k max(0, -gap - u) = f. Newton's step for the next iterate: the
// points below the obstacle (the active set) get k on the diagonal and
// -k gap on the right-hand side.
struct String
{
  unsigned int       n = 40;
  double             k = 1e4, gap = 0.02, load = -1;
  Vector<double>     u, b;
  FullMatrix<double> a;
  std::vector<bool>  active, solved_with;

  xcrack::NonlinearSolver::Problem
  problem()
  {
    u.reinit(n);
    active.assign(n, false);
    xcrack::NonlinearSolver::Problem p;
    p.linear   = (k == 0);
    p.assemble = [this](const bool first) {
      if (first)
        u = 0;
      a.reinit(n, n);
      b.reinit(n);
      const double h = 1. / (n + 1);
      for (unsigned int i = 0; i < n; ++i)
        {
          a(i, i) = 2 / h;
          if (i > 0)
            a(i, i - 1) = -1 / h;
          if (i + 1 < n)
            a(i, i + 1) = -1 / h;
          b(i)      = load * h;
          active[i] = (k > 0 && u(i) < -gap);
          if (active[i])
            {
              a(i, i) += k;
              b(i) -= k * gap;
            }
        }
    };
    p.solve = [this]() {
      FullMatrix<double> inverse(n, n);
      inverse.invert(a);
      inverse.vmult(u, b);
      solved_with = active;
      return 1u;
    };
    p.residual = [this]() {
      Vector<double> r(n);
      a.vmult(r, u);
      r -= b;
      return std::make_pair(r.l2_norm(), b.l2_norm());
    };
    p.changed_statuses = [this]() {
      unsigned int changed = 0;
      for (unsigned int i = 0; i < n; ++i)
        changed += (active[i] != solved_with[i]);
      return std::make_pair(changed, std::string("on the string"));
    };
    return p;
  }
};

int
main()
{
  xcrack::NonlinearSolver driver;
  driver.max_iterations = 30;
  driver.tolerance      = 1e-10;

  // Linear (no obstacle): one step.
  {
    String s;
    s.k            = 0;
    const auto res = driver.solve(s.problem(), "the string");
    logfile << "linear: " << res.iterations << " step, residual below 1e-12: "
            << (res.residual < 1e-12 ? "yes" : "NO") << std::endl;
  }

  // The obstacle: statuses settle, and the last active set's system is
  // solved exactly.
  String       s;
  const auto   res      = driver.solve(s.problem(), "the string");
  unsigned int n_active = 0;
  double       lowest   = 0;
  for (unsigned int i = 0; i < s.n; ++i)
    {
      n_active += s.active[i];
      lowest = std::min(lowest, s.u(i));
    }
  logfile << "obstacle: " << res.iterations << " steps, " << n_active << " of "
          << s.n << " points on the obstacle, residual below "
          << "1e-10: " << (res.residual < 1e-10 ? "yes" : "NO") << std::endl;
  // The penalty lets a point sink by about its load over k below the gap.
  logfile << std::scientific << std::setprecision(3)
          << "lowest point below the obstacle by " << -(lowest + s.gap)
          << " (load h / k = " << -s.load / (s.n + 1) / s.k << ")" << std::endl;

  // Too few steps allowed: a clear stop.
  driver.max_iterations = 2;
  try
    {
      String t;
      driver.solve(t.problem(), "the string");
      logfile << "NO error with 2 steps" << std::endl;
    }
  catch (const xcrack::NumericalError &e)
    {
      logfile << "with 2 steps: " << e.what() << std::endl;
    }
}
