#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <xcrack/linear_solver.h>

#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>
#include <stdexcept>

namespace xcrack
{
  LinearSolver::LinearSolver() = default;

  LinearSolver::~LinearSolver() = default;



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
      prm.declare_entry(
        "Direct solver ordering",
        "auto",
        Patterns::Selection("auto|pord"),
        "Fill-reducing ordering of MUMPS. auto: MUMPS's choice (approximate "
        "minimum degree on the problems measured); pord: nested dissection "
        "(the MUMPS reached through Amesos here has neither METIS nor "
        "SCOTCH). On the fifth mesh of sif_penny_3d.prm pord cut the "
        "factorisation flops by 42 % and the factor by 24 %: worth it for "
        "large 3D problems, where memory decides what fits.");
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
      ordering           = prm.get("Direct solver ordering");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
    }
    prm.leave_subsection();
  }



  void
  LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &rhs)
  {
    // Amesos directly rather than deal.II's SolverDirect: MUMPS needs its
    // parameters set. The matrix is symmetric positive definite (the
    // constraints are condensed symmetrically): an LDL^T factorisation of
    // one triangle halves time and memory. MUMPS estimates its workspace
    // before factorising, and enriched matrices (dense blocks at the front)
    // can exceed the estimate (INFOG(1) = -9): retry with more room, in
    // steps of two (a larger request may not be allocatable at all, -13).
    problem = std::make_unique<Epetra_LinearProblem>(
      const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()),
      &x.trilinos_vector(),
      const_cast<Epetra_MultiVector *>(
        static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
    int error = 0, info = 0;
    for (int relaxation = 100; relaxation <= 1600; relaxation *= 2)
      {
        factorization = std::make_unique<Amesos_Mumps>(*problem);
        factorization->SetICNTL(14, relaxation);
        factorization->SetICNTL(4, 0); // MUMPS prints nothing; we report
        if (ordering == "pord")
          factorization->SetICNTL(7, 4);
        Teuchos::ParameterList parameters;
        parameters.set("MatrixProperty", "SPD");
        factorization->SetParameters(parameters);
        error = factorization->SymbolicFactorization();
        if (error == 0)
          error = factorization->NumericFactorization();
        if (error == 0)
          error = factorization->Solve();
        info = factorization->GetINFOG()[0];
        if (error == 0 || info != -9)
          break;
      }
    if (error == 0)
      return;
    factorization.reset();
    if (info == -10)
      throw std::runtime_error(
        "the direct solver failed: the stiffness matrix is singular. "
        "Check that the Dirichlet data fix every part of the body. With a "
        "crack, supports cut very close to a node can do this: raise "
        "Enrichment/Heaviside volume tolerance.");
    throw std::runtime_error(
      "the direct solver (MUMPS) failed with INFOG(1) = " +
      std::to_string(info) +
      (info == -9 || info == -8 || info == -13 || info == -19 ?
         ": it ran out of memory; use fewer cells or Linear solver/Type = "
         "cg amg." :
         "; see the MUMPS manual."));
  }



  unsigned int
  LinearSolver::solve_cg(TrilinosWrappers::MPI::Vector       &x,
                         const TrilinosWrappers::MPI::Vector &rhs) const
  {
    SolverControl                           control(max_iterations,
                          relative_tolerance * rhs.l2_norm(),
                          false,
                          false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    cg.solve(*last_matrix, x, rhs, *amg);
    return control.last_step();
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &rhs,
                      const std::vector<std::vector<bool>> &constant_modes)
  {
    release();
    last_matrix = &matrix;
    // A failed solve keeps nothing (what it kept would refer to a matrix
    // that may be gone when this object is).
    try
      {
        if (type == "direct")
          {
            solve_direct(matrix, x, rhs);
            return 1;
          }

        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        data.constant_modes        = constant_modes;
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, data);
        return solve_cg(x, rhs);
      }
    catch (...)
      {
        release();
        throw;
      }
  }



  unsigned int
  LinearSolver::solve_again(TrilinosWrappers::MPI::Vector       &x,
                            const TrilinosWrappers::MPI::Vector &rhs)
  {
    Assert(last_matrix != nullptr, ExcMessage("No solve() before."));
    if (type != "direct")
      return solve_cg(x, rhs);
    AssertThrow(factorization, ExcMessage("No factorization to reuse."));
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
    const int error = factorization->Solve();
    AssertThrow(error == 0,
                ExcMessage("the direct solver failed on a further "
                           "right-hand side (error " +
                           std::to_string(error) + ")."));
    return 1;
  }


  void
  LinearSolver::release()
  {
    factorization.reset();
    problem.reset();
    amg.reset();
    last_matrix = nullptr;
  }
} // namespace xcrack
