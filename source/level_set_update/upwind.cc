#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/input_error.h>
#include <xcrack/level_set_update/band_grid.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/level_set_update/hamilton_jacobi.h>
#include <xcrack/level_set_update/upwind.h>
#include <xcrack/xfem/enrichment.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    void
    Upwind<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Upwind");
      prm.declare_entry(
        "Band radius",
        "0",
        Patterns::Double(0),
        "The grid covers the points of the body within this distance of "
        "the front (plus the advance); mesh nodes farther away keep lsn, "
        "and lst keeps its sign. 0: the larger of the enrichment radius and "
        "six diameters of the finest front cells, plus twice the largest "
        "advance (half the geometric update's first term: the grid's cost "
        "goes with the band's cross-section). At least Propagation/Maximum "
        "advance.");
      prm.declare_entry(
        "Grid spacing",
        "1",
        Patterns::Double(),
        "The spacing of the auxiliary grid, in edges of the cells at the "
        "front (> 0). The cost grows as its inverse to the power of the "
        "dimension plus one: in 3D, 1 costs 3 to 4 times the geometric "
        "update (about 1.4 % of a run), 0.5 about ten times more; the "
        "diffusion of the scheme shrinks with it "
        "(doc/verification/level-set-update.md).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Upwind<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Upwind");
      band_radius = prm.get_double("Band radius");
      spacing     = prm.get_double("Grid spacing");
      check_input(spacing > 0,
                  "Propagation/Level set update/Upwind/Grid spacing = " +
                    prm.get("Grid spacing") +
                    ": must be positive (in edges of the front cells).");
    }



    template <int dim>
    void
    Upwind<dim>::check_advance(const double maximum_advance) const
    {
      std::ostringstream message;
      message << "Propagation/Level set update/Upwind/Band radius = "
              << band_radius
              << " is narrower than Propagation/Maximum advance = "
              << maximum_advance
              << ": the new front would leave the grid. Give a band at least "
                 "the crowns' radius plus the advance, or 0.";
      check_input(band_radius == 0 || band_radius >= maximum_advance,
                  message.str());
    }



    template <int dim>
    double
    Upwind<dim>::band(const double h, const double largest_advance) const
    {
      if (band_radius > 0)
        return band_radius;
      // Half the geometric update's first term: the crowns and the
      // enriched zone still lie inside, and the grid's cost goes with the
      // band's cross-section (the ellipse: a third of the cost, the same
      // cycles within 0.1 %; doc/verification/level-set-update.md).
      const double radius = (this->get_enrichment() ?
                               this->get_enrichment()->get_parameters().radius :
                               0.);
      return std::max(radius, 6 * h) + 2 * largest_advance;
    }



    template <int dim>
    BoundingBox<dim>
    Upwind<dim>::body_box() const
    {
      std::vector<double> lower(dim, std::numeric_limits<double>::max()),
        upper(dim, std::numeric_limits<double>::max());
      for (const auto &cell : this->get_triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::min(upper[d], -cell->vertex(v)[d]);
              }
      const MPI_Comm comm = this->get_mpi_communicator();
      Utilities::MPI::min(lower, comm, lower);
      Utilities::MPI::min(upper, comm, upper);
      Point<dim> a, b;
      for (unsigned int d = 0; d < dim; ++d)
        {
          a[d] = lower[d];
          b[d] = -upper[d];
        }
      return BoundingBox<dim>({a, b});
    }



    namespace
    {
      /**
       * The band's points of @p grid: those in the body (@p phi not NaN)
       * within @p reach of the old fronts @p fronts. At each, @p kink and
       * @p advance get the kink (towards lsn > 0) and the advance of its
       * projection on the fronts, from the moves' @p tracks: the
       * velocities extended from the front.
       */
      template <int dim>
      std::vector<char>
      extend_moves(const BandGrid<dim>                             &grid,
                   const std::vector<double>                       &phi,
                   const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                   const std::vector<Track<dim>>                   &tracks,
                   const double                                     reach,
                   std::vector<double>                             &kink,
                   std::vector<double>                             &advance)
      {
        std::vector<char> active(grid.size(), 0);
        kink.assign(grid.size(), 0.);
        advance.assign(grid.size(), 0.);
        std::vector<unsigned int> front_of(grid.size(), 0);
        // Which way lsn counts along e2 at each front (e2 of the frame of K
        // need not point to the lsn > 0 side): behind a front lsn = +-(d .
        // e2).
        std::vector<double> orientation(fronts.size(), 0.);
        for (std::size_t i = 0; i < grid.size(); ++i)
          {
            if (std::isnan(phi[i]))
              continue;
            const Point<dim> x       = grid.point(i);
            const auto [front, s, p] = project(fronts, x);
            if (x.distance(p) > reach)
              continue;
            active[i]                = 1;
            const Sample<dim> sample = tracks[front].at(s);
            kink[i]                  = sample.angle;
            advance[i]               = sample.advance;
            front_of[i]              = front;
            if ((x - p) * sample.old_direction() < 0)
              orientation[front] += phi[i] * ((x - p) * sample.old_normal());
          }
        for (std::size_t i = 0; i < grid.size(); ++i)
          if (active[i] && orientation[front_of[i]] < 0)
            kink[i] = -kink[i];
        return active;
      }



      /**
       * Give crack @p crack of @p fields the fields @p phi, @p psi of
       * @p grid: the mesh nodes within @p radius of the old fronts
       * @p fronts by interpolation; the others as the geometric update's
       * far nodes (lsn kept, lst behind the front lowered by the largest
       * advance @p largest, ahead kept).
       */
      template <int dim>
      void
      write_back(const BandGrid<dim>                             &grid,
                 const std::vector<double>                       &phi,
                 const std::vector<double>                       &psi,
                 const std::vector<std::vector<FrontPoint<dim>>> &fronts,
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
        TrilinosWrappers::MPI::Vector new_lsn(owned, comm),
          new_lst(owned, comm);
        const auto &old_lsn = fields.lsn(crack);
        const auto &old_lst = fields.lst(crack);
        for (const types::global_dof_index dof : owned)
          {
            const Point<dim> &x  = support.at(dof);
            const double      t0 = old_lst[dof];
            new_lsn[dof]         = old_lsn[dof];
            new_lst[dof]         = (t0 <= 0 ? t0 - largest : t0);
            // (weights() is empty off the grid.)
            const auto weights = grid.weights(x);
            if (weights.empty() ||
                x.distance(std::get<2>(project(fronts, x))) > radius)
              continue;
            double n = 0, t = 0;
            for (const auto &[i, w] : weights)
              {
                n += w * phi[i];
                t += w * psi[i];
              }
            new_lsn[dof] = n;
            new_lst[dof] = t;
          }
        new_lsn.compress(VectorOperation::insert);
        new_lst.compress(VectorOperation::insert);
        fields.set(crack, new_lsn, new_lst);
      }
    } // namespace



    template <int dim>
    void
    Upwind<dim>::update(const unsigned int                 crack,
                        const std::vector<FrontMove<dim>> &moves,
                        LevelSetFields<dim>               &fields)
    {
      const auto &fronts = this->get_crack_surfaces()[crack].fronts();
      double      largest;
      const std::vector<Track<dim>> tracks =
        make_tracks(crack, moves, fronts, largest);
      if (largest == 0)
        return;
      const MPI_Comm comm = this->get_mpi_communicator();
      // The cells that resolve the front set the grid and the band (the
      // largest cells that reach it are coarse ones on a graded mesh).
      const double h = front_cell_sizes(fields, crack, comm).finest;
      AssertThrow(h < std::numeric_limits<double>::max(),
                  ExcMessage("The upwind level-set update found no cell at "
                             "the front of crack " +
                             std::to_string(crack + 1) + "."));
      const double dx     = spacing * h / std::sqrt(dim);
      const double radius = band(h, largest);
      // The grid reaches a little beyond the band, so that the grid cells of
      // the mesh nodes in the band have all their corners.
      const double reach = radius + largest + 2 * dx;
      if (largest < dx && !warned_short_advance)
        {
          // The study of doc/verification/level-set-update.md: a tip asked
          // to move by 0.1 cell moved by 0.3.
          this->get_pcout()
            << "  Warning: the largest advance (" << largest
            << ") is shorter than the upwind update's grid spacing (" << dx
            << "): its first-order scheme moves a front by a fraction of a "
               "grid cell per step of its own, which such a step does not "
               "outweigh. Take a larger Propagation/Maximum advance or a "
               "smaller Propagation/Level set update/Upwind/Grid spacing."
            << std::endl;
          warned_short_advance = true;
        }

      BandGrid<dim> grid(front_box(fronts, reach),
                         body_box(),
                         dx,
                         static_cast<std::size_t>(max_points));
      auto [phi, psi] = grid.sample(fields, crack, comm);

      // The band, with the velocities extended from the front.
      std::vector<double> kink, advance;
      grid.set_active(
        extend_moves(grid, phi, fronts, tracks, reach, kink, advance));
      const HamiltonJacobi::Iterations n =
        HamiltonJacobi::move_front(grid, kink, advance, reach, phi, psi);
      this->get_pcout() << "   Upwind update of crack " << crack + 1 << ": "
                        << grid.n_active() << " grid points, iterations "
                        << n.reinitialise_phi << ", " << n.orthogonalise << ", "
                        << n.reinitialise_psi << std::endl;

      write_back(
        grid, phi, psi, fronts, radius + largest, largest, crack, fields);
    }



    XCRACK_REGISTER_PLUGIN(Interface,
                           Upwind,
                           "upwind",
                           "Hamilton-Jacobi equations on an auxiliary "
                           "Cartesian grid over a band around the front, "
                           "first-order upwind differences, with "
                           "reinitialisation and re-orthogonalisation "
                           "(subsection Upwind).")
  } // namespace LevelSetUpdate
} // namespace xcrack
