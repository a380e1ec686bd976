#ifndef xcrack_level_set_update_crack_mesh_h
#define xcrack_level_set_update_crack_mesh_h

#include <xcrack/crack/facet_surface.h>
#include <xcrack/level_set_update/interface.h>
#include <xcrack/simulator_access.h>

#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * `crack mesh`: the crack kept as an explicit surface (segments in 2D,
     * triangles in 3D; a FacetSurface), extended at each step by the strip
     * its fronts sweep, and the level sets computed anew on every node by
     * projection on it (the seed's fourth method; Code_Aster's crack
     * given by a mesh).
     *
     * The surface starts, at the first update, as the lips the fields draw
     * (CrackSurface::lips()), its fronts as the extracted ones. A step adds
     * the strip between each point p of the surface's fronts and p + a (cos
     * k e1 + sin k e2), a and k the advance and kink interpolated from the
     * moves at p's projection on the extracted front; the advanced points
     * with their new direction become the fronts. Growing from its own
     * fronts, not from the extracted ones, the surface does not lose at
     * every step the sagitta that the Q1 fields cut off a curved front;
     * points are added where a growing front's points drift apart.
     *
     * What it buys: lsn is the distance to the surface everywhere, so a
     * crack that keeps turning leaves no extension planes behind (the
     * spurious pieces of the geometric method past 80 degrees of turn),
     * and the surface behind the front never moves. What it costs: a
     * nearest-facet search per node (R-trees), and the surface grows by a
     * strip per step. The surface is written each step as
     * `crack_mesh[i]-<step>.vtu` and saved with the checkpoint.
     */
    template <int dim>
    class CrackMesh : public Interface<dim>, public SimulatorAccess<dim>
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

      void
      save(Plugins::State &state) const override;

      void
      load(const Plugins::State &state) override;

    private:
      /// A point that advances, with its abscissa on the extracted front.
      struct Start
      {
        Point<dim> x;
        double     s;
      };

      /**
       * The points of crack @p crack that advance, per extracted front:
       * the surface's own front nodes, so that its fronts move as the moves
       * say (the extracted fronts lie on the Q1 fields' zeros, which cut the
       * chords off a curved front: a surface grown from them would lose that
       * sagitta at every step), with points added where they drifted
       * apart; at the first step, or where the fronts changed in number, the
       * extracted fronts themselves.
       */
      std::vector<std::vector<Start>>
      starting_points(const unsigned int crack) const;

      /// The strip swept by the fronts of crack @p crack, and the new
      /// fronts, from the tracks of the step's moves.
      void
      extend(const unsigned int                 crack,
             const std::vector<FrontMove<dim>> &moves);

      bool write_surface = true;

      /// Per crack; empty until the crack's first update.
      std::vector<FacetSurface<dim>> surfaces;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
