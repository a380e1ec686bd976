#ifndef xcrack_level_set_update_upwind_h
#define xcrack_level_set_update_upwind_h

#include <xcrack/level_set_update/interface.h>
#include <xcrack/level_set_update/narrow_band.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * `upwind`: the level sets moved by Hamilton-Jacobi equations on an
     * auxiliary Cartesian grid over a band around the front (Gravouil, Moes
     * and Belytschko 2002; Code_Aster's UPWIND), first-order upwind
     * differences (hamilton_jacobi.h). The classic method of the level-set
     * literature, here to be compared with: it diffuses what the geometric
     * update keeps exact, and costs a grid.
     *
     * Each grid point in the band takes the advance a and kink k of its
     * projection on the old front (the velocities extended from the front),
     * and the phases run in pseudo-time:
     *
     * 1. lsn: phi_t + V |grad phi| = 0, V = max(lst, 0) asinh(tan(k)):
     *    ahead of the front the extension plane turns about it by the kink
     *    k (the rate that turns a line by k in a unit of time), behind it
     *    the crack stays;
     * 2. lst: psi_t + a cos(k) |grad psi| = 0: the plane through the front
     *    moves to the new front, which lies where both zero sets meet;
     * 3. lsn reinitialised to a distance;
     * 4. lst made orthogonal to lsn (its zero on the crack surface kept);
     * 5. lst reinitialised.
     *
     * The grid covers the body's points within the band of the front (the
     * larger of the enrichment radius and six of the finest front cells,
     * plus twice the advance: the crowns and the new front inside); at its
     * edge a missing neighbour brings no information (no ghost points), and
     * the points next to a zero set are reinitialised by projection on it.
     * The fields come from the mesh by the Q1 interpolant and go back by
     * d-linear interpolation. Mesh nodes beyond the band keep lsn,
     * and lst keeps its sign, as with `geometric`. The grid is built anew
     * at each step: nothing to checkpoint.
     */
    template <int dim>
    class Upwind : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      check_advance(const double maximum_advance) const override;

      void
      update(const unsigned int                 crack,
             const std::vector<FrontMove<dim>> &moves,
             LevelSetFields<dim>               &fields) override;

    private:
      /// The bounding box of the body (collective).
      BoundingBox<dim>
      body_box() const;

      NarrowBand narrow_band;
      /// The grid spacing in edges of the front cells.
      double spacing = 1;
      /// The most grid points allowed.
      double max_points = 2e7;
      /// Whether the run was told that its advance is below the grid.
      bool warned_short_advance = false;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
