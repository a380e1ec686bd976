#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_enriched.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <xcrack/xfem/enrichment.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace xcrack
{
  template <int dim>
  HeavisideFunction<dim>::HeavisideFunction(const CrackGeometry<dim> &crack)
    : crack(crack)
  {}



  template <int dim>
  double
  HeavisideFunction<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    return (crack.lsn(p) >= 0 ? 1. : -1.);
  }



  template <int dim>
  Tensor<1, dim>
  HeavisideFunction<dim>::gradient(const Point<dim> &, const unsigned int) const
  {
    return Tensor<1, dim>();
  }



  namespace
  {
    /**
     * The Q1 interpolant of vertex values on the reference cell, with the
     * value, gradient and Hessian the quadrature generator asks for.
     */
    template <int dim>
    class ReferenceCellLevelSet : public Function<dim>
    {
    public:
      explicit ReferenceCellLevelSet(const std::vector<double> &vertex_values)
        : vertex_values(vertex_values)
      {}

      double
      value(const Point<dim> &p, const unsigned int = 0) const override
      {
        double v = 0;
        for (unsigned int i = 0; i < vertex_values.size(); ++i)
          v += vertex_values[i] * q1.shape_value(i, p);
        return v;
      }

      Tensor<1, dim>
      gradient(const Point<dim> &p, const unsigned int = 0) const override
      {
        Tensor<1, dim> g;
        for (unsigned int i = 0; i < vertex_values.size(); ++i)
          g += vertex_values[i] * q1.shape_grad(i, p);
        return g;
      }

      SymmetricTensor<2, dim>
      hessian(const Point<dim> &p, const unsigned int = 0) const override
      {
        Tensor<2, dim> h;
        for (unsigned int i = 0; i < vertex_values.size(); ++i)
          h += vertex_values[i] * q1.shape_grad_grad(i, p);
        return symmetrize(h);
      }

    private:
      // FE_Q(1) numbers its shape functions like the cell's vertices.
      const FE_Q<dim>     q1{1};
      std::vector<double> vertex_values;
    };

    /**
     * The rule of a cell cut by the zero set of the Q1 interpolant of
     * @p vertex_values (reference coordinates): Gauss rules of
     * @p n_points_1d points per direction on each side, joined. Also
     * returns the reference volume of the negative side.
     */
    template <int dim>
    std::pair<Quadrature<dim>, double>
    cut_cell_rule(const std::vector<double> &vertex_values,
                  const unsigned int         n_points_1d)
    {
      const ReferenceCellLevelSet<dim>      level_set(vertex_values);
      const hp::QCollection<1>              q1d(QGauss<1>{n_points_1d});
      NonMatching::QuadratureGenerator<dim> generator(q1d);
      Point<dim>                            upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = 1;
      generator.generate(level_set,
                         BoundingBox<dim>(std::make_pair(Point<dim>(), upper)));

      std::vector<Point<dim>> points;
      std::vector<double>     weights;
      for (const Quadrature<dim> *side : {&generator.get_inside_quadrature(),
                                          &generator.get_outside_quadrature()})
        {
          points.insert(points.end(),
                        side->get_points().begin(),
                        side->get_points().end());
          weights.insert(weights.end(),
                         side->get_weights().begin(),
                         side->get_weights().end());
        }
      const auto &inside = generator.get_inside_quadrature().get_weights();
      return {Quadrature<dim>(points, weights),
              std::accumulate(inside.begin(), inside.end(), 0.)};
    }
  } // namespace



  template <int dim>
  Enrichment<dim>::Enrichment(const CrackGeometry<dim> &crack,
                              const unsigned int        degree,
                              const double              volume_tolerance)
    : crack(crack)
    , volume_tolerance(volume_tolerance)
    , heaviside_function(crack)
  {
    fe_collection.push_back(
      FESystem<dim>(FE_Enriched<dim>(FE_Q<dim>(degree)), dim));
    fe_collection.push_back(FESystem<dim>(FE_Enriched<dim>(FE_Q<dim>(degree),
                                                           FE_Q<dim>(degree),
                                                           &heaviside_function),
                                          dim));
  }



  template <int dim>
  const hp::FECollection<dim> &
  Enrichment<dim>::get_fe_collection() const
  {
    return fe_collection;
  }



  namespace
  {
    /**
     * OR (or, with @p overwrite, copy) the per-vertex @p flags that the
     * owners of the ghost cells computed into ours. A rank sees every cell
     * around the vertices of its own cells, so owners know their vertices'
     * flags completely; a ghost cell's vertex may have neighbours that only its
     * owner sees.
     */
    template <int dim>
    void
    import_ghost_vertex_flags(const Triangulation<dim> &tria,
                              std::vector<bool>        &flags,
                              const bool                overwrite = false)
    {
      if (dynamic_cast<const parallel::TriangulationBase<dim> *>(&tria) ==
          nullptr)
        return;
      using Iterator = typename Triangulation<dim>::active_cell_iterator;
      GridTools::exchange_cell_data_to_ghosts<std::vector<bool>,
                                              Triangulation<dim>>(
        tria,
        [&](const Iterator &cell) {
          std::vector<bool> values;
          for (const unsigned int v : cell->vertex_indices())
            values.push_back(flags[cell->vertex_index(v)]);
          return std_cxx17::optional<std::vector<bool>>(values);
        },
        [&](const Iterator &cell, const std::vector<bool> &values) {
          for (const unsigned int v : cell->vertex_indices())
            if (overwrite)
              flags[cell->vertex_index(v)] = values[v];
            else if (values[v])
              flags[cell->vertex_index(v)] = true;
        });
    }
  } // namespace



  template <int dim>
  void
  Enrichment<dim>::set_fe_indices(DoFHandler<dim> &dof_handler)
  {
    const Triangulation<dim> &tria = dof_handler.get_triangulation();
    cell_kind.assign(tria.n_active_cells(), CellKind::plain);
    split_rules.clear();

    std::vector<bool> touches_split(tria.n_vertices(), false);
    std::vector<bool> touches_tip(tria.n_vertices(), false);
    // Volume of the support of each vertex's function on each side of the
    // crack, and whether a cell the crack splits touches it directly.
    std::vector<double> volume_plus(tria.n_vertices(), 0.);
    std::vector<double> volume_minus(tria.n_vertices(), 0.);
    std::vector<bool>   directly_split(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        {
          double min_lsn = std::numeric_limits<double>::max(),
                 max_lsn = -min_lsn;
          double min_lst = min_lsn, max_lst = -min_lsn;
          for (const unsigned int v : cell->vertex_indices())
            {
              const double n = crack.lsn(cell->vertex(v));
              const double t = crack.lst(cell->vertex(v));
              min_lsn        = std::min(min_lsn, n);
              max_lsn        = std::max(max_lsn, n);
              min_lst        = std::min(min_lst, t);
              max_lst        = std::max(max_lst, t);
            }
          // lsn = 0 counts as the positive side (as H(0) = +1 does): a crack
          // through a row of nodes then splits the cells on its negative
          // side, along their faces.
          const bool cut = (min_lsn < 0 && max_lsn >= 0);
          if (!cut || min_lst >= 0)
            {
              // Not on the crack: the whole cell lies on one side of it.
              const double cell_side = crack.lsn(cell->center());
              for (const unsigned int v : cell->vertex_indices())
                (cell_side >= 0 ? volume_plus :
                                  volume_minus)[cell->vertex_index(v)] +=
                  cell->measure();
              continue;
            }
          const CellKind kind = (max_lst < 0 ? CellKind::split : CellKind::tip);
          cell_kind[cell->active_cell_index()] = kind;
          double fraction_minus                = 0.5;
          if (kind == CellKind::split)
            {
              std::vector<double> values;
              for (const unsigned int v : cell->vertex_indices())
                values.push_back(crack.lsn(cell->vertex(v)));
              fraction_minus = cut_cell_rule<dim>(values, 2).second;
            }
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int index = cell->vertex_index(v);
              (kind == CellKind::split ? touches_split : touches_tip)[index] =
                true;
              directly_split[index] =
                directly_split[index] || kind == CellKind::split;
              volume_minus[index] += fraction_minus * cell->measure();
              volume_plus[index] += (1 - fraction_minus) * cell->measure();
            }
        }

    import_ghost_vertex_flags(tria, touches_split);
    import_ghost_vertex_flags(tria, touches_tip);

    // A coarse vertex whose hanging neighbour (the midpoint of a refined
    // line, or a vertex inside a refined face) touches a split cell has a
    // function that reaches into that cell through the hanging-node
    // constraints: it counts as touching it. 2:1 mesh balance keeps the
    // chains one level deep; a second pass covers a line refined twice.
    for (unsigned int pass = 0; pass < 2; ++pass)
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->is_artificial())
          {
            const auto pull = [&](const auto &object, const auto &children) {
              bool split = false, tip = false;
              for (const unsigned int h : children)
                {
                  split = split || touches_split[h];
                  tip   = tip || touches_tip[h];
                }
              for (const unsigned int v : object->vertex_indices())
                {
                  touches_split[object->vertex_index(v)] =
                    touches_split[object->vertex_index(v)] || split;
                  touches_tip[object->vertex_index(v)] =
                    touches_tip[object->vertex_index(v)] || tip;
                }
            };
            for (unsigned int l = 0; l < cell->n_lines(); ++l)
              if (cell->line(l)->has_children())
                pull(cell->line(l),
                     std::vector<unsigned int>{
                       cell->line(l)->child(0)->vertex_index(1)});
            if (dim == 3)
              for (const auto &face : cell->face_iterators())
                if (face->has_children())
                  {
                    // The centre of an isotropically refined quad (vertex
                    // 3 of child 0) depends on all four corners; the
                    // midpoints of its lines are handled with the lines.
                    pull(face,
                         std::vector<unsigned int>{
                           face->child(0)->vertex_index(3)});
                  }
          }

    // The vertices whose shape functions are enriched.
    std::vector<bool> &enriched = enriched_vertex;
    enriched.assign(tria.n_vertices(), false);
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        enriched[v] = touches_split[v] && !touches_tip[v];
        // A support the crack barely cuts gives a function that is almost a
        // copy of the standard one, and a nearly singular matrix: drop it.
        // (A vertex that only reaches split cells through hanging-node
        // constraints has no split cell of its own; it is kept.)
        const double total = volume_plus[v] + volume_minus[v];
        if (enriched[v] && directly_split[v] &&
            std::min(volume_plus[v], volume_minus[v]) <=
              volume_tolerance * total)
          enriched[v] = false;
      }
    // The owners of the ghost cells see their vertices' full supports.
    import_ghost_vertex_flags(tria, enriched, /*overwrite=*/true);

    // A hanging vertex takes its values from the vertices of the coarse
    // line or face it lies on: where one of those is enriched, so is the
    // hanging vertex's function on the fine side, and the fine cells around
    // it need the enriched element too (else the enriched function of the
    // coarse side would end at a non-conforming face).
    std::vector<bool> influenced = enriched;
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        {
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            {
              const auto line = cell->line(l);
              if (line->has_children() && (enriched[line->vertex_index(0)] ||
                                           enriched[line->vertex_index(1)]))
                influenced[line->child(0)->vertex_index(1)] = true;
            }
          if (dim == 3)
            for (const auto &face : cell->face_iterators())
              if (face->has_children())
                {
                  bool any = false;
                  for (const unsigned int v : face->vertex_indices())
                    any = any || enriched[face->vertex_index(v)];
                  if (any)
                    for (unsigned int c = 0; c < face->n_children(); ++c)
                      for (const unsigned int v :
                           face->child(c)->vertex_indices())
                        influenced[face->child(c)->vertex_index(v)] = true;
                }
        }

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool has_enriched_vertex = false;
          for (const unsigned int v : cell->vertex_indices())
            has_enriched_vertex =
              has_enriched_vertex || influenced[cell->vertex_index(v)];
          cell->set_active_fe_index(has_enriched_vertex ? heaviside : plain);
        }
  }



  template <int dim>
  bool
  Enrichment<dim>::is_enriched_dof(const FiniteElement<dim> &fe,
                                   const unsigned int        i)
  {
    // Outer FESystem: (base, component) and the index inside FE_Enriched,
    // whose own base 0 is the standard FE_Q and base 1 the enriched one.
    const auto &index = fe.system_to_base_index(i);
    return fe.base_element(index.first.first)
             .system_to_base_index(index.second)
             .first.first > 0;
  }



  template <int dim>
  bool
  Enrichment<dim>::is_split(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    return cell_kind[cell->active_cell_index()] == CellKind::split;
  }



  template <int dim>
  IndexSet
  Enrichment<dim>::enriched_dofs(const DoFHandler<dim> &dof_handler) const
  {
    IndexSet                             result(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == heaviside)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (is_enriched_dof(cell->get_fe(), i))
              result.add_index(dofs[i]);
        }
    result.compress();
    return result;
  }



  template <int dim>
  void
  Enrichment<dim>::make_constraints(
    const DoFHandler<dim>     &dof_handler,
    AffineConstraints<double> &constraints) const
  {
    // For every enriched DoF: does its support contain a split cell, a tip
    // cell? All cells of the support of a DoF of an owned cell are owned or
    // ghost, so the answer is complete where it is needed.
    std::map<types::global_dof_index, std::pair<bool, bool>> support;
    std::vector<types::global_dof_index>                     dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == heaviside)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const CellKind kind = cell_kind[cell->active_cell_index()];
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (is_enriched_dof(cell->get_fe(), i))
              {
                auto &s  = support[dofs[i]];
                s.first  = s.first || kind == CellKind::split;
                s.second = s.second || kind == CellKind::tip;
              }
        }

    // A hanging DoF passes what its support contains to the DoFs it is
    // constrained to: their functions reach its cells.
    for (unsigned int pass = 0; pass < 2; ++pass)
      for (const auto &[dof, flags] : support)
        if (constraints.is_constrained(dof))
          for (const auto &entry : *constraints.get_constraint_entries(dof))
            {
              auto &s  = support[entry.first];
              s.first  = s.first || flags.first;
              s.second = s.second || flags.second;
            }

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == heaviside)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (is_enriched_dof(cell->get_fe(), i))
              {
                // Vertex DoFs follow the vertex flags, which are complete on
                // every rank; the others the support of their function.
                const FiniteElement<dim> &fe = cell->get_fe();
                const unsigned int        n_vertex_dofs =
                  fe.n_dofs_per_vertex() * cell->n_vertices();
                bool keep;
                if (i < n_vertex_dofs)
                  keep = enriched_vertex[cell->vertex_index(
                    i / fe.n_dofs_per_vertex())];
                else
                  {
                    const auto &s = support[dofs[i]];
                    keep          = s.first && !s.second;
                  }
                if (!keep && !constraints.is_constrained(dofs[i]))
                  constraints.add_line(dofs[i]);
              }
        }
  }



  template <int dim>
  const Quadrature<dim> &
  Enrichment<dim>::split_cell_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    n_points_1d) const
  {
    // The cache key combines cell and order: assembly and error evaluation
    // use different orders on the same cells.
    const unsigned int key = cell->active_cell_index() * 16 + n_points_1d;
    const auto         it  = split_rules.find(key);
    if (it != split_rules.end())
      return it->second;

    std::vector<double> values;
    for (const unsigned int v : cell->vertex_indices())
      values.push_back(crack.lsn(cell->vertex(v)));
    return split_rules
      .emplace(key, cut_cell_rule<dim>(values, n_points_1d).first)
      .first->second;
  }



  template class HeavisideFunction<2>;
  template class HeavisideFunction<3>;
  template class Enrichment<2>;
  template class Enrichment<3>;
} // namespace xcrack
