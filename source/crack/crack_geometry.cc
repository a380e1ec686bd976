#include <xcrack/crack/crack_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  std::vector<std::vector<unsigned int>>
  chain_edges(const unsigned int                                        n_nodes,
              const std::vector<std::pair<unsigned int, unsigned int>> &edges)
  {
    std::vector<std::vector<unsigned int>> neighbours(n_nodes);
    for (const auto &[a, b] : edges)
      {
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
      }
    std::vector<bool> visited(n_nodes, false);
    const auto        walk = [&](const unsigned int start) {
      std::vector<unsigned int> chain{start};
      visited[start] = true;
      for (bool extended = true; extended;)
        {
          extended = false;
          for (const unsigned int next : neighbours[chain.back()])
            if (!visited[next])
              {
                visited[next] = true;
                chain.push_back(next);
                extended = true;
                break;
              }
        }
      if (chain.size() > 2 && std::count(neighbours[chain.back()].begin(),
                                         neighbours[chain.back()].end(),
                                         start) > 0)
        chain.push_back(start);
      return chain;
    };
    std::vector<std::vector<unsigned int>> chains;
    for (unsigned int k = 0; k < n_nodes; ++k)
      if (!visited[k] && neighbours[k].size() == 1)
        chains.push_back(walk(k));
    for (unsigned int k = 0; k < n_nodes; ++k)
      if (!visited[k] && !neighbours[k].empty())
        chains.push_back(walk(k));
    return chains;
  }



  template <int dim>
  void
  orient_front(std::vector<FrontPoint<dim>> &front)
  {
    if constexpr (dim == 3)
      {
        double along = 0;
        for (unsigned int k = 0; k + 1 < front.size(); ++k)
          along += (front[k + 1].position - front[k].position) * front[k].e3;
        if (along < 0)
          std::reverse(front.begin(), front.end());
      }
    for (unsigned int k = 0; k < front.size(); ++k)
      front[k].s =
        (k == 0 ?
           0. :
           front[k - 1].s + front[k].position.distance(front[k - 1].position));
  }

  template void
  orient_front<2>(std::vector<FrontPoint<2>> &);
  template void
  orient_front<3>(std::vector<FrontPoint<3>> &);



  template <int dim>
  std::pair<Tensor<1, dim>, Tensor<1, dim>>
  LevelSetFunctions<dim>::gradients(const Point<dim> &p) const
  {
    double scale = 1;
    for (unsigned int d = 0; d < dim; ++d)
      scale = std::max(scale, std::abs(p[d]));
    const double   h = 1e-6 * scale;
    Tensor<1, dim> grad_n, grad_t;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Point<dim> plus = p, minus = p;
        plus[d] += h;
        minus[d] -= h;
        grad_n[d] = (lsn(plus) - lsn(minus)) / (2 * h);
        grad_t[d] = (lst(plus) - lst(minus)) / (2 * h);
      }
    return {grad_n, grad_t};
  }

  template class LevelSetFunctions<2>;
  template class LevelSetFunctions<3>;


  namespace
  {
    /// The intersection of two boxes (may be empty: lower > upper).
    template <int dim>
    BoundingBox<dim>
    intersect(const BoundingBox<dim> &a, const BoundingBox<dim> &b)
    {
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::max(a.get_boundary_points().first[d],
                              b.get_boundary_points().first[d]);
          upper[d] = std::min(a.get_boundary_points().second[d],
                              b.get_boundary_points().second[d]);
        }
      return BoundingBox<dim>(std::make_pair(lower, upper));
    }

    /// Whether @p p lies in @p box, with a relative tolerance.
    template <int dim>
    bool
    inside(const BoundingBox<dim> &box, const Point<dim> &p)
    {
      const double tolerance = 1e-12 * box.side_length(0);
      for (unsigned int d = 0; d < dim; ++d)
        if (p[d] < box.get_boundary_points().first[d] - tolerance ||
            p[d] > box.get_boundary_points().second[d] + tolerance)
          return false;
      return true;
    }
  } // namespace



  // ----------------------------------------------------------------- 2D

  SegmentCrack::SegmentCrack(const Point<2> &start,
                             const Point<2> &end,
                             const bool      start_is_tip,
                             const bool      end_is_tip)
    : start(start)
    , end(end)
    , tangent((end - start) / (end - start).norm())
    , normal({-tangent[1], tangent[0]})
    , start_is_tip(start_is_tip)
    , end_is_tip(end_is_tip)
  {}



  double
  SegmentCrack::lsn(const Point<2> &p) const
  {
    return (p - start) * normal;
  }



  double
  SegmentCrack::lst(const Point<2> &p) const
  {
    // Distance ahead of each tip along its own e1; a mouth does not bound
    // the crack, so the crack extends indefinitely behind it: without tips,
    // "far behind" is a large but finite number, which interpolation on a
    // cell (sums of value times shape function) can still handle.
    double value = -1e100;
    if (end_is_tip)
      value = std::max(value, (p - end) * tangent);
    if (start_is_tip)
      value = std::max(value, (start - p) * tangent);
    return value;
  }



  std::vector<FrontPoint<2>>
  SegmentCrack::front(const unsigned int, const BoundingBox<2> &) const
  {
    std::vector<FrontPoint<2>> tips;
    const auto                 add = [&](const Point<2> &p, const double sign) {
      FrontPoint<2> tip;
      tip.position = p;
      tip.e1       = sign * tangent;
      tip.e2       = Tensor<1, 2>({-tip.e1[1], tip.e1[0]});
      tips.push_back(tip);
    };
    if (start_is_tip)
      add(start, -1.);
    if (end_is_tip)
      add(end, 1.);
    return tips;
  }



  BoundingBox<2>
  SegmentCrack::bounding_box(const BoundingBox<2> &body) const
  {
    Point<2> lower, upper;
    for (unsigned int d = 0; d < 2; ++d)
      {
        lower[d] = std::min(start[d], end[d]);
        upper[d] = std::max(start[d], end[d]);
      }
    return intersect(BoundingBox<2>(std::make_pair(lower, upper)), body);
  }



  // ----------------------------------------------------------------- 3D

  PlanarCrack::PlanarCrack(const Point<3>     &center,
                           const Tensor<1, 3> &normal_,
                           const Tensor<1, 3> &u_)
    : center(center)
    , normal(normal_ / normal_.norm())
  {
    u = u_ - (u_ * normal) * normal;
    u /= u.norm();
    v = cross_product_3d(normal, u);
  }



  double
  PlanarCrack::lsn(const Point<3> &p) const
  {
    return (p - center) * normal;
  }



  double
  PlanarCrack::lst(const Point<3> &p) const
  {
    const Tensor<1, 3> d = p - center;
    return in_plane_distance(d * u, d * v);
  }



  Point<3>
  PlanarCrack::to_space(const double x, const double y) const
  {
    return center + x * u + y * v;
  }



  FrontPoint<3>
  PlanarCrack::frame(const double x,
                     const double y,
                     const double nx,
                     const double ny) const
  {
    FrontPoint<3> point;
    point.position = to_space(x, y);
    point.e1       = nx * u + ny * v;
    point.e1 /= point.e1.norm();
    point.e2 = normal;
    point.e3 = cross_product_3d(point.e1, point.e2);
    return point;
  }



  HalfPlaneCrack::HalfPlaneCrack(const Point<3>     &point_on_front,
                                 const Tensor<1, 3> &normal,
                                 const Tensor<1, 3> &propagation)
    : PlanarCrack(point_on_front, normal, propagation)
  {}



  double
  HalfPlaneCrack::in_plane_distance(const double x, const double) const
  {
    return x;
  }



  std::vector<FrontPoint<3>>
  HalfPlaneCrack::front(const unsigned int    n_points,
                        const BoundingBox<3> &body) const
  {
    // The front line center + t v, clipped to the body box.
    double t_min = -std::numeric_limits<double>::max();
    double t_max = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < 3; ++d)
      {
        const double lo = body.get_boundary_points().first[d] - center[d];
        const double hi = body.get_boundary_points().second[d] - center[d];
        if (std::abs(v[d]) < 1e-14)
          {
            if (lo > 0 || hi < 0)
              return {};
            continue;
          }
        const double t1 = lo / v[d], t2 = hi / v[d];
        t_min = std::max(t_min, std::min(t1, t2));
        t_max = std::min(t_max, std::max(t1, t2));
      }
    std::vector<FrontPoint<3>> points;
    if (t_min >= t_max || n_points == 0)
      return points;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const double t =
          (n_points == 1 ? 0.5 * (t_min + t_max) :
                           t_min + (t_max - t_min) * i / (n_points - 1));
        points.push_back(frame(0, t, 1, 0));
      }
    orient_front(points);
    return points;
  }



  BoundingBox<3>
  HalfPlaneCrack::bounding_box(const BoundingBox<3> &body) const
  {
    // The half-plane is unbounded: the part of the body box behind the
    // front, which contains the crack surface inside the body.
    return body;
  }



  EllipticalCrack::EllipticalCrack(const Point<3>     &center,
                                   const Tensor<1, 3> &normal,
                                   const Tensor<1, 3> &major_axis,
                                   const double        a,
                                   const double        b)
    : PlanarCrack(center, normal, major_axis)
    , a(a)
    , b(b)
  {}



  double
  EllipticalCrack::closest_point(const double px,
                                 const double py,
                                 double      &x,
                                 double      &y) const
  {
    // Work in the first quadrant with e0 >= e1, as in D. Eberly, "Distance
    // from a point to an ellipse, an ellipsoid, or a hyperellipsoid" (2013).
    const bool   swap = (b > a);
    const double e0 = swap ? b : a, e1 = swap ? a : b;
    // Coordinates within round-off of an axis are on it (the root s below
    // tends to -1 near the centre, and s + 1 rounds to 0: a vertex at the
    // centre of a penny once gave lst = -inf).
    const double tiny = 1e-12 * e0;
    double       y0 = std::abs(swap ? py : px), y1 = std::abs(swap ? px : py);
    if (y0 < tiny)
      y0 = 0;
    if (y1 < tiny)
      y1 = 0;
    double x0, x1;

    if (e0 == e1)
      {
        // A circle: the radial projection, accurate down to the centre.
        const double r = std::hypot(y0, y1);
        x0             = (r > 0 ? e0 * y0 / r : e0);
        x1             = (r > 0 ? e0 * y1 / r : 0);
      }
    else if (y1 > 0)
      {
        if (y0 > 0)
          {
            const double z0 = y0 / e0, z1 = y1 / e1;
            const double g = z0 * z0 + z1 * z1 - 1;
            if (g != 0)
              {
                // Root of F(s) = (r0 z0/(s + r0))^2 + (z1/(s + 1))^2 - 1.
                const double r0 = (e0 / e1) * (e0 / e1);
                const double n0 = r0 * z0;
                double       s0 = z1 - 1;
                double s1 = (g < 0 ? 0 : std::sqrt(n0 * n0 + z1 * z1) - 1);
                double s  = 0;
                for (unsigned int i = 0; i < 200; ++i)
                  {
                    s = 0.5 * (s0 + s1);
                    if (s == s0 || s == s1)
                      break;
                    const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1);
                    const double f = ratio0 * ratio0 + ratio1 * ratio1 - 1;
                    if (f > 0)
                      s0 = s;
                    else if (f < 0)
                      s1 = s;
                    else
                      break;
                  }
                x0 = r0 * y0 / (s + r0);
                // Near the centre s + 1 is small and y1 / (s + 1) loses the
                // digits that the ellipse's equation keeps.
                x1 =
                  (s + 1 > 0.5 ?
                     y1 / (s + 1) :
                     e1 * std::sqrt(std::max(0., 1 - (x0 / e0) * (x0 / e0))));
              }
            else
              {
                x0 = y0;
                x1 = y1;
              }
          }
        else
          {
            x0 = 0;
            x1 = e1;
          }
      }
    else
      {
        // On the major axis: the closest point is off the axis only inside
        // the evolute (never for a circle, where denom0 = 0).
        const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
        if (numer0 < denom0)
          {
            const double xde0 = numer0 / denom0;
            x0                = e0 * xde0;
            x1                = e1 * std::sqrt(1 - xde0 * xde0);
          }
        else
          {
            x0 = e0;
            x1 = 0;
          }
      }

    // Back to the original quadrant and axes.
    x0 = std::copysign(x0, swap ? py : px);
    x1 = std::copysign(x1, swap ? px : py);
    x  = swap ? x1 : x0;
    y  = swap ? x0 : x1;

    const double distance  = std::hypot(px - x, py - y);
    const bool   is_inside = (px / a) * (px / a) + (py / b) * (py / b) < 1;
    return is_inside ? -distance : distance;
  }



  double
  EllipticalCrack::in_plane_distance(const double px, const double py) const
  {
    double x, y;
    return closest_point(px, py, x, y);
  }



  std::vector<FrontPoint<3>>
  EllipticalCrack::front(const unsigned int    n_points,
                         const BoundingBox<3> &body) const
  {
    std::vector<FrontPoint<3>> points;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const double phi = 2 * numbers::PI * i / n_points;
        const double x = a * std::cos(phi), y = b * std::sin(phi);
        // Outward normal of the ellipse: gradient of (x/a)^2 + (y/b)^2.
        const FrontPoint<3> point = frame(x, y, x / (a * a), y / (b * b));
        if (inside(body, point.position))
          points.push_back(point);
      }
    orient_front(points);
    return points;
  }



  BoundingBox<3>
  EllipticalCrack::bounding_box(const BoundingBox<3> &body) const
  {
    Point<3> lower, upper;
    for (unsigned int d = 0; d < 3; ++d)
      {
        const double extent = std::hypot(a * u[d], b * v[d]);
        lower[d]            = center[d] - extent;
        upper[d]            = center[d] + extent;
      }
    return intersect(BoundingBox<3>(std::make_pair(lower, upper)), body);
  }



  RectangularCrack::RectangularCrack(const Point<3>     &center,
                                     const Tensor<1, 3> &normal,
                                     const Tensor<1, 3> &u,
                                     const double        width,
                                     const double        height)
    : PlanarCrack(center, normal, u)
    , half_width(width / 2)
    , half_height(height / 2)
  {}



  double
  RectangularCrack::in_plane_distance(const double x, const double y) const
  {
    const double qx = std::abs(x) - half_width, qy = std::abs(y) - half_height;
    const double outside = std::hypot(std::max(qx, 0.), std::max(qy, 0.));
    const double inside  = std::min(std::max(qx, qy), 0.);
    return outside + inside;
  }



  std::vector<FrontPoint<3>>
  RectangularCrack::front(const unsigned int    n_points,
                          const BoundingBox<3> &body) const
  {
    // Walk the boundary counter-clockwise (from u towards v), starting at
    // the corner (w, -h).
    const double               perimeter = 4 * (half_width + half_height);
    std::vector<FrontPoint<3>> points;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        double        t = perimeter * (i + 0.5) / n_points;
        const double  w = half_width, h = half_height;
        FrontPoint<3> point;
        if (t < 2 * h)
          point = frame(w, -h + t, 1, 0);
        else if ((t -= 2 * h) < 2 * w)
          point = frame(w - t, h, 0, 1);
        else if ((t -= 2 * w) < 2 * h)
          point = frame(-w, h - t, -1, 0);
        else
          point = frame(-w + (t - 2 * h), -h, 0, -1);
        if (inside(body, point.position))
          points.push_back(point);
      }
    orient_front(points);
    return points;
  }



  BoundingBox<3>
  RectangularCrack::bounding_box(const BoundingBox<3> &body) const
  {
    Point<3> lower, upper;
    for (unsigned int d = 0; d < 3; ++d)
      {
        const double extent =
          std::abs(half_width * u[d]) + std::abs(half_height * v[d]);
        lower[d] = center[d] - extent;
        upper[d] = center[d] + extent;
      }
    return intersect(BoundingBox<3>(std::make_pair(lower, upper)), body);
  }
} // namespace xcrack
