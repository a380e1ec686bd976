#ifndef xcrack_level_set_update_geometric_h
#define xcrack_level_set_update_geometric_h

#include <xcrack/level_set_update/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * `geometric`: the update without a partial differential equation
     * (Colombo and Massin 2011; the seed's chapter 5), 3 to 30 times
     * faster than upwind schemes and free of their diffusion.
     *
     * Every node within `Band radius` of the old front is projected onto
     * it (the front as the fields show it, a polyline with frames), which
     * gives a front point p with frame (e1, e2), and the kink angle and
     * advance interpolated there along the front from the moves. The
     * node's coordinates in that frame are the old level sets, t = lst and
     * n = +-lsn (the sign that makes it d . e2 behind the front, d = x - p),
     * where they agree with d . e1 and d . e2 within a front cell, else
     * the latter (farther nodes keep only the signs of their old values, so
     * a node entering the band may bring a stale value); with the kink
     * angle k and the new direction
     * e1' = cos(k) e1 + sin(k) e2:
     *
     * - lst = t cos(k) + n sin(k) - advance: the signed distance to the new
     *   front along the new direction;
     * - lsn = +-(n cos(k) - t sin(k)) on the side of the new segment, where
     *   d . (e1 + e1') > 0 (the bisector of the kink: lsn is continuous
     *   across it), and the old lsn on the other side, so that the crack
     *   surface behind the old front stays where it was; but where the old
     *   lst > 0 the old lsn was an extension plane, not the crack, and the
     *   new plane replaces it on both sides (else the extension planes of
     *   a crack that keeps turning pile up, and their zeros become
     *   spurious pieces of crack).
     *
     * Taking t and n from the old fields rather than as d . e1 and d . e2
     * keeps the discrete front's shape: d ends on the chords of the
     * polyline, inside a curved front, and a penny lost the chords'
     * sagitta of radius at every step (doc/verification.md).
     *
     * Nodes farther away keep lsn, and lst keeps its sign (behind stays
     * behind, ahead stays ahead: the front moved less than the band): only
     * the signs matter there. A 2D tip is a front of one point; a
     * 3D front may be open (ending on the body's surface) or closed.
     */
    template <int dim>
    class Geometric : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      update(const unsigned int                 crack,
             const std::vector<FrontMove<dim>> &moves,
             LevelSetFields<dim>               &fields) override;

    private:
      /**
       * The band radius of a step whose largest advance is
       * @p largest_advance, with front cells of size @p h: `Band radius`,
       * or (0) twice the larger of the enrichment radius and six front
       * cells, plus twice the advance.
       */
      double
      band(const double h, const double largest_advance) const;

      double band_radius = 0;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
