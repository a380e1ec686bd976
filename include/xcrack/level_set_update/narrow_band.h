#ifndef xcrack_level_set_update_narrow_band_h
#define xcrack_level_set_update_narrow_band_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/xfem/enrichment.h>

#include <functional>
#include <string>
#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * The band of the Hamilton-Jacobi updates (`upwind` on its grid,
     * `simplex` on the mesh): how wide it is, how the front's moves reach its
     * points, and how its fields go back to the mesh. The equations need
     * the velocities off the front and cost what the band holds, so both
     * methods solve them only near the front, and the nodes beyond keep
     * the far rule of the geometric update.
     */
    class NarrowBand
    {
    public:
      /// Declare `Band radius` in the current subsection.
      static void
      declare_parameters(ParameterHandler &prm);

      /// Read `Band radius`; @p path names the subsection in messages.
      void
      parse_parameters(ParameterHandler &prm, const std::string &path);

      /// An InputError naming the entry if a band radius was given that is
      /// narrower than @p maximum_advance: the new front would leave it.
      void
      check_advance(const double maximum_advance) const;

      /**
       * The band's radius around the old front: the user's, or the larger
       * of @p enrichment's radius (0 without one) and six front cells of
       * size @p h, plus
       * twice the largest advance @p largest_advance (half the geometric
       * update's first term: the crowns and the enriched zone still lie
       * inside, and the cost goes with the band's cross-section;
       * doc/verification/level-set-update.md).
       */
      template <int dim>
      double
      radius(const Enrichment<dim> *enrichment,
             const double           h,
             const double           largest_advance) const;

    private:
      double      band_radius = 0;
      std::string path;
    };



    /**
     * The diameter of the finest cells at the front of crack @p crack
     * (front_cell_sizes()): the scale of the band and of its scheme.
     * Collective. Where no cell is at the front (a path gone astray left
     * its front outside the mesh), an InputError naming @p method: once
     * results are written, the run ends there with a clear message.
     */
    template <int dim>
    double
    finest_front_cell(const LevelSetFields<dim> &fields,
                      const unsigned int         crack,
                      const std::string         &method,
                      const MPI_Comm             communicator);



    /**
     * The velocities extended from the front: of the @p n points (point @p i
     * at @p point_of(i), lsn @p phi[i], NaN outside the body), those within
     * @p reach of the old fronts @p fronts take part (the returned mask);
     * each gets in @p kink and @p advance the kink (towards lsn > 0) and
     * the advance of its projection on the fronts, from the moves'
     * @p tracks, and in @p plane its signed distance to the old front's
     * tangent plane (through the projection, spanned by the front and its
     * direction; counted as lsn counts).
     */
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
                 std::vector<double>                             &plane);

    /**
     * Make lsn @p phi ahead of the old fronts (lst @p psi > 0, at the points
     * of @p mask) the distance @p plane to the front's tangent plane
     * (extend_moves()). There lsn only extends the crack, and the
     * Hamilton-Jacobi phases keep its shape (they turn it about the front);
     * a bend left where an earlier step's band met the values kept beyond
     * it would reach the front some steps later (band radius over advance)
     * and bend the crack's frame there: spurious K_II, a zigzag path,
     * pieces of crack. The crack itself (lsn = 0, lst <= 0) does not move.
     */
    void
    straighten_ahead(const std::vector<char>   &mask,
                     const std::vector<double> &psi,
                     const std::vector<double> &plane,
                     std::vector<double>       &phi);

    /**
     * Give crack @p crack of @p fields new level sets: at the mesh nodes
     * within @p radius of the old fronts @p fronts, what @p band_values
     * gives at the node's position (it returns false where it has none);
     * at the others the geometric update's far rule (lsn kept, lst behind
     * the front lowered by the largest advance @p largest, ahead kept),
     * except that lsn ahead of the front (lst > 0) within twice @p radius
     * is the distance to the new extension plane (the moves' @p tracks).
     */
    template <int dim>
    void
    write_back(const std::function<bool(const Point<dim> &, double &, double &)>
                                                               &band_values,
               const std::vector<std::vector<FrontPoint<dim>>> &fronts,
               const std::vector<Track<dim>>                   &tracks,
               const double                                     radius,
               const double                                     largest,
               const unsigned int                               crack,
               LevelSetFields<dim>                             &fields);
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
