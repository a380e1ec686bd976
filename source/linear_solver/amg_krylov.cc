#include <deal.II/base/mpi.h>

#include <deal.II/lac/solver_control.h>

#include <xcrack/linear_solver/amg_krylov.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Export.h>
#include <Epetra_IntVector.h>
#include <map>
#include <stdexcept>

namespace xcrack
{
  namespace LinearSolver
  {
    template <int dim>
    AmgKrylov<dim>::AmgKrylov() = default;

    template <int dim>
    AmgKrylov<dim>::~AmgKrylov() = default;



    template <int dim>
    void
    AmgKrylov<dim>::parse_parameters(ParameterHandler &prm)
    {
      partition          = prm.get("Partition");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
    }



    template <int dim>
    std::string
    AmgKrylov<dim>::iterative_method() const
    {
      return method();
    }



    template <int dim>
    unsigned int
    AmgKrylov<dim>::run(TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &rhs) const
    {
      SolverControl control(max_iterations,
                            relative_tolerance * rhs.l2_norm(),
                            false,
                            false);
      try
        {
          if (!balanced_matrix)
            {
              iterate(*last_matrix, x, rhs, control, *amg);
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
          iterate(*balanced_matrix, balanced_x, balanced_rhs, control, *amg);
          // The export's reverse: each assembled row from its balanced owner.
          x.trilinos_vector().Import(balanced_x.trilinos_vector(),
                                     *to_balanced,
                                     Insert);
          return control.last_step();
        }
      catch (const SolverControl::NoConvergence &e)
        {
          throw std::runtime_error(
            "the iterative solver (" + method() + " with AMG) did not " +
            "converge in " + std::to_string(e.last_step) +
            " iterations (Linear solver/Maximum iterations): residual " +
            std::to_string(e.last_residual) + " against the target " +
            std::to_string(control.tolerance()) +
            ". Use Linear solver/Type = direct, or allow more iterations.");
        }
    }



    template <int dim>
    std::vector<std::vector<bool>>
    AmgKrylov<dim>::balance_rows(
      const TrilinosWrappers::SparseMatrix &matrix,
      const std::vector<std::vector<bool>> &constant_modes)
    {
      // The rows in the order of the ranks, then of each rank's rows (for
      // deal.II's DoF numbering, ascending): rank p receives those whose
      // entries start in the p-th share of all entries.
      const Epetra_CrsMatrix &assembled = matrix.trilinos_matrix();
      const MPI_Comm          comm      = matrix.get_mpi_communicator();
      const unsigned int      n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(comm);
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
            std::min<unsigned long long>(n_ranks - 1,
                                         before * n_ranks / total));
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



    template <int dim>
    unsigned int
    AmgKrylov<dim>::solve(const System                        &system,
                          TrilinosWrappers::MPI::Vector       &x,
                          const TrilinosWrappers::MPI::Vector &rhs)
    {
      release();
      AssertThrow(this->accepts(system.property),
                  ExcMessage("The " + method() + " solver cannot solve a " +
                             to_string(system.property) + " system."));
      last_matrix = &system.matrix;
      // A failed solve keeps nothing (what it kept would refer to a matrix
      // that may be gone when this object is).
      try
        {
          TrilinosWrappers::PreconditionAMG::AdditionalData data;
          data.elliptic              = true;
          data.higher_order_elements = false;
          data.smoother_sweeps       = 2;
          data.aggregation_threshold = 0.02;
          const std::vector<std::vector<bool>> modes =
            (system.constant_modes ? system.constant_modes() :
                                     std::vector<std::vector<bool>>());
          const bool balance = (partition == "balanced" &&
                                dealii::Utilities::MPI::n_mpi_processes(
                                  system.matrix.get_mpi_communicator()) > 1);
          data.constant_modes =
            (balance ? balance_rows(system.matrix, modes) : modes);
          amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
          amg->initialize(balance ? *balanced_matrix : system.matrix, data);
          return run(x, rhs);
        }
      catch (...)
        {
          release();
          throw;
        }
    }



    template <int dim>
    unsigned int
    AmgKrylov<dim>::solve_again(TrilinosWrappers::MPI::Vector       &x,
                                const TrilinosWrappers::MPI::Vector &rhs)
    {
      Assert(last_matrix != nullptr, ExcMessage("No solve() before."));
      return run(x, rhs);
    }



    template <int dim>
    unsigned long long
    AmgKrylov<dim>::n_local_entries() const
    {
      Assert(last_matrix != nullptr, ExcMessage("No solve() before."));
      return (balanced_matrix ? *balanced_matrix : *last_matrix)
        .trilinos_matrix()
        .NumMyNonzeros();
    }



    template <int dim>
    void
    AmgKrylov<dim>::release()
    {
      amg.reset();
      balanced_matrix.reset();
      to_balanced.reset();
      last_matrix = nullptr;
    }



    template class AmgKrylov<2>;
    template class AmgKrylov<3>;
  } // namespace LinearSolver
} // namespace xcrack
