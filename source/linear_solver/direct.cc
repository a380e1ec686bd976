#include <deal.II/base/mpi.h>

#include <xcrack/linear_solver/direct.h>

#include <Amesos_Mumps.h>
#include <Epetra_CrsMatrix.h>
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
  namespace LinearSolver
  {
    namespace
    {
      /**
       * Holds back what is written to std::cerr while it lives. Amesos_Mumps
       * writes "Amesos_Mumps : ERROR" there whenever MUMPS returns an error,
       * also for the workspace shortfalls that solve() retries with more
       * room: a run that recovered would print errors, and one that did not
       * says what failed in its exception.
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



    template <int dim>
    Direct<dim>::Direct() = default;

    template <int dim>
    Direct<dim>::~Direct() = default;



    template <int dim>
    void
    Direct<dim>::declare_parameters(ParameterHandler &prm)
    {
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
    }



    template <int dim>
    void
    Direct<dim>::parse_parameters(ParameterHandler &prm)
    {
      ordering = prm.get("Direct solver ordering");
    }



    template <int dim>
    bool
    Direct<dim>::accepts(const MatrixProperty) const
    {
      return true;
    }



    template <int dim>
    std::string
    Direct<dim>::iterative_method() const
    {
      return "";
    }



    template <int dim>
    unsigned int
    Direct<dim>::solve(const System                        &system,
                       TrilinosWrappers::MPI::Vector       &x,
                       const TrilinosWrappers::MPI::Vector &rhs)
    {
      release();
      // Amesos directly rather than deal.II's SolverDirect: MUMPS needs its
      // parameters set. MUMPS estimates its workspace before factorising,
      // and enriched matrices (dense blocks at the front) can exceed the
      // estimate (INFOG(1) = -9): retry with more room, in steps of two (a
      // larger request may not be allocatable at all, -13).
      problem = std::make_unique<Epetra_LinearProblem>(
        const_cast<Epetra_CrsMatrix *>(&system.matrix.trilinos_matrix()),
        &x.trilinos_vector(),
        const_cast<Epetra_MultiVector *>(
          static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
      // The ordering once: the retries below factorise the same matrix.
      const std::vector<int> permutation =
        (ordering == "metis" ? metis_ordering(system.matrix.trilinos_matrix()) :
                               std::vector<int>());
      const char *property =
        (system.property == MatrixProperty::spd       ? "SPD" :
         system.property == MatrixProperty::symmetric ? "symmetric" :
                                                        "general");
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
                factorization->SetOrdering(
                  const_cast<int *>(permutation.data()));
            }
          Teuchos::ParameterList parameters;
          parameters.set("MatrixProperty", property);
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
        return 1;
      release();
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



    template <int dim>
    unsigned int
    Direct<dim>::solve_again(TrilinosWrappers::MPI::Vector       &x,
                             const TrilinosWrappers::MPI::Vector &rhs)
    {
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



    template <int dim>
    void
    Direct<dim>::release()
    {
      factorization.reset();
      problem.reset();
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Direct,
                           "direct",
                           "parallel sparse LU or LDL^T (MUMPS), for every "
                           "kind of system.")
  } // namespace LinearSolver
} // namespace xcrack
