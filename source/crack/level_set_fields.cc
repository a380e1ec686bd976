#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/crack/level_set_fields.h>

#include <cmath>
#include <limits>
#include <map>

namespace xcrack
{
  template <int dim>
  LevelSetFields<dim>::LevelSetFields(const Triangulation<dim> &triangulation)
    : fe(1)
    , dof_handler(triangulation)
  {}



  template <int dim>
  void
  LevelSetFields<dim>::reinit_vector(TrilinosWrappers::MPI::Vector &vector,
                                     const bool ghosted) const
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    if (ghosted)
      {
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
        vector.reinit(dof_handler.locally_owned_dofs(), relevant, comm);
      }
    else
      vector.reinit(dof_handler.locally_owned_dofs(), comm);
  }



  template <int dim>
  void
  LevelSetFields<dim>::initialize(
    const std::vector<const CrackGeometry<dim> *> &shapes)
  {
    dof_handler.distribute_dofs(fe);
    std::vector<TrilinosWrappers::MPI::Vector> owned(2 * shapes.size());
    for (unsigned int c = 0; c < shapes.size(); ++c)
      {
        const CrackGeometry<dim> &shape = *shapes[c];
        reinit_vector(owned[c], false);
        reinit_vector(owned[shapes.size() + c], false);
        VectorTools::interpolate(dof_handler,
                                 ScalarFunctionFromFunctionObject<dim>(
                                   [&](const Point<dim> &p) {
                                     return shape.lsn(p);
                                   }),
                                 owned[c]);
        VectorTools::interpolate(dof_handler,
                                 ScalarFunctionFromFunctionObject<dim>(
                                   [&](const Point<dim> &p) {
                                     return shape.lst(p);
                                   }),
                                 owned[shapes.size() + c]);
        // A shape's level sets are finite everywhere; anything else is a
        // bug in the shape, which would show as cracks where there are none.
        AssertThrow(std::isfinite(owned[c].l2_norm()) &&
                      std::isfinite(owned[shapes.size() + c].l2_norm()),
                    ExcMessage("The level sets of crack " +
                               std::to_string(c + 1) +
                               " are not finite at some vertex."));
      }
    set_all(owned);
  }



  template <int dim>
  void
  LevelSetFields<dim>::zero_round_off(
    TrilinosWrappers::MPI::Vector &owned) const
  {
    // The shortest edge at each locally relevant vertex DoF: the owned and
    // ghost cells hold every cell around an owned vertex.
    std::map<types::global_dof_index, double> edge;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto dof = cell->vertex_dof_index(v, 0);
            if (!owned.locally_owned_elements().is_element(dof))
              continue;
            const double h            = cell->minimum_vertex_distance();
            const auto [it, inserted] = edge.emplace(dof, h);
            if (!inserted)
              it->second = std::min(it->second, h);
          }
    for (const auto &[dof, h] : edge)
      if (owned[dof] != 0 && std::abs(owned[dof]) <= 1e-10 * h)
        owned[dof] = 0;
    owned.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  LevelSetFields<dim>::set_all(
    std::vector<TrilinosWrappers::MPI::Vector> &owned)
  {
    for (auto &field : owned)
      zero_round_off(field);
    const unsigned int n = owned.size() / 2;
    normal.resize(n);
    tangent.resize(n);
    for (unsigned int c = 0; c < n; ++c)
      {
        reinit_vector(normal[c], true);
        reinit_vector(tangent[c], true);
        normal[c]  = owned[c];
        tangent[c] = owned[n + c];
      }
  }



  template <int dim>
  unsigned int
  LevelSetFields<dim>::n_cracks() const
  {
    return normal.size();
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
    AssertIndexRange(crack, normal.size());
    return normal[crack];
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  LevelSetFields<dim>::lst(const unsigned int crack) const
  {
    AssertIndexRange(crack, tangent.size());
    return tangent[crack];
  }



  template <int dim>
  std::vector<double>
  LevelSetFields<dim>::vertex_values(const unsigned int crack,
                                     const bool         normal_field) const
  {
    const TrilinosWrappers::MPI::Vector &field =
      (normal_field ? lsn(crack) : lst(crack));
    std::vector<double> values(dof_handler.get_triangulation().n_vertices(),
                               std::numeric_limits<double>::quiet_NaN());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          values[cell->vertex_index(v)] = field[cell->vertex_dof_index(v, 0)];
    return values;
  }



  template <int dim>
  std::vector<double>
  LevelSetFields<dim>::cell_front_distances() const
  {
    std::vector<std::vector<double>> n_values, t_values;
    for (unsigned int c = 0; c < n_cracks(); ++c)
      {
        n_values.push_back(vertex_values(c, true));
        t_values.push_back(vertex_values(c, false));
      }
    const auto         &triangulation = dof_handler.get_triangulation();
    std::vector<double> distances(triangulation.n_active_cells(),
                                  std::numeric_limits<double>::max());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int c = 0; c < n_cracks(); ++c)
          {
            double n = 0, t = 0;
            for (const unsigned int v : cell->vertex_indices())
              {
                n += n_values[c][cell->vertex_index(v)] / cell->n_vertices();
                t += t_values[c][cell->vertex_index(v)] / cell->n_vertices();
              }
            double &d = distances[cell->active_cell_index()];
            d         = std::min(d, std::hypot(n, t));
          }
    return distances;
  }



  template <int dim>
  void
  LevelSetFields<dim>::set(const unsigned int                   crack,
                           const TrilinosWrappers::MPI::Vector &new_lsn,
                           const TrilinosWrappers::MPI::Vector &new_lst)
  {
    AssertIndexRange(crack, normal.size());
    TrilinosWrappers::MPI::Vector owned_lsn, owned_lst;
    reinit_vector(owned_lsn, false);
    reinit_vector(owned_lst, false);
    owned_lsn = new_lsn;
    owned_lst = new_lst;
    zero_round_off(owned_lsn);
    zero_round_off(owned_lst);
    normal[crack]  = owned_lsn;
    tangent[crack] = owned_lst;
  }



  template <int dim>
  void
  LevelSetFields<dim>::subtract_from_lsn(
    const std::vector<std::vector<double>> &shift)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    for (unsigned int c = 0; c < shift.size() && c < normal.size(); ++c)
      {
        // Collective: a rank that fitted no vertex (an empty shift) takes
        // part in the others' vector operations (it skipped them, and the
        // ranks' collectives mismatched: a 2D trial step on two ranks).
        if (!Utilities::MPI::logical_or(!shift[c].empty(), comm))
          continue;
        TrilinosWrappers::MPI::Vector owned;
        reinit_vector(owned, false);
        owned = normal[c];
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && !shift[c].empty())
            for (const unsigned int v : cell->vertex_indices())
              {
                // Set, not subtract: a vertex is met by every cell around
                // it. Only the few shifted vertices are touched.
                const auto dof = cell->vertex_dof_index(v, 0);
                if (shift[c][cell->vertex_index(v)] != 0 &&
                    owned.locally_owned_elements().is_element(dof))
                  owned[dof] = normal[c][dof] - shift[c][cell->vertex_index(v)];
              }
        owned.compress(VectorOperation::insert);
        normal[c] = owned;
      }
  }



  template <int dim>
  std::vector<const TrilinosWrappers::MPI::Vector *>
  LevelSetFields<dim>::all_fields() const
  {
    std::vector<const TrilinosWrappers::MPI::Vector *> fields;
    for (const auto &f : normal)
      fields.push_back(&f);
    for (const auto &f : tangent)
      fields.push_back(&f);
    return fields;
  }



  template <int dim>
  void
  LevelSetFields<dim>::prepare_for_coarsening_and_refinement()
  {
    transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dof_handler);
    transfer->prepare_for_coarsening_and_refinement(all_fields());
  }



  template <int dim>
  void
  LevelSetFields<dim>::interpolate()
  {
    Assert(transfer,
           ExcMessage("Call prepare_for_coarsening_and_refinement "
                      "before refining the mesh."));
    dof_handler.distribute_dofs(fe);
    std::vector<TrilinosWrappers::MPI::Vector>   owned(2 * normal.size());
    std::vector<TrilinosWrappers::MPI::Vector *> pointers;
    for (auto &v : owned)
      {
        reinit_vector(v, false);
        pointers.push_back(&v);
      }
    transfer->interpolate(pointers);
    transfer.reset();
    set_all(owned);
  }



  template <int dim>
  void
  LevelSetFields<dim>::prepare_for_serialization()
  {
    transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dof_handler);
    transfer->prepare_for_serialization(all_fields());
  }



  template <int dim>
  void
  LevelSetFields<dim>::deserialize(const unsigned int n_cracks)
  {
    dof_handler.distribute_dofs(fe);
    std::vector<TrilinosWrappers::MPI::Vector>   owned(2 * n_cracks);
    std::vector<TrilinosWrappers::MPI::Vector *> pointers;
    for (auto &v : owned)
      {
        reinit_vector(v, false);
        pointers.push_back(&v);
      }
    transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dof_handler);
    transfer->deserialize(pointers);
    transfer.reset();
    set_all(owned);
  }



  template class LevelSetFields<2>;
  template class LevelSetFields<3>;
} // namespace xcrack
