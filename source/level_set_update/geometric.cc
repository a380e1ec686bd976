#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/input_error.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/level_set_update/geometric.h>
#include <xcrack/xfem/enrichment.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    void
    Geometric<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometric");
      prm.declare_entry(
        "Band radius",
        "0",
        Patterns::Double(0),
        "The nodes within this distance of the front get new level sets; "
        "farther ones keep lsn (ahead of the front, within twice the band, "
        "the new extension plane) and the sign of lst. 0: "
        "twice the larger of the enrichment radius and six diameters of "
        "the cells at the front, plus twice the largest advance.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Geometric<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Geometric");
      band_radius = prm.get_double("Band radius");
    }



    template <int dim>
    double
    Geometric<dim>::band(const double h, const double largest_advance) const
    {
      if (band_radius > 0)
        return band_radius;
      const double radius = (this->get_enrichment() ?
                               this->get_enrichment()->get_parameters().radius :
                               0.);
      return default_band(radius, h, largest_advance);
    }



    template <int dim>
    void
    Geometric<dim>::update(const unsigned int                 crack,
                           const std::vector<FrontMove<dim>> &moves,
                           LevelSetFields<dim>               &fields)
    {
      // The moves of each front of the crack, by abscissa.
      const auto &fronts = this->get_crack_surfaces()[crack].fronts();
      double      largest;
      const std::vector<Track<dim>> tracks =
        make_tracks(crack, moves, fronts, largest);
      if (largest == 0)
        return;

      const double h =
        front_cell_sizes(fields, crack, this->get_mpi_communicator()).largest;
      const double           radius      = band(h, largest);
      const DoFHandler<dim> &dof_handler = fields.get_dof_handler();
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           support);
      const MPI_Comm                comm  = this->get_mpi_communicator();
      const IndexSet                owned = dof_handler.locally_owned_dofs();
      TrilinosWrappers::MPI::Vector new_lsn(owned, comm), new_lst(owned, comm);
      const auto                   &old_lsn = fields.lsn(crack);
      const auto                   &old_lst = fields.lst(crack);

      // The nodes in the band, with their projection on the old fronts and
      // what moves there.
      struct Node
      {
        types::global_dof_index dof;
        unsigned int            front;
        Tensor<1, dim>          d, e1, e2;
        Sample<dim>             sample;
      };
      // The box of the old fronts, widened by the ring beyond the band:
      // nodes outside are not projected.
      const double           ring = 2 * (radius + largest);
      const BoundingBox<dim> box  = front_box(fronts, ring);

      std::vector<Node> band_nodes;
      // The nodes ahead of the front in the ring, with their front and
      // distance to its new extension plane (see below).
      std::vector<std::tuple<types::global_dof_index, unsigned int, double>>
        ahead;
      for (const types::global_dof_index dof : owned)
        {
          const Point<dim> &x  = support.at(dof);
          const double      n0 = old_lsn[dof], t0 = old_lst[dof];
          new_lsn[dof]      = n0;
          const bool in_box = box.point_inside(x);
          const auto [front, s, p] =
            (in_box ? project(fronts, x) :
                      std::make_tuple(0u, 0., Point<dim>()));
          if (!in_box || x.distance(p) > radius + largest)
            {
              if (in_box && t0 > 0 && x.distance(p) <= ring)
                {
                  const Sample<dim> sample = tracks[front].at(s);
                  if ((x - p) *
                        (sample.old_direction() + sample.new_direction()) >
                      0)
                    ahead.emplace_back(dof,
                                       front,
                                       (x - p) * sample.new_normal());
                }
              // Far from the front only the signs matter, and the front
              // cannot have passed a node farther than the advance: behind
              // stays behind, ahead (or aside, where the crack turned away)
              // stays ahead, as far as it was. (Shifting every lst by the
              // advance, old extension planes that the crack turned away
              // from became cracks after enough steps; halving it there,
              // lst tended to 0, and a cell refined later across such a
              // node and one behind got lst < 0 along the old plane: the
              // DCB paths stopped on such pieces after turning by 60
              // degrees.)
              new_lst[dof] = (t0 <= 0 ? t0 - largest : t0);
              continue;
            }
          Node node;
          node.dof    = dof;
          node.front  = front;
          node.d      = x - p;
          node.sample = tracks[front].at(s);
          node.e1     = node.sample.e1 / node.sample.e1.norm();
          node.e2     = node.sample.e2 - (node.sample.e2 * node.e1) * node.e1;
          node.e2 /= node.e2.norm();
          band_nodes.push_back(node);
        }

      // Which way lsn counts along e2 at each front: e2 is the normal of
      // the frame of K (in 2D e1 turned by +90 degrees), not necessarily
      // the lsn > 0 side. Behind a front the old lsn is +-(d . e2).
      std::vector<double> orientation(fronts.size(), 0.);
      for (const Node &node : band_nodes)
        if (node.d * node.e1 < 0)
          orientation[node.front] += old_lsn[node.dof] * (node.d * node.e2);
      Utilities::MPI::sum(ArrayView<const double>(orientation),
                          comm,
                          ArrayView<double>(orientation));

      for (const Node &node : band_nodes)
        {
          const double angle = node.sample.angle;
          const double c = std::cos(angle), s = std::sin(angle);
          const double sign = (orientation[node.front] < 0 ? -1. : 1.);
          // The node's coordinates in the frame of the old front. A 2D tip
          // is a point: the projection d . e1, d . e2 is exact. (The old
          // level sets near the new tip may have been interpolated, when
          // the mesh was refined after the last update, from cells across
          // the last kink: kept there, they tilt the next frame and the path
          // breaks up into zigzags.) A 3D front is a polyline: d ends on its
          // chords, inside a curved front, and their frames tilt the plane;
          // there the old level sets where they agree with the projection
          // within a front cell, the projection where they do not (far
          // nodes keep only the sign of their old values).
          const double t_old = old_lst[node.dof],
                       n_old = sign * old_lsn[node.dof];
          const double t_new = node.d * node.e1, n_new = node.d * node.e2;
          const bool   keep_t     = (dim == 3 && std::abs(t_old - t_new) < h);
          const bool   keep_n     = (dim == 3 && std::abs(n_old - n_new) < h);
          const double t          = (keep_t ? t_old : t_new);
          const double n          = (keep_n ? n_old : n_new);
          const Tensor<1, dim> e1 = c * node.e1 + s * node.e2;
          new_lst[node.dof]       = c * t + s * n - node.sample.advance;
          // The old lsn is the crack surface only behind the old front;
          // ahead of it, it is an extension plane, which a crack that turned
          // leaves behind (its zeros, with the new lst < 0 there, would make
          // a piece of crack where there is none): the new plane there too.
          if (node.d * (node.e1 + e1) > 0 || old_lst[node.dof] > 0)
            new_lsn[node.dof] = sign * (c * n - s * t);
        }
      // Beyond the band, lsn ahead of the front is the new extension plane
      // too (NarrowBand's write_back() does the same for `upwind` and
      // `simplex`): kept, the old lsn of a crack that turned keeps the sign
      // of the side it was on before, next to the band's new values.
      for (const auto &[dof, front, n] : ahead)
        new_lsn[dof] = (orientation[front] < 0 ? -n : n);
      new_lsn.compress(VectorOperation::insert);
      new_lst.compress(VectorOperation::insert);
      fields.set(crack, new_lsn, new_lst);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Geometric,
                           "geometric",
                           "no PDE: the nodes near the front are projected on "
                           "it and get the distances to the advanced, kinked "
                           "front; the surface behind it is kept "
                           "(subsection Geometric).")
  } // namespace LevelSetUpdate
} // namespace xcrack
