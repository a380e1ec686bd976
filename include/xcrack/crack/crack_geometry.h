#ifndef xcrack_crack_crack_geometry_h
#define xcrack_crack_crack_geometry_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * A point of a crack front with its local frame, in the conventions of
   * doc/benchmarks.md: e1 lies in the crack plane, normal to the front and
   * pointing ahead of it (the propagation direction); e2 is the crack-plane
   * normal, pointing to the "upper" lip (lsn > 0 for a crack whose front
   * frames all share one normal); in 3D e3 = e1 x e2 is tangent to the
   * front. In 2D e2 is e1 rotated by +90 degrees and e3 is unused.
   *
   * s is the curvilinear abscissa along the front (0 for a 2D tip).
   */
  template <int dim>
  struct FrontPoint
  {
    Point<dim>     position;
    double         s = 0;
    Tensor<1, dim> e1;
    Tensor<1, dim> e2;
    Tensor<1, dim> e3;

    /// Write or read with a boost archive (checkpoints).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &position &s &e1 &e2 &e3;
    }
  };

  /**
   * Join the edges (pairs of node indices among @p n_nodes) into chains of
   * nodes: the open ones from an end first, then the closed ones, whose
   * last node repeats the first. Each edge is used once; at a node with
   * more than two edges the walk takes the first unused one.
   */
  std::vector<std::vector<unsigned int>>
  chain_edges(const unsigned int                                        n_nodes,
              const std::vector<std::pair<unsigned int, unsigned int>> &edges);

  /**
   * Orient an ordered 3D front along its tangent e3 = e1 x e2 (reverse it
   * if it runs the other way on the whole) and fill the abscissae s from
   * 0; in 2D only the abscissae.
   */
  template <int dim>
  void
  orient_front(std::vector<FrontPoint<dim>> &front);



  /**
   * A pair of level sets as functions of the position:
   *
   * - lsn, the normal level set: signed distance to the crack surface
   *   extended beyond the front, positive on the side its normal points to;
   * - lst, the tangent level set: signed distance to the front measured in
   *   that surface, negative on the crack and positive ahead of the front.
   *
   * The crack is {lsn = 0, lst <= 0} and its front {lsn = 0, lst = 0}. Near
   * a front, r = sqrt(lsn^2 + lst^2) and theta = atan2(lsn, lst) are the
   * polar coordinates of the crack-tip fields (for 2D crack tips whose e2
   * points to the lsn > 0 side; the frame of each FrontPoint is the
   * reference).
   *
   * The enrichment functions (jump and branch functions) evaluate this:
   * during a run, the interpolants of a crack's level-set fields in one
   * cell (CellLevelSets); in tests and for the initial shapes, the
   * analytic CrackGeometry.
   */
  template <int dim>
  class LevelSetFunctions
  {
  public:
    virtual ~LevelSetFunctions() = default;

    /// Normal level set at @p p.
    virtual double
    lsn(const Point<dim> &p) const = 0;

    /// Tangent level set at @p p.
    virtual double
    lst(const Point<dim> &p) const = 0;

    /**
     * (grad lsn, grad lst) at @p p. By default central differences with a
     * step of 1e-6 of the size of the coordinates (the level sets are
     * smooth near a front: error ~ step^2); the branch functions'
     * derivatives need them.
     */
    virtual std::pair<Tensor<1, dim>, Tensor<1, dim>>
    gradients(const Point<dim> &p) const;
  };



  /**
   * The shape a crack is given in the parameter file: its level sets
   * everywhere (LevelSetFunctions), its front with local frames, and its
   * extent. Analytic shapes implement this exactly; a crack given by a
   * surface mesh computes it by projection.
   *
   * A shape only initialises a crack: the Simulator interpolates its level
   * sets on the mesh (LevelSetFields), and from there on the fields are
   * the crack for everything downstream (enrichment, rules, fronts, K
   * extraction, propagation).
   */
  template <int dim>
  class CrackGeometry : public LevelSetFunctions<dim>
  {
  public:
    /**
     * The front with local frames: the tips of a 2D crack, or @p n_points
     * points along a 3D front, ordered along it with their abscissa s.
     * Fronts that are not closed (half-plane) are clipped to @p body.
     */
    virtual std::vector<FrontPoint<dim>>
    front(const unsigned int n_points, const BoundingBox<dim> &body) const = 0;

    /// A box that contains the crack surface, clipped to @p body.
    virtual BoundingBox<dim>
    bounding_box(const BoundingBox<dim> &body) const = 0;

    /**
     * Called once the body's mesh is known, before the level sets are
     * used. Analytic shapes need nothing (the level sets extend through
     * the body's surface); a crack given by a surface mesh decides there
     * which of its boundary edges are front and which are mouths.
     */
    virtual void
    locate_in(const Triangulation<dim> &)
    {}
  };



  /**
   * A straight 2D crack from @p start to @p end. Each end is a tip unless it
   * is declared a mouth (an end on or outside the boundary of the body, as
   * for an edge crack). The normal is the direction end - start rotated by
   * +90 degrees.
   */
  class SegmentCrack : public CrackGeometry<2>
  {
  public:
    SegmentCrack(const Point<2> &start,
                 const Point<2> &end,
                 const bool      start_is_tip,
                 const bool      end_is_tip);

    double
    lsn(const Point<2> &p) const override;
    double
    lst(const Point<2> &p) const override;
    std::vector<FrontPoint<2>>
    front(const unsigned int    n_points,
          const BoundingBox<2> &body) const override;
    BoundingBox<2>
    bounding_box(const BoundingBox<2> &body) const override;

  private:
    Point<2>     start, end;
    Tensor<1, 2> tangent, normal;
    bool         start_is_tip, end_is_tip;
  };



  /**
   * A planar 3D crack described in its own frame (u, v, normal) centred at
   * @p center: the base of the half-plane, penny, ellipse and rectangle
   * shapes. lsn is the distance to the plane; lst the signed distance, in
   * the plane, to the shape's boundary curve.
   */
  class PlanarCrack : public CrackGeometry<3>
  {
  public:
    /**
     * @p normal and @p u need not be unit vectors; u is made orthogonal to
     * the normal. v = normal x u.
     */
    PlanarCrack(const Point<3>     &center,
                const Tensor<1, 3> &normal,
                const Tensor<1, 3> &u);

    double
    lsn(const Point<3> &p) const override;
    double
    lst(const Point<3> &p) const override;

  protected:
    /// Signed distance of the in-plane point (x, y) to the shape's boundary.
    virtual double
    in_plane_distance(const double x, const double y) const = 0;

    /// Point at in-plane coordinates (x, y).
    Point<3>
    to_space(const double x, const double y) const;

    /**
     * Front frame at the in-plane point (x, y) with in-plane outward normal
     * (nx, ny) of the shape's boundary.
     */
    FrontPoint<3>
    frame(const double x,
          const double y,
          const double nx,
          const double ny) const;

    Point<3>     center;
    Tensor<1, 3> normal, u, v;
  };



  /// Half-plane crack: the front is the line through @p center along v.
  class HalfPlaneCrack : public PlanarCrack
  {
  public:
    /// @p propagation is e1: the crack lies on the side opposite to it.
    HalfPlaneCrack(const Point<3>     &point_on_front,
                   const Tensor<1, 3> &normal,
                   const Tensor<1, 3> &propagation);

    std::vector<FrontPoint<3>>
    front(const unsigned int    n_points,
          const BoundingBox<3> &body) const override;
    BoundingBox<3>
    bounding_box(const BoundingBox<3> &body) const override;

  protected:
    double
    in_plane_distance(const double x, const double y) const override;
  };



  /**
   * Elliptical crack with semi-axes @p a along u and @p b along v; a penny
   * is the case a = b. A semi-elliptical surface crack is an ellipse whose
   * centre lies on a face of the body: the body clips it.
   */
  class EllipticalCrack : public PlanarCrack
  {
  public:
    EllipticalCrack(const Point<3>     &center,
                    const Tensor<1, 3> &normal,
                    const Tensor<1, 3> &major_axis,
                    const double        a,
                    const double        b);

    /**
     * Front points at equal steps of the parametric angle phi, a front
     * point being (a cos phi, b sin phi), phi from 0 (the u axis) towards v.
     * Points outside @p body are dropped.
     */
    std::vector<FrontPoint<3>>
    front(const unsigned int    n_points,
          const BoundingBox<3> &body) const override;
    BoundingBox<3>
    bounding_box(const BoundingBox<3> &body) const override;

    /**
     * Closest point (x, y) on the ellipse to the in-plane point (px, py),
     * by Eberly's robust bisection; returns the signed distance (negative
     * inside).
     */
    double
    closest_point(const double px, const double py, double &x, double &y) const;

  protected:
    double
    in_plane_distance(const double x, const double y) const override;

  private:
    double a, b;
  };



  /// Rectangular crack of sides @p width along u and @p height along v.
  class RectangularCrack : public PlanarCrack
  {
  public:
    RectangularCrack(const Point<3>     &center,
                     const Tensor<1, 3> &normal,
                     const Tensor<1, 3> &u,
                     const double        width,
                     const double        height);

    /**
     * Front points spread over the four sides in proportion to their
     * length, at the middle of equal sub-segments so that no point sits on
     * a corner, where e1 is not defined.
     */
    std::vector<FrontPoint<3>>
    front(const unsigned int    n_points,
          const BoundingBox<3> &body) const override;
    BoundingBox<3>
    bounding_box(const BoundingBox<3> &body) const override;

  protected:
    double
    in_plane_distance(const double x, const double y) const override;

  private:
    double half_width, half_height;
  };
} // namespace xcrack

#endif
