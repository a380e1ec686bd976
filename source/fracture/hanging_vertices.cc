#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/hanging_vertices.h>

namespace xcrack
{
  template <int dim>
  HangingVertices<dim>::HangingVertices(const Triangulation<dim> &triangulation)
    : fe(1)
    , dof_handler(triangulation)
  {
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();
    if (constraints.n_constraints() > 0)
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           support_points);
  }



  template <int dim>
  std::vector<std::pair<Point<dim>, double>>
  HangingVertices<dim>::masters(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       v) const
  {
    std::vector<std::pair<Point<dim>, double>> result;
    if (constraints.n_constraints() == 0)
      return result;
    const typename DoFHandler<dim>::active_cell_iterator q1_cell(
      &dof_handler.get_triangulation(),
      cell->level(),
      cell->index(),
      &dof_handler);
    const types::global_dof_index dof = q1_cell->vertex_dof_index(v, 0);
    if (constraints.is_constrained(dof))
      for (const auto &[master, weight] :
           *constraints.get_constraint_entries(dof))
        result.emplace_back(support_points.at(master), weight);
    return result;
  }



  template class HangingVertices<2>;
  template class HangingVertices<3>;
} // namespace xcrack
