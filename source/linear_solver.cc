#include <deal.II/base/mpi.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <xcrack/linear_solver.h>

#include <Amesos_Mumps.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Export.h>
#include <Epetra_IntVector.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <iostream>
#include <metis.h>
#include <sstream>
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
        "metis",
        Patterns::Selection("metis|auto|pord"),
        "Fill-reducing ordering of MUMPS. metis: METIS nested dissection of "
        "the matrix graph, computed by xcrack on the first rank and handed "
        "to MUMPS (the MUMPS of Debian has neither METIS nor SCOTCH inside); "
        "auto: MUMPS's own choice (PORD on the 3D problems measured, "
        "approximate minimum degree on small ones); pord: PORD always. "
        "metis and PORD give about the same factor; metis orders in a "
        "fraction of PORD's time, which MUMPS spends on one rank "
        "(doc/performance.md, \"The ordering of the direct solver\").");
      prm.declare_entry(
        "Partition",
        "balanced",
        Patterns::Selection("balanced|assembly"),
        "cg amg on several MPI ranks: which rows each rank solves. "
        "balanced: the matrix is moved so that every rank holds the same "
        "number of its entries (the cost of AMG and of CG); assembly: the "
        "rows each rank assembled, which Parallel/Partition = work makes "
        "uneven (the rank with the front has fewer rows). The direct "
        "solver ignores it.");
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
      partition          = prm.get("Partition");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /**
     * Holds back what is written to std::cerr while it lives. Amesos_Mumps
     * writes "Amesos_Mumps : ERROR" there whenever MUMPS returns an error,
     * also for the workspace shortfalls that solve_direct() retries with
     * more room: a run that recovered would print errors, and one that did
     * not says what failed in its exception.
     */
    class HeldBackErrors
    {
    public:
      HeldBackErrors()
        : previous(std::cerr.rdbuf(held.rdbuf()))
      {}
      ~HeldBackErrors()
      {
        std::cerr.rdbuf(previous);
      }

    private:
      std::ostringstream held;
      std::streambuf    *previous;
    };



    /**
     * METIS nested dissection of the graph of @p matrix, as MUMPS's
     * PERM_IN (the 1-based position of each row in the pivot order), on
     * rank 0 of its communicator, MUMPS's host; empty on the other ranks.
     * The rows' column lists are gathered there: the ordering is a
     * sequential computation in MUMPS too (its analysis phase), and METIS
     * does it in a fraction of the time PORD takes.
     */
    std::vector<int>
    metis_ordering(const Epetra_CrsMatrix &matrix)
    {
      const MPI_Comm comm =
        dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm();
      // Per owned row: its global index, the number of its off-diagonal
      // columns, their global indices.
      std::vector<int> rows;
      for (int i = 0; i < matrix.NumMyRows(); ++i)
        {
          int     n;
          double *values;
          int    *columns;
          matrix.ExtractMyRowView(i, n, values, columns);
          const int row = matrix.GRID(i);
          rows.push_back(row);
          const std::size_t count = rows.size();
          rows.push_back(0);
          for (int k = 0; k < n; ++k)
            if (matrix.GCID(columns[k]) != row)
              {
                rows.push_back(matrix.GCID(columns[k]));
                ++rows[count];
              }
        }
      const std::vector<std::vector<int>> all =
        dealii::Utilities::MPI::gather(comm, rows, 0);
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return {};

      // The symmetric adjacency (both directions of every entry: METIS
      // needs a symmetric graph, and a constrained row may hold only its
      // diagonal while its column is not empty), in CSR form.
      const idx_t                     n_rows = matrix.NumGlobalRows();
      std::vector<std::vector<idx_t>> adjacency(n_rows);
      for (const std::vector<int> &part : all)
        for (std::size_t p = 0; p < part.size(); p += 2 + part[p + 1])
          for (int k = 0; k < part[p + 1]; ++k)
            {
              adjacency[part[p]].push_back(part[p + 2 + k]);
              adjacency[part[p + 2 + k]].push_back(part[p]);
            }
      std::vector<idx_t> offsets(n_rows + 1, 0), neighbours;
      for (idx_t i = 0; i < n_rows; ++i)
        {
          std::vector<idx_t> &list = adjacency[i];
          std::sort(list.begin(), list.end());
          list.erase(std::unique(list.begin(), list.end()), list.end());
          neighbours.insert(neighbours.end(), list.begin(), list.end());
          offsets[i + 1] = neighbours.size();
          std::vector<idx_t>().swap(list);
        }
      std::vector<idx_t> permutation(n_rows), inverse(n_rows);
      idx_t              options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      idx_t n = n_rows;
      if (METIS_NodeND(&n,
                       offsets.data(),
                       neighbours.data(),
                       nullptr,
                       options,
                       permutation.data(),
                       inverse.data()) != METIS_OK)
        throw std::runtime_error("METIS could not order the matrix; use "
                                 "Linear solver/Direct solver ordering = "
                                 "auto.");
      std::vector<int> perm_in(n_rows);
      for (idx_t i = 0; i < n_rows; ++i)
        perm_in[i] = inverse[i] + 1;
      return perm_in;
    }
  } // namespace



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
    // The ordering once: the retries below factorise the same matrix.
    const std::vector<int> permutation =
      (ordering == "metis" ? metis_ordering(matrix.trilinos_matrix()) :
                             std::vector<int>());
    int                  error = 0, info = 0;
    const HeldBackErrors quiet;
    for (int relaxation = 100; relaxation <= 1600; relaxation *= 2)
      {
        factorization = std::make_unique<Amesos_Mumps>(*problem);
        factorization->SetICNTL(14, relaxation);
        factorization->SetICNTL(4, 0); // MUMPS prints nothing; we report
        if (ordering == "pord")
          factorization->SetICNTL(7, 4);
        else if (ordering == "metis")
          {
            factorization->SetICNTL(7, 1);
            // MUMPS reads the permutation on its host only.
            if (!permutation.empty())
              factorization->SetOrdering(const_cast<int *>(permutation.data()));
          }
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
    if (!balanced_matrix)
      {
        cg.solve(*last_matrix, x, rhs, *amg);
        return control.last_step();
      }
    const MPI_Comm  comm = x.get_mpi_communicator();
    const IndexSet &rows = balanced_matrix->locally_owned_range_indices();
    TrilinosWrappers::MPI::Vector balanced_x(rows, comm),
      balanced_rhs(rows, comm);
    balanced_x.trilinos_vector().Export(x.trilinos_vector(),
                                        *to_balanced,
                                        Insert);
    balanced_rhs.trilinos_vector().Export(rhs.trilinos_vector(),
                                          *to_balanced,
                                          Insert);
    cg.solve(*balanced_matrix, balanced_x, balanced_rhs, *amg);
    // The export's reverse: each assembled row from its balanced owner.
    x.trilinos_vector().Import(balanced_x.trilinos_vector(),
                               *to_balanced,
                               Insert);
    return control.last_step();
  }



  std::vector<std::vector<bool>>
  LinearSolver::balance_rows(
    const TrilinosWrappers::SparseMatrix &matrix,
    const std::vector<std::vector<bool>> &constant_modes)
  {
    // The rows in the order of the ranks, then of each rank's rows (for
    // deal.II's DoF numbering, ascending): rank p receives those whose
    // entries start in the p-th share of all entries.
    const Epetra_CrsMatrix &assembled = matrix.trilinos_matrix();
    const MPI_Comm          comm      = matrix.get_mpi_communicator();
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned long long mine   = assembled.NumMyNonzeros();
    unsigned long long       before = 0, total = 0;
    MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      before = 0; // MPI_Exscan leaves the first rank's result undefined
    MPI_Allreduce(&mine, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    std::map<unsigned int, std::vector<types::global_dof_index>> send;
    for (int i = 0; i < assembled.NumMyRows(); ++i)
      {
        const unsigned int rank = static_cast<unsigned int>(
          std::min<unsigned long long>(n_ranks - 1, before * n_ranks / total));
        send[rank].push_back(assembled.GRID(i));
        before += assembled.NumMyEntries(i);
      }
    IndexSet balanced_rows(matrix.m());
    for (const auto &[rank, rows] :
         dealii::Utilities::MPI::some_to_some(comm, send))
      balanced_rows.add_indices(rows.begin(), rows.end());
    balanced_rows.compress();

    const Epetra_Map rows = balanced_rows.make_trilinos_map(comm, false);
    to_balanced = std::make_unique<Epetra_Export>(assembled.RowMap(), rows);
    // Row lengths first: a matrix that knows them takes its entries
    // without reallocating (half the time of FillComplete()).
    Epetra_IntVector lengths(assembled.RowMap()), moved_lengths(rows);
    for (int i = 0; i < assembled.NumMyRows(); ++i)
      lengths[i] = assembled.NumMyEntries(i);
    moved_lengths.Export(lengths, *to_balanced, Insert);
    Epetra_CrsMatrix moved(Copy, rows, moved_lengths.Values(), true);
    moved.Export(assembled, *to_balanced, Insert);
    moved.FillComplete(rows, rows);
    balanced_matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    balanced_matrix->reinit(moved);

    // The near-null space moves with its rows.
    Epetra_MultiVector modes(assembled.RowMap(), constant_modes.size());
    for (unsigned int d = 0; d < constant_modes.size(); ++d)
      for (unsigned int i = 0; i < constant_modes[d].size(); ++i)
        modes[d][i] = constant_modes[d][i];
    Epetra_MultiVector moved_modes(rows, constant_modes.size());
    moved_modes.Export(modes, *to_balanced, Insert);
    std::vector<std::vector<bool>> balanced_modes(
      constant_modes.size(), std::vector<bool>(rows.NumMyElements()));
    for (unsigned int d = 0; d < constant_modes.size(); ++d)
      for (int i = 0; i < rows.NumMyElements(); ++i)
        balanced_modes[d][i] = (moved_modes[d][i] != 0);
    return balanced_modes;
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
        const bool balance =
          (partition == "balanced" && dealii::Utilities::MPI::n_mpi_processes(
                                        matrix.get_mpi_communicator()) > 1);
        data.constant_modes =
          (balance ? balance_rows(matrix, constant_modes) : constant_modes);
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(balance ? *balanced_matrix : matrix, data);
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


  unsigned long long
  LinearSolver::n_local_entries() const
  {
    Assert(last_matrix != nullptr, ExcMessage("No solve() before."));
    return (balanced_matrix ? *balanced_matrix : *last_matrix)
      .trilinos_matrix()
      .NumMyNonzeros();
  }



  void
  LinearSolver::release()
  {
    factorization.reset();
    problem.reset();
    amg.reset();
    balanced_matrix.reset();
    to_balanced.reset();
    last_matrix = nullptr;
  }
} // namespace xcrack
