#include <xcrack/simulator.h>

#include <limits>

namespace xcrack
{
  template <int dim>
  bool
  Simulator<dim>::cap_refinement_flags(const unsigned int level_cap)
  {
    const int finest = std::min(refinement_parameters.max_level, level_cap);
    bool      marked = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->refine_flag_set() && cell->level() >= finest)
            cell->clear_refine_flag();
          if (cell->coarsen_flag_set() &&
              cell->level() <= int(refinement_parameters.min_level))
            cell->clear_coarsen_flag();
          marked =
            marked || cell->refine_flag_set() || cell->coarsen_flag_set();
        }
    return Utilities::MPI::logical_or(marked, mpi_communicator);
  }



  template <int dim>
  bool
  Simulator<dim>::execute_refinement(const unsigned int level_cap)
  {
    if (!cap_refinement_flags(level_cap))
      return false;
    // Indexed by the cells of the mesh about to change.
    k_error_cells.indicators.reinit(0);
    // The cracks' fields follow the mesh (before the cracks move, the next
    // set-up interpolates their shapes again).
    triangulation.prepare_coarsening_and_refinement();
    // With no refinement left to do, the mesh can only lose cells; if it
    // keeps them all, nothing changed (coarsen flags the 2:1 balance does
    // not let through), and marking again would set the same flags: a pass
    // that ends the loop of adapt_mesh_to_fronts() rather than repeating
    // it up to Maximum level times (doc/performance.md, "The overhead of a
    // 2D step").
    bool refines = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set())
        refines = true;
    refines = Utilities::MPI::logical_or(refines, mpi_communicator);
    const types::global_cell_index n_cells =
      triangulation.n_global_active_cells();
    if (enrichment)
      level_sets.prepare_for_coarsening_and_refinement();
    triangulation.execute_coarsening_and_refinement();
    if (enrichment)
      level_sets.interpolate();
    return refines || triangulation.n_global_active_cells() != n_cells;
  }



  template <int dim>
  bool
  Simulator<dim>::refine_mesh()
  {
    mesh_refinement->mark(triangulation);
    return execute_refinement();
  }



  template <int dim>
  bool
  Simulator<dim>::check_mesh_goal(const bool last_mesh)
  {
    const auto status = mesh_refinement->check_goal();
    statistics.add_value("goal_met", (unsigned long long)status.met);
    if (detailed_screen)
      pcout << "  mesh goal: " << status.text << std::endl;
    if (status.met)
      return true;
    if (last_mesh)
      {
        pcout << "  Warning: the goal of the refinement is not met after "
              << refinement_parameters.n_meshes
              << " meshes (Mesh refinement/Number of meshes); the results of "
                 "the last one stand."
              << std::endl;
        return true;
      }
    // Mark now, so that a mesh that cannot change (every marked cell at
    // Maximum level) ends the step here rather than being solved again.
    mesh_refinement->mark(triangulation);
    if (cap_refinement_flags())
      return false;
    pcout << "  Warning: the goal of the refinement is not met and the mesh "
             "cannot be refined further where the error sits (Mesh "
             "refinement/Maximum level = "
          << refinement_parameters.max_level
          << "); the results of this mesh stand." << std::endl;
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::adapt_mesh_to_fronts()
  {
    // A strategy that does not follow the fronts (global, kelly, residual,
    // region) leaves the mesh as it is once the cracks grow.
    if (!mesh_refinement->follows_fronts())
      return;
    // Without a goal the strategy refines the cells at the fronts at every
    // pass: the growing fronts keep the level step 0 reached (the mesh's
    // finest, whose cells are at the fronts), or Growth level.
    unsigned int cap = numbers::invalid_unsigned_int;
    if (!mesh_refinement->has_goal())
      {
        if (refinement_parameters.growth_level > 0)
          cap = refinement_parameters.growth_level;
        else
          {
            if (growth_front_level == numbers::invalid_unsigned_int)
              {
                growth_front_level = triangulation.n_global_levels() - 1;
                double h           = std::numeric_limits<double>::max();
                for (const auto &cell : triangulation.active_cell_iterators())
                  if (cell->is_locally_owned())
                    h = std::min(h, cell->diameter());
                h = Utilities::MPI::min(h, mpi_communicator);
                pcout << "Growth: the cells at the fronts stay at refinement "
                         "level "
                      << growth_front_level << " (diameter " << h
                      << "), the finest of step 0 (Mesh refinement/Growth "
                         "level)."
                      << std::endl;
              }
            cap = growth_front_level;
          }
      }
    // One level per pass, until the marking reaches a fixed point.
    for (unsigned int pass = 0; pass <= refinement_parameters.max_level + 1;
         ++pass)
      {
        mesh_refinement->mark(triangulation);
        if (!execute_refinement(cap))
          break;
        // Unmoved cracks (before the first solve) are marked by their
        // shapes, not by fields interpolated from the coarser mesh.
        update_level_sets();
      }
  }



  template <int dim>
  void
  Simulator<dim>::refine_before_first_solve()
  {
    // The estimate's wide crown around the initial fronts, if it is asked
    // for: the strategy (k tolerance) refines it too.
    if (fracture_parameters.error_estimate)
      {
        std::vector<std::vector<FrontPoint<dim>>> fronts;
        for (unsigned int c = 0; c < cracks.size(); ++c)
          {
            CrackSurface<dim> surface;
            surface.extract(level_sets, c);
            for (const auto &front : surface.fronts())
              fronts.push_back(front);
          }
        if (!fronts.empty())
          expect_wide_crown(fronts);
      }
    adapt_mesh_to_fronts();
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
