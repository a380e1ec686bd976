// The constraints of the Enrichment's space (see its class documentation):
// the enriched functions it drops (those whose support the crack barely
// cuts, and Q2 DoFs whose support holds no split cell) and, with
// gathering, the ties of the branch DoFs (enrichment_gathering.cc). Apart
// from the classification because it works on the distributed DoFs, after
// the cells' elements are chosen.

#include <xcrack/xfem/enrichment.h>

#include <map>

namespace xcrack
{
  template <int dim>
  void
  Enrichment<dim>::make_constraints(
    const DoFHandler<dim>                                        &dof_handler,
    AffineConstraints<double>                                    &constraints,
    const std::vector<std::vector<std::vector<FrontPoint<dim>>>> &fronts)
  {
    // For every enriched non-vertex DoF (Q2 jump DoFs): does its support
    // contain a split cell, a tip cell, and how much of it lies on each side
    // of the crack? All cells of the support of a DoF of an owned cell are
    // owned or ghost, so the answer is complete where it is needed. (These
    // DoFs are kept in the tip zone: in a cell with jump vertices on one
    // side and branch vertices on the other, a Q2 vertex function and a Q1
    // hat do not add up to one along the crack, and without the edge DoF
    // the jump is lost there; measured: 0.52 instead of 0.013 energy error.)
    struct Support
    {
      bool   split = false, tip = false;
      double plus = 0, minus = 0;
    };
    std::map<types::global_dof_index, Support> support;
    std::vector<types::global_dof_index>       dofs;
    // Q1 elements have vertex DoFs only: no supports to look at (filling
    // the map is not free where the tip zone is large, doc/performance.md).
    bool inner_dofs = false;
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      inner_dofs = inner_dofs || fe_collection[i].n_dofs_per_cell() >
                                   fe_collection[i].n_dofs_per_vertex() *
                                     GeometryInfo<dim>::vertices_per_cell;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (inner_dofs && !cell->is_artificial() &&
          cell->active_fe_index() != plain)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const CellKind kind = cell_kind[cell->active_cell_index()];
          const double   minus =
            fraction_minus[cell_crack[cell->active_cell_index()]]
                          [cell->active_cell_index()];
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (is_enriched_dof(cell->get_fe(), i))
              {
                auto &s = support[dofs[i]];
                s.split = s.split || kind == CellKind::split;
                s.tip   = s.tip || kind == CellKind::tip;
                s.minus += minus * cell->measure();
                s.plus += (1 - minus) * cell->measure();
              }
        }

    // A hanging DoF passes what its support contains to the DoFs it is
    // constrained to: their functions reach its cells (its volumes once).
    for (unsigned int pass = 0; pass < 2; ++pass)
      for (const auto &[dof, flags] : support)
        if (constraints.is_constrained(dof))
          for (const auto &entry : *constraints.get_constraint_entries(dof))
            {
              auto &s = support[entry.first];
              s.split = s.split || flags.split;
              s.tip   = s.tip || flags.tip;
              if (pass == 0)
                {
                  s.plus += flags.plus;
                  s.minus += flags.minus;
                }
            }

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() != plain)
        {
          const FiniteElement<dim> &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const unsigned int n_vertex_dofs =
            fe.n_dofs_per_vertex() * cell->n_vertices();
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const unsigned int s = slot(fe, i);
              if (s == 0)
                continue;
              // Vertex DoFs follow the vertex flags, which are complete on
              // every rank; the others the support of their function.
              bool keep;
              if (i < n_vertex_dofs)
                keep =
                  (s == 1 ? heaviside_vertex : tip_vertex)[cell->vertex_index(
                    i / fe.n_dofs_per_vertex())];
              else
                {
                  // As for vertices: the support must straddle the crack
                  // by more than the volume tolerance (a Q2 edge DoF of a
                  // cell whose face the crack runs along sees one side).
                  const Support &flags = support[dofs[i]];
                  keep                 = flags.split && !flags.tip &&
                         std::min(flags.plus, flags.minus) >
                           parameters.heaviside_volume_tolerance *
                             (flags.plus + flags.minus);
                }
              if (!keep && !constraints.is_constrained(dofs[i]))
                constraints.add_line(dofs[i]);
            }
        }

    gathered_dofs = IndexSet(dof_handler.n_dofs());
    master_dofs   = IndexSet(dof_handler.n_dofs());
    if (parameters.gather)
      gather_branch_dofs(dof_handler, fronts, constraints);
  }

  template void
  Enrichment<2>::make_constraints(
    const DoFHandler<2> &,
    AffineConstraints<double> &,
    const std::vector<std::vector<std::vector<FrontPoint<2>>>> &);
  template void
  Enrichment<3>::make_constraints(
    const DoFHandler<3> &,
    AffineConstraints<double> &,
    const std::vector<std::vector<std::vector<FrontPoint<3>>>> &);
} // namespace xcrack
