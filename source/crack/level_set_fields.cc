#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/crack/level_set_fields.h>

#include <functional>

namespace xcrack
{
  template <int dim>
  LevelSetFields<dim>::LevelSetFields(
    const parallel::distributed::Triangulation<dim> &triangulation)
    : fe(1)
    , dof_handler(triangulation)
  {}



  template <int dim>
  void
  LevelSetFields<dim>::update(const CrackSet<dim>                    &cracks,
                              const std::vector<std::vector<double>> &lsn_shift)
  {
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();

    // Interpolate one level set of a crack into a ghosted vector.
    TrilinosWrappers::MPI::Vector distributed(owned, comm);
    const auto                    interpolate =
      [&](const std::function<double(const Point<dim> &)> &f,
          TrilinosWrappers::MPI::Vector                   &field,
          const std::vector<double>                       &shift) {
        VectorTools::interpolate(dof_handler,
                                 ScalarFunctionFromFunctionObject<dim>(f),
                                 distributed);
        if (!shift.empty())
          {
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned())
                for (const unsigned int v : cell->vertex_indices())
                  {
                    // Set, not subtract: a vertex is met by every cell
                    // around it. Only the few shifted vertices are touched.
                    const auto dof = cell->vertex_dof_index(v, 0);
                    if (shift[cell->vertex_index(v)] != 0 &&
                        owned.is_element(dof))
                      distributed[dof] =
                        f(cell->vertex(v)) - shift[cell->vertex_index(v)];
                  }
            distributed.compress(VectorOperation::insert);
          }
        field.reinit(owned, relevant, comm);
        field = distributed;
      };

    normal.resize(cracks.size());
    tangent.resize(cracks.size());
    for (unsigned int i = 0; i < cracks.size(); ++i)
      {
        const CrackGeometry<dim> &crack = cracks[i];
        interpolate([&](const Point<dim> &p) { return crack.lsn(p); },
                    normal[i],
                    (i < lsn_shift.size() ? lsn_shift[i] :
                                            std::vector<double>()));
        interpolate([&](const Point<dim> &p) { return crack.lst(p); },
                    tangent[i],
                    {});
      }
  }



  template <int dim>
  const DoFHandler<dim> &
  LevelSetFields<dim>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  LevelSetFields<dim>::lsn(const unsigned int crack) const
  {
    return normal[crack];
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  LevelSetFields<dim>::lst(const unsigned int crack) const
  {
    return tangent[crack];
  }



  template class LevelSetFields<2>;
  template class LevelSetFields<3>;
} // namespace xcrack
