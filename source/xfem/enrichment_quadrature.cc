// The quadrature rules of the Enrichment's cells (see its class
// documentation): which rule each kind of cell gets (cut, tip, near the
// front, Gauss), cached per cell, and the rule on the lips. Apart from the
// classification because it is the part the accuracy/cost trades of the
// rules change.

#include <deal.II/base/quadrature_lib.h>

#include <xcrack/xfem/cell_quadrature.h>
#include <xcrack/xfem/enrichment.h>

#include <algorithm>

namespace xcrack
{
  template <int dim>
  const Quadrature<dim> *
  Enrichment<dim>::special_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    n_points_1d) const
  {
    const CellKind kind = cell_kind[cell->active_cell_index()];
    const bool     near = near_front[cell->active_cell_index()];
    if (kind == CellKind::plain && !near)
      return nullptr;
    // Split cells with branch functions integrate them as finely as tip
    // cells: a low-order rule would leave their many DoFs underintegrated
    // (spurious zero-energy modes). Cells near the front that it does not
    // touch and that carry the branch functions alone may take a Gauss
    // rule (Near-front quadrature points): their integrands are smooth, if
    // steep where the front passes close.
    const bool gauss_near = kind == CellKind::plain &&
                            cell->active_fe_index() == tip &&
                            parameters.near_front_quadrature_points > 0;
    const unsigned int n =
      (gauss_near ?
         std::max(n_points_1d, parameters.near_front_quadrature_points) :
       kind == CellKind::tip || near || cell->active_fe_index() >= tip ?
         std::max(n_points_1d, parameters.tip_quadrature_points) :
         n_points_1d);
    // The cache key combines cell and order: assembly and error evaluation
    // use different orders on the same cells.
    const unsigned int key = cell->active_cell_index() * 32 + n;
    const auto         it  = special_rules.find(key);
    if (it != special_rules.end())
      return &it->second;

    const unsigned int        c   = crack_index(cell);
    const std::vector<double> lsn = vertex_values(cell, c, true);
    Quadrature<dim>           rule;
    if (gauss_near)
      rule = QGauss<dim>(n);
    else if (kind == CellKind::split && !near)
      rule = CellQuadrature::cut_cell_rule<dim>(lsn, n).first;
    else
      rule = CellQuadrature::tip_cell_rule<dim>(lsn,
                                                vertex_values(cell, c, false),
                                                n);
    return &special_rules.emplace(key, std::move(rule)).first->second;
  }



  template <int dim>
  NonMatching::ImmersedSurfaceQuadrature<dim>
  Enrichment<dim>::lip_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    if (!(is_split(cell) || is_tip(cell)))
      return {};
    const auto [lsn, lst] = level_set_values(cell);
    // Where the front crosses a 3D cell, four boxes per direction (2D tip
    // cells are split exactly).
    const unsigned int n_points =
      (is_tip(cell) ?
         std::max(assembly_points_1d, parameters.tip_quadrature_points) :
         assembly_points_1d);
    return CellQuadrature::lip_rule<dim>(lsn, lst, n_points, 4);
  }



  template <int dim>
  const Quadrature<dim> &
  Enrichment<dim>::split_cell_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    n_points_1d) const
  {
    Assert(is_split(cell), ExcMessage("Not a split cell."));
    return *special_quadrature(cell, n_points_1d);
  }

  template const Quadrature<2> *
  Enrichment<2>::special_quadrature(const DoFHandler<2>::active_cell_iterator &,
                                    const unsigned int) const;
  template const Quadrature<3> *
  Enrichment<3>::special_quadrature(const DoFHandler<3>::active_cell_iterator &,
                                    const unsigned int) const;
  template NonMatching::ImmersedSurfaceQuadrature<2>
  Enrichment<2>::lip_quadrature(
    const DoFHandler<2>::active_cell_iterator &) const;
  template NonMatching::ImmersedSurfaceQuadrature<3>
  Enrichment<3>::lip_quadrature(
    const DoFHandler<3>::active_cell_iterator &) const;
  template const Quadrature<2> &
  Enrichment<2>::split_cell_quadrature(
    const DoFHandler<2>::active_cell_iterator &,
    const unsigned int) const;
  template const Quadrature<3> &
  Enrichment<3>::split_cell_quadrature(
    const DoFHandler<3>::active_cell_iterator &,
    const unsigned int) const;
} // namespace xcrack
