#include <xcrack/simulator.h>

namespace xcrack
{
  namespace
  {
    /**
     * The rigid translations of the space, one per component, on the
     * locally owned DoFs (in the order of the owned index set): the
     * near-null space from which AMG builds its coarse spaces. A
     * translation is 1 on the standard DoFs and 0 on the enriched ones,
     * whose functions are not constants. DoFTools::extract_constant_modes()
     * does not know FE_Enriched: deal.II's debug library stops there, and
     * the release one marked none of the DoFs of enriched cells, leaving
     * holes in the modes around the cracks.
     */
    template <int dim>
    std::vector<std::vector<bool>>
    translation_modes(const DoFHandler<dim> &dof_handler,
                      const bool             enriched_space)
    {
      const IndexSet                &owned = dof_handler.locally_owned_dofs();
      std::vector<std::vector<bool>> modes(dim,
                                           std::vector<bool>(owned.n_elements(),
                                                             false));
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const FiniteElement<dim> &fe = cell->get_fe();
            dofs.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (owned.is_element(dofs[i]) &&
                  !(enriched_space && Enrichment<dim>::is_enriched_dof(fe, i)))
                modes[fe.system_to_component_index(i).first]
                     [owned.index_within_set(dofs[i])] = true;
          }
      return modes;
    }
  } // namespace



  template <int dim>
  unsigned int
  Simulator<dim>::solve()
  {
    TimerOutput::Scope t(*timer, "solve");

    std::vector<std::vector<bool>> constant_modes;
    if (linear_solver.type != "direct")
      constant_modes = translation_modes(dof_handler, enrichment != nullptr);

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
