#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/input_error.h>
#include <xcrack/level_set_update/narrow_band.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    void
    NarrowBand::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Band radius",
        "0",
        Patterns::Double(0),
        "The update covers the points of the body within this distance of "
        "the front (plus the advance); mesh nodes farther away keep lsn "
        "(ahead of the front, within twice the band, the new extension "
        "plane), and lst keeps its sign. 0: the larger of the enrichment "
        "radius and six diameters of the finest front cells, plus twice the "
        "largest advance (half the geometric update's first term: the cost "
        "goes with the band's cross-section). At least Propagation/Maximum "
        "advance.");
    }



    void
    NarrowBand::parse_parameters(ParameterHandler &prm, const std::string &p)
    {
      band_radius = prm.get_double("Band radius");
      path        = p;
    }



    void
    NarrowBand::check_advance(const double maximum_advance) const
    {
      std::ostringstream message;
      message << path << "/Band radius = " << band_radius
              << " is narrower than Propagation/Maximum advance = "
              << maximum_advance
              << ": the new front would leave the band. Give a band at least "
                 "the crowns' radius plus the advance, or 0.";
      check_input(band_radius == 0 || band_radius >= maximum_advance,
                  message.str());
    }



    template <int dim>
    double
    NarrowBand::radius(const Enrichment<dim> *enrichment,
                       const double           h,
                       const double           largest_advance) const
    {
      if (band_radius > 0)
        return band_radius;
      const double enriched =
        (enrichment ? enrichment->get_parameters().radius : 0.);
      return std::max(enriched, 6 * h) + 2 * largest_advance;
    }



    template <int dim>
    double
    finest_front_cell(const LevelSetFields<dim> &fields,
                      const unsigned int         crack,
                      const std::string         &method,
                      const MPI_Comm             communicator)
    {
      const double h = front_cell_sizes(fields, crack, communicator).finest;
      check_input(h < std::numeric_limits<double>::max(),
                  "the " + method +
                    " level-set update found no cell at the "
                    "front of crack " +
                    std::to_string(crack + 1) +
                    ": its front lies outside the mesh, a path gone astray "
                    "(for paths that turn hard: Propagation/Level set "
                    "update/Model name = crack mesh)");
      return h;
    }



    template <int dim>
    std::vector<char>
    extend_moves(const std::size_t                                n,
                 const std::function<Point<dim>(std::size_t)>    &point_of,
                 const std::vector<double>                       &phi,
                 const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                 const std::vector<Track<dim>>                   &tracks,
                 const double                                     reach,
                 std::vector<double>                             &kink,
                 std::vector<double>                             &advance,
                 std::vector<double>                             &plane)
    {
      std::vector<char> active(n, 0);
      kink.assign(n, 0.);
      advance.assign(n, 0.);
      plane.assign(n, 0.);
      std::vector<unsigned int> front_of(n, 0);
      // Which way lsn counts along e2 at each front (e2 of the frame of K
      // need not point to the lsn > 0 side): behind a front lsn = +-(d .
      // e2).
      std::vector<double> orientation(fronts.size(), 0.);
      for (std::size_t i = 0; i < n; ++i)
        {
          if (std::isnan(phi[i]))
            continue;
          const Point<dim> x       = point_of(i);
          const auto [front, s, p] = project(fronts, x);
          if (x.distance(p) > reach)
            continue;
          active[i]                = 1;
          const Sample<dim> sample = tracks[front].at(s);
          kink[i]                  = sample.angle;
          advance[i]               = sample.advance;
          front_of[i]              = front;
          plane[i]                 = (x - p) * sample.old_normal();
          if ((x - p) * sample.old_direction() < 0)
            orientation[front] += phi[i] * plane[i];
        }
      for (std::size_t i = 0; i < n; ++i)
        if (active[i] && orientation[front_of[i]] < 0)
          {
            kink[i]  = -kink[i];
            plane[i] = -plane[i];
          }
      return active;
    }



    void
    straighten_ahead(const std::vector<char>   &mask,
                     const std::vector<double> &psi,
                     const std::vector<double> &plane,
                     std::vector<double>       &phi)
    {
      for (std::size_t i = 0; i < phi.size(); ++i)
        if (mask[i] && psi[i] > 0)
          phi[i] = plane[i];
    }



    template <int dim>
    void
    write_back(const std::function<bool(const Point<dim> &, double &, double &)>
                                                               &band_values,
               const std::vector<std::vector<FrontPoint<dim>>> &fronts,
               const std::vector<Track<dim>>                   &tracks,
               const double                                     radius,
               const double                                     largest,
               const unsigned int                               crack,
               LevelSetFields<dim>                             &fields)
    {
      const DoFHandler<dim> &dof_handler = fields.get_dof_handler();
      const MPI_Comm         comm        = dof_handler.get_communicator();
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           support);
      const IndexSet                owned = dof_handler.locally_owned_dofs();
      TrilinosWrappers::MPI::Vector new_lsn(owned, comm), new_lst(owned, comm);
      const auto                   &old_lsn = fields.lsn(crack);
      const auto                   &old_lst = fields.lst(crack);
      // The nodes ahead of the front in the ring beyond the band, with
      // their front and distance to its new extension plane.
      const double           ring = 2 * radius;
      const BoundingBox<dim> box  = front_box(fronts, ring);
      std::vector<std::tuple<types::global_dof_index, unsigned int, double>>
                          ahead;
      std::vector<double> orientation(fronts.size(), 0.);
      for (const types::global_dof_index dof : owned)
        {
          const Point<dim> &x  = support.at(dof);
          const double      t0 = old_lst[dof];
          new_lsn[dof]         = old_lsn[dof];
          new_lst[dof]         = (t0 <= 0 ? t0 - largest : t0);
          if (!box.point_inside(x))
            continue;
          const auto [front, s, p]   = project(fronts, x);
          const double      distance = x.distance(p);
          const Sample<dim> sample   = tracks[front].at(s);
          double            n, t;
          if (distance <= radius && band_values(x, n, t))
            {
              new_lsn[dof] = n;
              new_lst[dof] = t;
              if ((x - p) * sample.old_direction() < 0)
                orientation[front] +=
                  old_lsn[dof] * ((x - p) * sample.old_normal());
            }
          else if (t0 > 0 && distance <= ring &&
                   (x - p) * (sample.old_direction() + sample.new_direction()) >
                     0)
            ahead.emplace_back(dof, front, (x - p) * sample.new_normal());
        }
      Utilities::MPI::sum(ArrayView<const double>(orientation),
                          comm,
                          ArrayView<double>(orientation));
      // Beyond the band, lsn ahead of the front (ahead of the bisector of
      // the old and new directions, as in the geometric update, and lst >
      // 0) is the new extension plane; lst keeps its sign. Kept there, the
      // old lsn of a crack that turned has the sign of the side it was on
      // before: next to the band's new values behind the front, lst < 0,
      // its sign changed between two nodes, a piece of crack on the outer
      // side of the turn. (Beside and behind the front the plane is not
      // the crack's side: a node there crossed it as the crack turned.)
      for (const auto &[dof, front, n] : ahead)
        new_lsn[dof] = (orientation[front] < 0 ? -n : n);
      new_lsn.compress(VectorOperation::insert);
      new_lst.compress(VectorOperation::insert);
      fields.set(crack, new_lsn, new_lst);
    }



#define XCRACK_INSTANTIATE(dim)                                             \
  template double            NarrowBand::radius(const Enrichment<dim> *,    \
                                     const double,               \
                                     const double) const;        \
  template double            finest_front_cell(const LevelSetFields<dim> &, \
                                               const unsigned int,          \
                                               const std::string &,         \
                                               const MPI_Comm);             \
  template std::vector<char> extend_moves(                                  \
    const std::size_t,                                                      \
    const std::function<Point<dim>(std::size_t)> &,                         \
    const std::vector<double> &,                                            \
    const std::vector<std::vector<FrontPoint<dim>>> &,                      \
    const std::vector<Track<dim>> &,                                        \
    const double,                                                           \
    std::vector<double> &,                                                  \
    std::vector<double> &,                                                  \
    std::vector<double> &);                                                 \
  template void write_back(                                                 \
    const std::function<bool(const Point<dim> &, double &, double &)> &,    \
    const std::vector<std::vector<FrontPoint<dim>>> &,                      \
    const std::vector<Track<dim>> &,                                        \
    const double,                                                           \
    const double,                                                           \
    const unsigned int,                                                     \
    LevelSetFields<dim> &);
    XCRACK_INSTANTIATE(2)
    XCRACK_INSTANTIATE(3)
#undef XCRACK_INSTANTIATE
  } // namespace LevelSetUpdate
} // namespace xcrack
