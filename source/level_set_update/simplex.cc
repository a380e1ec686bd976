#include <xcrack/crack/crack_surface.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/level_set_update/hamilton_jacobi.h>
#include <xcrack/level_set_update/simplex.h>
#include <xcrack/level_set_update/simplex_band.h>
#include <xcrack/xfem/enrichment.h>

#include <limits>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    void
    Simplex<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Simplex");
      NarrowBand::declare_parameters(prm);
      prm.leave_subsection();
    }



    template <int dim>
    void
    Simplex<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Simplex");
      narrow_band.parse_parameters(prm, "Propagation/Level set update/Simplex");
    }



    template <int dim>
    void
    Simplex<dim>::check_advance(const double maximum_advance) const
    {
      narrow_band.check_advance(maximum_advance);
    }



    template <int dim>
    void
    Simplex<dim>::update(const unsigned int                 crack,
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
      const double   h    = finest_front_cell(fields, crack, "simplex", comm);
      const double   radius =
        narrow_band.radius(this->get_enrichment(), h, largest);
      // The band reaches a cell beyond the nodes that get new values, so
      // that those have their simplices on every side.
      const double reach = radius + largest + h;

      SimplexBand<dim> band =
        SimplexBand<dim>::gather(fields, crack, front_box(fronts, reach), comm);
      std::vector<double> phi = band.lsn(), psi = band.lst();
      std::vector<double> kink, advance, plane;
      const auto          point_of = [&band](const std::size_t i) {
        return band.point(i);
      };
      const std::vector<char> active = extend_moves<dim>(band.size(),
                                                         point_of,
                                                         phi,
                                                         fronts,
                                                         tracks,
                                                         reach,
                                                         kink,
                                                         advance,
                                                         plane);
      band.set_active(active);
      straighten_ahead(active, psi, plane, phi);
      const HamiltonJacobi::Iterations n =
        HamiltonJacobi::move_front(band, kink, advance, reach, phi, psi);
      this->get_pcout() << "   Simplex update of crack " << crack + 1 << ": "
                        << band.n_simplices() << " simplices, iterations "
                        << n.reinitialise_phi << ", " << n.orthogonalise << ", "
                        << n.reinitialise_psi << std::endl;

      write_back<dim>(
        [&](const Point<dim> &x, double &normal, double &tangent) {
          // A node at the band's edge lacks the simplices beyond it (on a
          // graded mesh a coarse cell across the edge takes its
          // neighbours' too): its lst would keep its old value where the
          // far rule lowers it, a spurious front. It gets the far rule.
          const std::size_t i = band.find(x);
          if (i == SimplexBand<dim>::none || !band.is_active(i) ||
              band.is_edge(i) || band.simplices_of(i).empty())
            return false;
          normal  = phi[i];
          tangent = psi[i];
          return true;
        },
        fronts,
        tracks,
        radius + largest,
        largest,
        crack,
        fields);
    }



    XCRACK_REGISTER_PLUGIN(Interface,
                           Simplex,
                           "simplex",
                           "the Hamilton-Jacobi phases of `upwind` on the "
                           "mesh's cells near the front split into "
                           "simplices, by the simplex scheme: no auxiliary "
                           "grid; it costs more than `upwind` and loses "
                           "some hard turns (doc/verification/"
                           "level-set-update.md) (subsection Simplex).")
  } // namespace LevelSetUpdate
} // namespace xcrack
