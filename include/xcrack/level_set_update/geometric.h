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
     * advance interpolated there along the front from the moves. With the
     * new direction e1' and normal e2' (e1, e2 turned by the kink angle)
     * and d = x - p:
     *
     * - lst = d . e1' - advance: the signed distance to the new front
     *   along the new direction;
     * - lsn = d . e2' on the side of the new segment, i.e. where
     *   d . (e1 + e1') > 0 (the bisector of the kink: lsn is continuous
     *   across it), and the old lsn on the other side, so that the crack
     *   surface behind the old front stays where it was; but where the old
     *   lst > 0 the old lsn was an extension plane, not the crack, and the
     *   new plane replaces it on both sides (else the extension planes of
     *   a crack that keeps turning pile up, and their zeros become
     *   spurious pieces of crack).
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
             LevelSetFields<dim>               &fields) const override;

    private:
      /**
       * The band radius of a step whose largest advance is
       * @p largest_advance: `Band radius`, or (0) twice the larger of the
       * enrichment radius and six diameters of the cells at the front,
       * plus twice the advance.
       */
      double
      band(const LevelSetFields<dim> &fields,
           const unsigned int         crack,
           const double               largest_advance) const;

      double band_radius = 0;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
