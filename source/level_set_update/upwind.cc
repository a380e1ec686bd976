#include <deal.II/base/mpi.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/input_error.h>
#include <xcrack/level_set_update/band_grid.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/level_set_update/hamilton_jacobi.h>
#include <xcrack/level_set_update/narrow_band.h>
#include <xcrack/level_set_update/upwind.h>
#include <xcrack/xfem/enrichment.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    void
    Upwind<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Upwind");
      NarrowBand::declare_parameters(prm);
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
      narrow_band.parse_parameters(prm, "Propagation/Level set update/Upwind");
      spacing = prm.get_double("Grid spacing");
      check_input(spacing > 0,
                  "Propagation/Level set update/Upwind/Grid spacing = " +
                    prm.get("Grid spacing") +
                    ": must be positive (in edges of the front cells).");
    }



    template <int dim>
    void
    Upwind<dim>::check_advance(const double maximum_advance) const
    {
      narrow_band.check_advance(maximum_advance);
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
      const double h  = finest_front_cell(fields, crack, "upwind", comm);
      const double dx = spacing * h / std::sqrt(dim);
      const double radius =
        narrow_band.radius(this->get_enrichment(), h, largest);
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
      std::vector<double> kink, advance, plane;
      const auto          point_of = [&grid](const std::size_t i) {
        return grid.point(i);
      };
      const std::vector<char> active = extend_moves<dim>(grid.size(),
                                                         point_of,
                                                         phi,
                                                         fronts,
                                                         tracks,
                                                         reach,
                                                         kink,
                                                         advance,
                                                         plane);
      grid.set_active(active);
      straighten_ahead(active, psi, plane, phi);
      const HamiltonJacobi::Iterations n =
        HamiltonJacobi::move_front(grid, kink, advance, reach, phi, psi);
      this->get_pcout() << "   Upwind update of crack " << crack + 1 << ": "
                        << grid.n_active() << " grid points, iterations "
                        << n.reinitialise_phi << ", " << n.orthogonalise << ", "
                        << n.reinitialise_psi << std::endl;

      // (weights() is empty off the grid.)
      write_back<dim>(
        [&](const Point<dim> &x, double &n, double &t) {
          const auto weights = grid.weights(x);
          n = t = 0;
          for (const auto &[i, w] : weights)
            {
              n += w * phi[i];
              t += w * psi[i];
            }
          return !weights.empty();
        },
        fronts,
        tracks,
        radius + largest,
        largest,
        crack,
        fields);
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
