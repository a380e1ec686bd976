#ifndef xcrack_fracture_front_curve_h
#define xcrack_fracture_front_curve_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <xcrack/crack/crack_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * A front as a polyline through its points, with a frame that varies
   * continuously along it: where a point x projects (abscissa s), the
   * frame there (the auxiliary fields and theta live in it) and the
   * derivative of that frame along s, which makes the auxiliary fields of
   * a curved front compatible (see InteractionIntegral).
   *
   * The frame at s (frame_at): e2 the normals of the points interpolated
   * linearly in s, e3 the chord of the polyline over [s - step, s +
   * step], e1 = e2 x e3; its derivative along s is a central difference
   * over the same @p step, a length a few cells long (half the crown):
   * the frames of the extracted points come from level-set gradients and
   * tilt by O(h) from point to point, so the derivative must average over
   * several segments.
   */
  template <int dim>
  class FrontCurve
  {
  public:
    struct Projection
    {
      double     s = 0;
      Point<dim> foot;
      /// Rows e1, e2 (, e3): global to local components.
      Tensor<2, dim> R;
      /// d R / d s (zero in 2D).
      Tensor<2, dim> dR;
      /// Open front and x beyond one of its ends.
      bool at_end = false;
      /**
       * Which foot this is: the normal-plane foot, or where project()
       * falls back to it, the nearest point of the polyline, inside a
       * segment or at a vertex (an end of an open front included). They
       * move differently with x (grad_s()).
       */
      enum class Kind
      {
        normal_plane,
        nearest_on_segment,
        nearest_at_vertex
      };
      Kind kind = Kind::nearest_at_vertex;
      /// The segment the foot was searched from (where walks along the
      /// front start).
      unsigned int segment = 0;

      /// h_s = 1 + x1 de1/ds . e3 + x2 de2/ds . e3 at local coordinates
      /// @p xl: the Jacobian of the local coordinates along s, grad s = e3
      /// / h_s on a smooth front (1 in 2D).
      double
      jacobian_s(const Tensor<1, dim> &xl) const
      {
        if constexpr (dim == 3)
          return 1 + xl[0] * (dR[0] * R[2]) + xl[1] * (dR[1] * R[2]);
        else
          return 1;
      }
    };

    FrontCurve(const std::vector<FrontPoint<dim>> &points, const double step)
      : points(points)
      , closed(points.size() > 2 &&
               points.front().position == points.back().position)
      , length(points.back().s)
      , step(std::min(step, 0.25 * points.back().s))
    {}

    /**
     * The foot of @p x on the front: in 3D the abscissa s whose normal
     * plane holds x, (x - p(s)) . e3(s) = 0, found from the nearest point
     * of the segments @p first to @p last - 1 (all by default). The
     * nearest point itself jumps across the bisector plane of each vertex
     * on the concave side, and the auxiliary fields that live in its
     * frame jump with it; the normal-plane foot is as continuous as the
     * frame, and it is the foot whose grad s the auxiliary fields'
     * turning term assumes (aux_gradients()). Beyond half the radius of
     * curvature on the concave side the nearest point stays
     * (normal_plane_foot()). doc/verification.md, "The divergence term
     * and the foot on the front", measures both. A single point in 2D.
     */
    Projection
    project(const Point<dim>  &x,
            const unsigned int first = 0,
            unsigned int       last  = numbers::invalid_unsigned_int) const
    {
      Projection result;
      if (points.size() == 1)
        {
          result.foot = points[0].position;
          result.R    = frame_at(0);
          return result;
        }
      last                = std::min<unsigned int>(last, points.size() - 1);
      double       best   = std::numeric_limits<double>::max();
      unsigned int best_i = first;
      double       best_t = 0;
      for (unsigned int i = first; i < last; ++i)
        {
          const Tensor<1, dim> ab = points[i + 1].position - points[i].position;
          const double         t =
            std::clamp(((x - points[i].position) * ab) / (ab * ab), 0., 1.);
          const double d = (x - (points[i].position + t * ab)).norm_square();
          if (d < best)
            {
              best   = d;
              best_i = i;
              best_t = t;
            }
        }
      const FrontPoint<dim> &a = points[best_i];
      const FrontPoint<dim> &b = points[best_i + 1];
      result.foot    = a.position + best_t * (b.position - a.position);
      result.s       = a.s + best_t * (b.s - a.s);
      result.segment = best_i;
      result.kind =
        (best_t > 0 && best_t < 1 ? Projection::Kind::nearest_on_segment :
                                    Projection::Kind::nearest_at_vertex);
      result.at_end = !closed && ((best_i == 0 && best_t == 0) ||
                                  (best_i + 2 == points.size() && best_t == 1));
      result.R      = frame_at(result.s, best_i);
      if (dim == 3 && step > 0)
        {
          result.dR = frame_derivative(result.s, best_i);
          if (!result.at_end)
            normal_plane_foot(x, best_i, result);
        }
      return result;
    }

    /// A range of segments, @p first to @p last - 1, and the distance of
    /// the nearest of them to the point they were chosen for.
    struct SegmentRange
    {
      unsigned int first;
      unsigned int last;
      double       distance;
    };

    /**
     * The smallest range of segments, within @p first to @p last - 1, that
     * holds every segment whose distance to @p x exceeds the nearest one's
     * by at most @p slack: the segments that can be nearest to any point
     * within slack / 2 of x (project() on that range finds the same foot
     * as on the whole one, ties included).
     */
    SegmentRange
    near_segments(const Point<dim>  &x,
                  const double       slack,
                  const unsigned int first = 0,
                  unsigned int       last = numbers::invalid_unsigned_int) const
    {
      if (points.size() == 1)
        return {0, 1, x.distance(points[0].position)};
      last        = std::min<unsigned int>(last, points.size() - 1);
      double best = std::numeric_limits<double>::max();
      for (unsigned int i = first; i < last; ++i)
        best = std::min(best, segment_distance(i, x));
      SegmentRange range{last, first, best};
      for (unsigned int i = first; i < last; ++i)
        if (segment_distance(i, x) <= best + slack)
          {
            range.first = std::min(range.first, i);
            range.last  = std::max(range.last, i + 1);
          }
      return range;
    }

    /// Distance of the segments @p i to @p x.
    double
    segment_distance(const unsigned int i, const Point<dim> &x) const
    {
      const Tensor<1, dim> ab = points[i + 1].position - points[i].position;
      const double         t =
        std::clamp(((x - points[i].position) * ab) / (ab * ab), 0., 1.);
      return (x - (points[i].position + t * ab)).norm();
    }

    /**
     * The foot moved along the front to abscissa @p s, with its frame and
     * the frame's derivative there (the kind of @p projection kept): a
     * field that lives in the foot's frame, evaluated at a fixed x with
     * this foot, gives that field's derivative along s.
     */
    Projection
    moved(const Projection &projection, const double s) const
    {
      Projection result = projection;
      result.s          = s;
      result.foot       = position_at(s, projection.segment);
      result.R          = frame_at(s, projection.segment);
      if (dim == 3 && step > 0)
        result.dR = frame_derivative(s, projection.segment);
      return result;
    }

    /**
     * The abscissae at which derivatives along s around @p projection are
     * differenced: s -+ a ten-thousandth of the foot's segment (clamped
     * to the ends of an open front). The frame is only piecewise smooth
     * in s (a polyline, interpolated normals, chords), so the step is a
     * fraction of the scale on which its pieces vary.
     */
    std::pair<double, double>
    difference_abscissae(const Projection &projection) const
    {
      const unsigned int i     = projection.segment;
      const double       h     = 1e-4 * (points[i + 1].s - points[i].s);
      double             minus = projection.s - h, plus = projection.s + h;
      if (!closed)
        {
          minus = std::max(minus, 0.);
          plus  = std::min(plus, length);
        }
      return {minus, plus};
    }

    /**
     * grad s at @p x, whose foot is @p projection: how the foot moves with
     * x. For the normal-plane foot, from (x - p(s)) . e3(s) = 0,
     * grad s = e3 / (p' . e3 - (x - p) . e3'), with p' and e3' the
     * derivatives along s of the polyline and of the frame that project()
     * solved with (on a smooth front e3 / h_s); for the nearest point
     * inside a segment, the segment's direction over its length; zero at a
     * vertex, where the foot stays while x moves. (The nearest point also
     * jumps across the bisector planes of vertices; that jump is no
     * gradient.) Zero in 2D.
     */
    Tensor<1, dim>
    grad_s(const Point<dim> &x, const Projection &projection) const
    {
      Tensor<1, dim> result;
      if (points.size() == 1)
        return result;
      if (projection.kind == Projection::Kind::nearest_on_segment)
        {
          const FrontPoint<dim> &a  = points[projection.segment];
          const FrontPoint<dim> &b  = points[projection.segment + 1];
          const Tensor<1, dim>   ab = b.position - a.position;
          result                    = ab * ((b.s - a.s) / (ab * ab));
        }
      else if constexpr (dim == 3)
        if (projection.kind == Projection::Kind::normal_plane)
          {
            const auto [minus, plus] = difference_abscissae(projection);
            const unsigned int   i   = projection.segment;
            const Tensor<1, dim> dp =
              (position_at(plus, i) - position_at(minus, i)) / (plus - minus);
            const Tensor<1, dim> de3 =
              (frame_at(plus, i)[2] - frame_at(minus, i)[2]) / (plus - minus);
            const Tensor<1, dim> e3 = projection.R[2];
            result = e3 / (dp * e3 - (x - projection.foot) * de3);
          }
      return result;
    }

    /// The front point (position and frame) at abscissa @p s.
    FrontPoint<dim>
    at(const double s) const
    {
      if (points.size() == 1)
        return points[0];
      const unsigned int     i = segment_of(s);
      const FrontPoint<dim> &a = points[i];
      const FrontPoint<dim> &b = points[i + 1];
      const double           t = std::clamp((s - a.s) / (b.s - a.s), 0., 1.);
      const Tensor<2, dim>   R = frame_at(s);
      FrontPoint<dim>        point;
      point.position = a.position + t * (b.position - a.position);
      point.s        = s;
      for (unsigned int d = 0; d < dim; ++d)
        {
          point.e1[d] = R[0][d];
          point.e2[d] = R[1][d];
          if constexpr (dim == 3)
            point.e3[d] = R[2][d];
        }
      return point;
    }

    const std::vector<FrontPoint<dim>> &points;
    const bool                          closed;
    const double                        length;

  private:
    /// d R / d s at abscissa @p s: the central difference over the step
    /// (one-sided at the ends of an open front).
    Tensor<2, dim>
    frame_derivative(const double s, const unsigned int hint) const
    {
      double s_minus = s - step, s_plus = s + step;
      if (!closed)
        {
          s_minus = std::max(s_minus, 0.);
          s_plus  = std::min(s_plus, length);
        }
      return (frame_at(s_plus, hint) - frame_at(s_minus, hint)) /
             (s_plus - s_minus);
    }

    /**
     * Moves @p projection, the nearest point of @p x on segment @p hint,
     * to the root of g(s) = (x - p(s)) . e3(s): a Newton step with
     * g'(s) = -h_s (Projection::jacobian_s()) from the nearest point's
     * frame, then secant steps (g is only piecewise smooth: p is a
     * polyline, e3 a chord). The nearest point is within a fraction of a
     * segment of the root, so a few steps reach round-off; an open front's
     * foot stays on it (at_end beyond an end).
     *
     * Far from the front, towards its centres of curvature, the normal
     * planes of nearby abscissae cross and the root is neither unique nor
     * well conditioned (at a circle's centre every s is one). There, where
     * h_s falls under 1/2 (x farther than half the radius of curvature
     * on the concave side), or where the steps do not settle or wander
     * farther than x's distance from the front plus a segment, the
     * nearest point stays: crowns that reach so far have no continuous
     * foot to offer.
     */
    void
    normal_plane_foot(const Point<dim>  &x,
                      const unsigned int hint,
                      Projection        &projection) const
    {
      const auto g = [&](const double s, const Tensor<2, dim> &R) {
        return (x - position_at(s, hint)) * R[2];
      };
      const Tensor<1, dim> xl        = projection.R * (x - projection.foot);
      double               slope     = -projection.jacobian_s(xl);
      double               s_old     = projection.s;
      double               g_old     = g(s_old, projection.R);
      double               s         = s_old;
      const double         tolerance = 1e-14 * length;
      bool                 converged = (g_old == 0);
      for (unsigned int iteration = 0; iteration < 20 && !converged;
           ++iteration)
        {
          if (slope == 0)
            break;
          double s_new = s_old - g_old / slope;
          if (!closed)
            s_new = std::clamp(s_new, 0., length);
          s = s_new;
          if (std::abs(s_new - s_old) <= tolerance)
            {
              converged = true;
              break;
            }
          const double g_new = g(s_new, frame_at(s_new, hint));
          slope              = (g_new - g_old) / (s_new - s_old);
          s_old              = s_new;
          g_old              = g_new;
          converged          = (g_new == 0);
        }
      const double segment = points[hint + 1].s - points[hint].s;
      const double reach   = xl.norm() + segment;
      if (!converged || std::abs(s - projection.s) > reach)
        return;
      if (closed)
        s -= length * std::floor(s / length);
      Projection foot;
      foot.s       = s;
      foot.segment = hint;
      foot.kind    = Projection::Kind::normal_plane;
      foot.foot    = position_at(s, hint);
      foot.R       = frame_at(s, hint);
      foot.dR      = frame_derivative(s, hint);
      if (foot.jacobian_s(foot.R * (x - foot.foot)) < 0.5)
        return;
      foot.at_end = !closed && (s <= 0 || s >= length) &&
                    std::abs(g(s, foot.R)) > 1e-12 * length;
      if (foot.at_end)
        foot.kind = Projection::Kind::nearest_at_vertex;
      projection = foot;
    }

    /**
     * The segment holding abscissa @p s (in [0, length]): the last point
     * at or before s, clamped to the segments. With @p hint (a segment
     * near s) a walk from there, which the frames at and around a
     * projection's foot take (a few segments away at most), else a
     * binary search; both give the same segment.
     */
    unsigned int
    segment_of(const double       s,
               const unsigned int hint = numbers::invalid_unsigned_int) const
    {
      if (hint < points.size() - 1)
        {
          unsigned int i = hint;
          while (i + 2 < points.size() && !(s < points[i + 1].s))
            ++i;
          while (i > 0 && s < points[i].s)
            --i;
          return i;
        }
      const auto it =
        std::upper_bound(points.begin(),
                         points.end(),
                         s,
                         [](const double value, const FrontPoint<dim> &p) {
                           return value < p.s;
                         });
      const unsigned int i =
        (it == points.begin() ? 0 : it - points.begin() - 1);
      return std::min<unsigned int>(i, points.size() - 2);
    }

    /// The point of the polyline at abscissa @p s (wrapped on a closed
    /// front, clamped to the ends of an open one).
    Point<dim>
    position_at(double             s,
                const unsigned int hint = numbers::invalid_unsigned_int) const
    {
      if (closed)
        s -= length * std::floor(s / length);
      s                        = std::clamp(s, 0., length);
      const unsigned int     i = segment_of(s, hint);
      const FrontPoint<dim> &a = points[i];
      const FrontPoint<dim> &b = points[i + 1];
      const double           t = std::clamp((s - a.s) / (b.s - a.s), 0., 1.);
      return a.position + t * (b.position - a.position);
    }

    /**
     * Rows e1, e2 (, e3) at abscissa @p s. e2 is the normal of the points
     * interpolated; in 3D e3 is the chord of the polyline from s - step
     * to s + step (the frames of the extracted points come from Q1
     * level-set gradients and tilt by O(h) from point to point, the
     * positions are within O(h^2) of the front: the chord gives a
     * tangent whose derivative along s is the curvature, not noise).
     */
    Tensor<2, dim>
    frame_at(double             s,
             const unsigned int hint = numbers::invalid_unsigned_int) const
    {
      Tensor<1, dim> e1 = points[0].e1, e2 = points[0].e2;
      if (points.size() > 1)
        {
          if (closed)
            s -= length * std::floor(s / length);
          const unsigned int     i = segment_of(s, hint);
          const FrontPoint<dim> &a = points[i];
          const FrontPoint<dim> &b = points[i + 1];
          const double t = std::clamp((s - a.s) / (b.s - a.s), 0., 1.);
          e2             = (1 - t) * a.e2 + t * b.e2;
          e2 /= e2.norm();
          if constexpr (dim == 3)
            {
              const double   half = std::max(step, 1e-3 * length);
              Tensor<1, dim> e3 =
                position_at(s + half, i) - position_at(s - half, i);
              e3 -= (e3 * e2) * e2;
              e3 /= e3.norm();
              e1 = cross_product_3d(e2, e3);
            }
        }
      Tensor<2, dim> R;
      for (unsigned int d = 0; d < dim; ++d)
        {
          R[0][d] = e1[d];
          R[1][d] = e2[d];
        }
      if constexpr (dim == 3)
        {
          const Tensor<1, dim> e3 = cross_product_3d(e1, e2);
          for (unsigned int d = 0; d < dim; ++d)
            R[2][d] = e3[d];
        }
      return R;
    }

    const double step;
  };
} // namespace xcrack

#endif
