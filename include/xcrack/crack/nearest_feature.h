#ifndef xcrack_crack_nearest_feature_h
#define xcrack_crack_nearest_feature_h

#include <deal.II/base/point.h>

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * Nearest points on the pieces of a crack surface given explicitly
   * (MeshCrack, FacetSurface): the point of a segment or triangle nearest
   * to a point, with the feature it lies on, and an R-tree of the pieces'
   * boxes that finds the pieces a nearest point can lie on. Included only
   * by the .cc files of those classes (it brings boost::geometry).
   */
  namespace NearestFeature
  {
    /// Where the nearest point lies: on corner k, on edge k (from corner k
    /// to corner k + 1, cyclically), or inside.
    struct Feature
    {
      enum Kind
      {
        corner,
        edge,
        interior
      } kind;
      unsigned int index = 0;
    };

    /// The point of segment [a, b] nearest to @p p (edge 0 is the inside).
    template <int dim>
    std::pair<Point<dim>, Feature>
    on_segment(const Point<dim> &a, const Point<dim> &b, const Point<dim> &p)
    {
      const Tensor<1, dim> t = b - a;
      const double         s =
        (t.norm_square() > 0 ? (p - a) * t / t.norm_square() : 0.);
      if (s <= 0)
        return {a, {Feature::corner, 0}};
      if (s >= 1)
        return {b, {Feature::corner, 1}};
      return {a + s * t, {Feature::interior, 0}};
    }

    /// The point of triangle (a, b, c) nearest to @p p, by the Voronoi
    /// regions of its corners, edges and inside (Ericson, Real-Time
    /// Collision Detection, 5.1.5).
    inline std::pair<Point<3>, Feature>
    on_triangle(const Point<3> &a,
                const Point<3> &b,
                const Point<3> &c,
                const Point<3> &p)
    {
      const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
      const double       d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0 && d2 <= 0)
        return {a, {Feature::corner, 0}};
      const Tensor<1, 3> bp = p - b;
      const double       d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0 && d4 <= d3)
        return {b, {Feature::corner, 1}};
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return {a + d1 / (d1 - d3) * ab, {Feature::edge, 0}};
      const Tensor<1, 3> cp = p - c;
      const double       d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0 && d5 <= d6)
        return {c, {Feature::corner, 2}};
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return {a + d2 / (d2 - d6) * ac, {Feature::edge, 2}};
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b),
                {Feature::edge, 1}};
      const double denominator = 1. / (va + vb + vc);
      return {a + vb * denominator * ab + vc * denominator * ac,
              {Feature::interior, 0}};
    }



    /**
     * An R-tree of the boxes of numbered pieces (segments, triangles, front
     * edges). The piece whose box is nearest to p (nearest_box()) bounds
     * the distance d to the nearest piece, which is among those whose
     * boxes meet the box of half-width d around p (candidates()).
     */
    template <int dim>
    class BoxTree
    {
    public:
      /// Add piece @p number spanned by @p corners (before build()).
      template <typename Container>
      void
      add(const Container &corners, const unsigned int number)
      {
        Box box(to_boost(corners[0]), to_boost(corners[0]));
        for (const auto &x : corners)
          boost::geometry::expand(box, to_boost(x));
        values.emplace_back(box, number);
      }

      /// Build the tree of the pieces added.
      void
      build()
      {
        tree = Tree(values.begin(), values.end());
        values.clear();
      }

      /// The piece whose box is nearest to @p p (the tree is not empty).
      unsigned int
      nearest_box(const Point<dim> &p) const
      {
        return tree.qbegin(boost::geometry::index::nearest(to_boost(p), 1))
          ->second;
      }

      /// The pieces whose boxes meet the box of half-width @p d around
      /// @p p: with d the distance to the piece nearest_box() gives, those
      /// the nearest point to p may lie on.
      std::vector<unsigned int>
      candidates(const Point<dim> &p, const double d) const
      {
        // Widened by rounding, so that boxes at distance exactly d count.
        const double w = d * (1 + 1e-9) + 1e-300;
        Box          ball(to_boost(p), to_boost(p));
        for (unsigned int d = 0; d < dim; ++d)
          {
            Point<dim> x = p;
            x[d] -= w;
            boost::geometry::expand(ball, to_boost(x));
            x[d] += 2 * w;
            boost::geometry::expand(ball, to_boost(x));
          }
        std::vector<Value> found;
        tree.query(boost::geometry::index::intersects(ball),
                   std::back_inserter(found));
        std::vector<unsigned int> numbers;
        for (const auto &value : found)
          numbers.push_back(value.second);
        return numbers;
      }

    private:
      using BPoint = boost::geometry::model::
        point<double, dim, boost::geometry::cs::cartesian>;
      using Box   = boost::geometry::model::box<BPoint>;
      using Value = std::pair<Box, unsigned int>;
      using Tree =
        boost::geometry::index::rtree<Value, boost::geometry::index::rstar<16>>;

      static BPoint
      to_boost(const Point<dim> &p)
      {
        BPoint b;
        boost::geometry::set<0>(b, p[0]);
        boost::geometry::set<1>(b, p[1]);
        if constexpr (dim == 3)
          boost::geometry::set<2>(b, p[2]);
        return b;
      }

      std::vector<Value> values;
      Tree               tree;
    };
  } // namespace NearestFeature
} // namespace xcrack

#endif
