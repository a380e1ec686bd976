#ifndef xcrack_level_set_update_front_track_h
#define xcrack_level_set_update_front_track_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/front_move.h>

#include <tuple>
#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * What moves at a point of a front: the kink, the advance and the frame
     * of K there (smooth along the front, unlike the frames of the
     * extracted points, which carry the noise of the level sets'
     * gradients). Samples interpolate linearly along the front.
     */
    template <int dim>
    struct Sample
    {
      double         angle = 0, advance = 0;
      Tensor<1, dim> e1, e2;

      Sample
      operator*(const double w) const
      {
        return {angle * w, advance * w, e1 * w, e2 * w};
      }

      Sample
      operator+(const Sample &other) const
      {
        return {angle + other.angle,
                advance + other.advance,
                e1 + other.e1,
                e2 + other.e2};
      }

      /// The unit direction of the old front (e1 normalised).
      Tensor<1, dim>
      old_direction() const;

      /// The unit normal of the old front (e2 made normal to e1).
      Tensor<1, dim>
      old_normal() const;

      /// The new direction: old_direction() turned by the kink angle.
      Tensor<1, dim>
      new_direction() const;

      /// The new normal: old_normal() turned by the kink angle.
      Tensor<1, dim>
      new_normal() const;
    };



    /**
     * The moves along one front, by abscissa: what every level-set update
     * method reads of a step's moves at an arbitrary point of the front.
     */
    template <int dim>
    struct Track
    {
      std::vector<double>      s;
      std::vector<Sample<dim>> samples;
      bool                     closed = false;
      double                   length = 0;

      /// The sample at abscissa @p x: linear between the points, periodic
      /// on a closed front, constant beyond the ends of an open one.
      Sample<dim>
      at(double x) const;
    };



    /**
     * The tracks of the fronts @p fronts of crack @p crack from the moves
     * @p moves of the step (moves of other cracks are skipped), each
     * sorted by abscissa; a front without moves gets an empty track.
     * @p largest_advance is set to the largest advance of the crack.
     */
    template <int dim>
    std::vector<Track<dim>>
    make_tracks(const unsigned int                               crack,
                const std::vector<FrontMove<dim>>               &moves,
                const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                double &largest_advance);

    /// Whether front @p front (a chain of points) is closed: its last point
    /// repeats its first.
    template <int dim>
    bool
    is_closed(const std::vector<FrontPoint<dim>> &front);

    /// The point of @p fronts nearest to @p x: (front, abscissa, point). A
    /// 2D tip is a front of one point, a 3D front a polyline.
    template <int dim>
    std::tuple<unsigned int, double, Point<dim>>
    project(const std::vector<std::vector<FrontPoint<dim>>> &fronts,
            const Point<dim>                                &x);

    /// The smallest and the largest diameter of the cells at a front.
    struct FrontCellSizes
    {
      double finest, largest;
    };

    /**
     * The diameters of the cells at the front of crack @p crack of
     * @p fields (collective): the cells with a vertex nearer to the front
     * than the cell's diameter. On a mesh graded towards the front the
     * finest are the cells that resolve it, the largest a coarse cell that
     * merely reaches it.
     */
    template <int dim>
    FrontCellSizes
    front_cell_sizes(const LevelSetFields<dim> &fields,
                     const unsigned int         crack,
                     const MPI_Comm             communicator);

    /// The bounding box of the points of @p fronts, widened by @p margin
    /// on every side: nodes outside it are farther than @p margin from
    /// every front, and an update need not project them.
    template <int dim>
    BoundingBox<dim>
    front_box(const std::vector<std::vector<FrontPoint<dim>>> &fronts,
              const double                                     margin);

    /**
     * The band around the front in which an update gives nodes new level
     * sets, when the user sets none: twice the larger of the enrichment
     * radius @p enrichment_radius and six front cells of size @p h (the
     * crowns of the next K extraction lie inside), plus twice the largest
     * advance @p largest_advance (the new front too).
     */
    double
    default_band(const double enrichment_radius,
                 const double h,
                 const double largest_advance);
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
