// The quadrature rules of the Enrichment's cells (see its class
// documentation): which rule each kind of cell gets (cut, tip, near the
// front, Gauss), cached per cell, and the rule on the lips. Apart from the
// classification because it is the part the accuracy/cost trades of the
// rules change.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

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
    // touch and that carry the branch functions alone take a Gauss rule:
    // their integrands are analytic, if steep where the front passes
    // close. Its order is fixed (Near-front quadrature points) or follows
    // the cell's distance from the front (Near-front quadrature tolerance),
    // with the tip rule where that is the cheaper of the two.
    const bool branch_near =
      kind == CellKind::plain && cell->active_fe_index() == tip;
    const bool gauss_near =
      branch_near && parameters.near_front_quadrature_points > 0;
    const bool graded = branch_near && !gauss_near &&
                        parameters.near_front_quadrature_tolerance > 0;
    const unsigned int n =
      (gauss_near ?
         std::max(n_points_1d, parameters.near_front_quadrature_points) :
       kind == CellKind::tip || near || cell->active_fe_index() >= tip ?
         std::max(n_points_1d, parameters.tip_quadrature_points) :
         n_points_1d);
    // The cache key combines cell and requested order: assembly and error
    // evaluation use different orders on the same cells.
    const unsigned int key = cell->active_cell_index() * 32 + n_points_1d;
    const auto         it  = special_rules.find(key);
    if (it != special_rules.end())
      return it->second;

    // Gauss rules are shared between the cells (and their FEValues with
    // them, is_shared_rule()).
    const auto gauss = [&](const unsigned int order) {
      return &gauss_rules.try_emplace(order, order).first->second;
    };
    const auto own = [&](Quadrature<dim> &&rule) {
      return &cell_rules.emplace(key, std::move(rule)).first->second;
    };
    const unsigned int        c   = crack_index(cell);
    const std::vector<double> lsn = vertex_values(cell, c, true);
    const Quadrature<dim>    *rule;
    if (gauss_near)
      rule = gauss(n);
    else if (kind == CellKind::split && !near)
      rule = own(CellQuadrature::cut_cell_rule<dim>(lsn, n).first);
    else
      {
        const std::vector<double> lst = vertex_values(cell, c, false);
        // classify() built the rule of the assembly's order already.
        Quadrature<dim> tip_rule;
        const auto      classified =
          classified_rules.find({cell->active_cell_index(), c});
        if (classified != classified_rules.end() &&
            n == std::max(assembly_points_1d, parameters.tip_quadrature_points))
          {
            tip_rule = std::move(classified->second);
            classified_rules.erase(classified);
          }
        else
          tip_rule = CellQuadrature::tip_cell_rule<dim>(lsn, lst, n);
        // The graded Gauss rule where it is the smaller of the two.
        unsigned int n_graded = numbers::invalid_unsigned_int;
        if (graded)
          n_graded = std::max(n_points_1d,
                              CellQuadrature::graded_gauss_points(
                                CellQuadrature::front_distance<dim>(lsn, lst),
                                parameters.near_front_quadrature_tolerance));
        if (n_graded < 32 &&
            Utilities::fixed_power<dim>(n_graded) < tip_rule.size())
          rule = gauss(n_graded);
        else
          rule = own(std::move(tip_rule));
      }
    special_rules.emplace(key, rule);
    return rule;
  }



  template <int dim>
  bool
  Enrichment<dim>::is_shared_rule(const Quadrature<dim> *rule) const
  {
    for (const auto &[order, gauss] : gauss_rules)
      if (rule == &gauss)
        return true;
    return false;
  }



  template <int dim>
  NonMatching::ImmersedSurfaceQuadrature<dim>
  Enrichment<dim>::lip_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    if (!(is_split(cell) || is_tip(cell)))
      return {};
    const auto [lsn, lst] = level_set_values(cell);
    // lsn = 0 counts as the positive side: lips that lie in a face (a crack
    // along a row of nodes) belong to the cell on their negative side, and
    // a tip cell without a negative vertex has none (its neighbour across
    // the face holds them; both held the piece at the tip before).
    if (*std::min_element(lsn.begin(), lsn.end()) >= 0)
      return {};
    // Where the front crosses a 3D cell, four boxes per direction (2D tip
    // cells are split exactly).
    const unsigned int n_points =
      (is_tip(cell) ?
         std::max(assembly_points_1d, parameters.tip_quadrature_points) :
         assembly_points_1d);
    return CellQuadrature::lip_rule<dim>(lsn, lst, n_points, 4);
  }



  template <int dim>
  Quadrature<dim>
  Enrichment<dim>::boundary_face_quadrature(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    face_no) const
  {
    const auto [lsn, lst] = level_set_values(cell);
    return CellQuadrature::boundary_face_rule<dim>(
      lsn,
      lst,
      face_no,
      std::max(assembly_points_1d, parameters.tip_quadrature_points));
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
  template bool
  Enrichment<2>::is_shared_rule(const Quadrature<2> *) const;
  template bool
  Enrichment<3>::is_shared_rule(const Quadrature<3> *) const;
  template NonMatching::ImmersedSurfaceQuadrature<2>
  Enrichment<2>::lip_quadrature(
    const DoFHandler<2>::active_cell_iterator &) const;
  template NonMatching::ImmersedSurfaceQuadrature<3>
  Enrichment<3>::lip_quadrature(
    const DoFHandler<3>::active_cell_iterator &) const;
  template Quadrature<2>
  Enrichment<2>::boundary_face_quadrature(
    const DoFHandler<2>::active_cell_iterator &,
    const unsigned int) const;
  template Quadrature<3>
  Enrichment<3>::boundary_face_quadrature(
    const DoFHandler<3>::active_cell_iterator &,
    const unsigned int) const;
  template const Quadrature<2> &
  Enrichment<2>::split_cell_quadrature(
    const DoFHandler<2>::active_cell_iterator &,
    const unsigned int) const;
  template const Quadrature<3> &
  Enrichment<3>::split_cell_quadrature(
    const DoFHandler<3>::active_cell_iterator &,
    const unsigned int) const;
} // namespace xcrack
