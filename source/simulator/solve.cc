#include <deal.II/dofs/dof_tools.h>

#include <xcrack/simulator.h>

namespace xcrack
{
  template <int dim>
  unsigned int
  Simulator<dim>::solve()
  {
    TimerOutput::Scope t(*timer, "solve");

    std::vector<std::vector<bool>> constant_modes;
    if (linear_solver.type != "direct")
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       constant_modes);

    TrilinosWrappers::MPI::Vector distributed(locally_owned_dofs,
                                              mpi_communicator);
    const unsigned int iterations = linear_solver.solve(system_matrix,
                                                        distributed,
                                                        system_rhs,
                                                        constant_modes);
    // The factorization references the matrix: keep it only for the dual
    // solves of the K error estimate, which follow at once.
    if (!(fracture_parameters.error_estimate && fracture_parameters.compute))
      linear_solver.release();
    constraints.distribute(distributed);
    solution = distributed;
    return iterations;
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
