#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <xcrack/xfem/cell_quadrature.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace xcrack
{
  namespace CellQuadrature
  {
    namespace
    {
      /**
       * The Q1 interpolant of vertex values on the reference cell, with the
       * value, gradient and Hessian the quadrature generator asks for.
       */
      template <int dim>
      class ReferenceCellLevelSet : public Function<dim>
      {
      public:
        explicit ReferenceCellLevelSet(const std::vector<double> &vertex_values)
          : vertex_values(vertex_values)
        {}

        double
        value(const Point<dim> &p, const unsigned int = 0) const override
        {
          double v = 0;
          for (unsigned int i = 0; i < vertex_values.size(); ++i)
            v += vertex_values[i] * q1.shape_value(i, p);
          return v;
        }

        Tensor<1, dim>
        gradient(const Point<dim> &p, const unsigned int = 0) const override
        {
          Tensor<1, dim> g;
          for (unsigned int i = 0; i < vertex_values.size(); ++i)
            g += vertex_values[i] * q1.shape_grad(i, p);
          return g;
        }

        SymmetricTensor<2, dim>
        hessian(const Point<dim> &p, const unsigned int = 0) const override
        {
          Tensor<2, dim> h;
          for (unsigned int i = 0; i < vertex_values.size(); ++i)
            h += vertex_values[i] * q1.shape_grad_grad(i, p);
          return symmetrize(h);
        }

      private:
        // FE_Q(1) numbers its shape functions like the cell's vertices.
        const FE_Q<dim>     q1{1};
        std::vector<double> vertex_values;
      };

      using Square = std::array<double, 4>; // values at (0,0),(1,0),(0,1),(1,1)

      double
      bilinear(const Square &f, const Point<2> &p)
      {
        return f[0] + (f[1] - f[0]) * p[0] + (f[2] - f[0]) * p[1] +
               (f[0] - f[1] - f[2] + f[3]) * p[0] * p[1];
      }

      double
      max_abs(const Square &f)
      {
        double m = 0;
        for (const double v : f)
          m = std::max(m, std::abs(v));
        return m;
      }

      /// The corners of the unit square counterclockwise, as vertex indices.
      constexpr std::array<unsigned int, 4> ccw_corners = {{0, 1, 3, 2}};

      Point<2>
      corner(const unsigned int vertex)
      {
        return Point<2>(vertex % 2, vertex / 2);
      }

      void
      add_unique(std::vector<Point<2>> &points, const Point<2> &p)
      {
        for (const auto &q : points)
          if (q.distance(p) < 1e-10)
            return;
        points.push_back(p);
      }

      /// Where f vanishes on the boundary of the square (a whole edge on
      /// which it vanishes contributes its two ends).
      std::vector<Point<2>>
      boundary_zeros(const Square &f)
      {
        std::vector<Point<2>> points;
        for (unsigned int e = 0; e < 4; ++e)
          {
            const unsigned int a = ccw_corners[e], b = ccw_corners[(e + 1) % 4];
            if (f[a] == 0)
              add_unique(points, corner(a));
            if (f[a] * f[b] < 0)
              add_unique(points,
                         corner(a) +
                           f[a] / (f[a] - f[b]) * (corner(b) - corner(a)));
          }
        return points;
      }

      /**
       * The common zeros of two bilinear functions on the closed unit square.
       * Eliminating y from f = (a0 + a1 x) + (a2 + a3 x) y = 0 and the same
       * for g leaves a quadratic in x. When one of them vanishes identically
       * (a face in the crack plane), the zeros of the other on the boundary
       * stand for the curve it leaves.
       */
      std::vector<Point<2>>
      common_zeros(Square f, Square g, const bool clip = true)
      {
        const double scale = std::max(max_abs(f), max_abs(g));
        if (scale == 0)
          return {};
        for (unsigned int i = 0; i < 4; ++i)
          {
            f[i] /= scale;
            g[i] /= scale;
          }
        constexpr double zero = 1e-12;
        if (max_abs(f) <= zero)
          return boundary_zeros(g);
        if (max_abs(g) <= zero)
          return boundary_zeros(f);

        const double a0 = f[0], a1 = f[1] - f[0], a2 = f[2] - f[0],
                     a3 = f[0] - f[1] - f[2] + f[3];
        const double b0 = g[0], b1 = g[1] - g[0], b2 = g[2] - g[0],
                     b3 = g[0] - g[1] - g[2] + g[3];
        const double c2 = a1 * b3 - b1 * a3;
        const double c1 = a0 * b3 + a1 * b2 - b0 * a3 - b1 * a2;
        const double c0 = a0 * b2 - b0 * a2;

        std::vector<double> roots;
        const double        c_max =
          std::max({std::abs(c0), std::abs(c1), std::abs(c2)});
        if (c_max <= zero)
          return {}; // f and g proportional: no isolated crossing
        if (std::abs(c2) <= zero * c_max)
          roots.push_back(-c0 / c1);
        else
          {
            double disc = c1 * c1 - 4 * c2 * c0;
            if (disc < 0 && disc > -zero * c_max * c_max)
              disc = 0;
            if (disc >= 0)
              {
                // The numerically stable pair of roots.
                const double q =
                  -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
                roots.push_back(q / c2);
                if (q != 0)
                  roots.push_back(c0 / q);
              }
          }

        constexpr double      tol = 1e-10;
        std::vector<Point<2>> points;
        for (double x : roots)
          {
            if (clip && !(x >= -tol && x <= 1 + tol))
              continue;
            if (clip)
              x = std::clamp(x, 0., 1.);
            const double fa  = a2 + a3 * x;
            const double ga  = b2 + b3 * x;
            const bool   use = std::abs(fa) >= std::abs(ga);
            if (std::max(std::abs(fa), std::abs(ga)) <= zero)
              continue; // both independent of y here
            double y = (use ? -(a0 + a1 * x) / fa : -(b0 + b1 * x) / ga);
            if (clip && !(y >= -tol && y <= 1 + tol))
              continue;
            if (clip)
              y = std::clamp(y, 0., 1.);
            const Point<2> p(x, y);
            if (std::abs(bilinear(f, p)) <= 1e-8 &&
                std::abs(bilinear(g, p)) <= 1e-8)
              add_unique(points, p);
          }
        return points;
      }

      Square
      square_of(const std::vector<double> &values)
      {
        return {{values[0], values[1], values[2], values[3]}};
      }

      /**
       * The fan of triangles from @p tip to the boundary of the unit square,
       * with the boundary points where lsn changes sign among the corners,
       * each integrated by a Duffy collapse at the tip graded as u = s^2.
       */
      Quadrature<2>
      fan_rule(const Point<2>    &tip,
               const Square      &lsn,
               const unsigned int n_points_1d)
      {
        std::vector<Point<2>> polygon;
        for (unsigned int e = 0; e < 4; ++e)
          {
            const unsigned int a = ccw_corners[e], b = ccw_corners[(e + 1) % 4];
            polygon.push_back(corner(a));
            if (lsn[a] * lsn[b] < 0)
              polygon.push_back(corner(a) + lsn[a] / (lsn[a] - lsn[b]) *
                                              (corner(b) - corner(a)));
          }

        const QGauss<1>       gauss(n_points_1d);
        std::vector<Point<2>> points;
        std::vector<double>   weights;
        for (unsigned int k = 0; k < polygon.size(); ++k)
          {
            const Point<2> &a = polygon[k];
            const Point<2> &b = polygon[(k + 1) % polygon.size()];
            const double    cross =
              (a - tip)[0] * (b - tip)[1] - (a - tip)[1] * (b - tip)[0];
            if (cross <= 2e-14)
              continue; // the tip lies on this piece of the boundary
            // Along the edge the integrands vary like 1/distance to the tip:
            // wide triangles are cut into pieces of at most 45 degrees seen
            // from the tip, on which that is smooth enough for Gauss.
            const double       angle = std::atan2(cross, (a - tip) * (b - tip));
            const unsigned int pieces =
              static_cast<unsigned int>(std::ceil(angle / (numbers::PI / 4)));
            for (unsigned int p = 0; p < pieces; ++p)
              {
                const Point<2>     a_p = a + (double(p) / pieces) * (b - a);
                const Point<2>     b_p = a + (double(p + 1) / pieces) * (b - a);
                const Tensor<1, 2> ta = a_p - tip, ab = b_p - a_p;
                const double       area = 0.5 * cross / pieces;
                for (unsigned int i = 0; i < n_points_1d; ++i)
                  for (unsigned int j = 0; j < n_points_1d; ++j)
                    {
                      const double s = gauss.point(i)[0];
                      const double v = gauss.point(j)[0];
                      const double u = s * s;
                      points.push_back(tip + u * ta + u * v * ab);
                      weights.push_back(4 * area * s * s * s * gauss.weight(i) *
                                        gauss.weight(j));
                    }
              }
          }
        return Quadrature<2>(points, weights);
      }

      /// The vertex of the unit cube with the given coordinate bits.
      unsigned int
      cube_vertex(const std::array<unsigned int, 3> &bits)
      {
        return bits[0] + 2 * bits[1] + 4 * bits[2];
      }

      /// Gradient of the trilinear interpolant of @p values at @p p.
      Tensor<1, 3>
      trilinear_gradient(const std::vector<double> &values, const Point<3> &p)
      {
        static const FE_Q<3> q1(1);
        Tensor<1, 3>         g;
        for (unsigned int i = 0; i < 8; ++i)
          g += values[i] * q1.shape_grad(i, p);
        return g;
      }
    } // namespace



    template <int dim>
    std::pair<Quadrature<dim>, double>
    cut_cell_rule(const std::vector<double> &lsn,
                  const unsigned int         n_points_1d)
    {
      const ReferenceCellLevelSet<dim>      level_set(lsn);
      const hp::QCollection<1>              q1d(QGauss<1>{n_points_1d});
      NonMatching::QuadratureGenerator<dim> generator(q1d);
      Point<dim>                            upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = 1;
      generator.generate(level_set,
                         BoundingBox<dim>(std::make_pair(Point<dim>(), upper)));

      std::vector<Point<dim>> points;
      std::vector<double>     weights;
      for (const Quadrature<dim> *side : {&generator.get_inside_quadrature(),
                                          &generator.get_outside_quadrature()})
        {
          points.insert(points.end(),
                        side->get_points().begin(),
                        side->get_points().end());
          weights.insert(weights.end(),
                         side->get_weights().begin(),
                         side->get_weights().end());
        }
      const auto &inside = generator.get_inside_quadrature().get_weights();
      return {Quadrature<dim>(points, weights),
              std::accumulate(inside.begin(), inside.end(), 0.)};
    }



    template <int dim>
    FaceRule<dim>
    face_rule(const std::vector<double> &lsn,
              const std::vector<double> &lst,
              const unsigned int         face_no,
              const BoundingBox<dim>    &box,
              const unsigned int         n_points_1d,
              const double               zero)
    {
      const unsigned int direction = face_no / 2;
      const double       coordinate =
        (face_no % 2 ? box.get_boundary_points().second[direction] :
                       box.get_boundary_points().first[direction]);
      // The face point p of the generator in the cell: deal.II's
      // restriction to a face numbers the remaining coordinates cyclically
      // after the face's own ((y, z), (z, x), (x, y) in 3D).
      const auto in_cell = [&](const Point<dim - 1> &p) {
        Point<dim> x;
        x[direction] = coordinate;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          x[(direction + 1 + k) % dim] = p[k];
        return x;
      };

      const ReferenceCellLevelSet<dim> normal(lsn);
      const ReferenceCellLevelSet<dim> tangent(lst);
      bool                             in_face = true;
      for (unsigned int v = 0; v < GeometryInfo<dim - 1>::vertices_per_cell;
           ++v)
        {
          const Point<dim - 1> corner =
            GeometryInfo<dim - 1>::unit_cell_vertex(v);
          Point<dim - 1> p;
          for (unsigned int k = 0; k + 1 < dim; ++k)
            {
              const unsigned int d = (direction + 1 + k) % dim;
              p[k]                 = box.get_boundary_points().first[d] +
                     corner[k] * box.side_length(d);
            }
          in_face = in_face && std::abs(normal.value(in_cell(p))) <= zero;
        }

      const hp::QCollection<1>                  q1d(QGauss<1>{n_points_1d});
      NonMatching::FaceQuadratureGenerator<dim> generator(q1d);
      generator.generate(in_face ? static_cast<const Function<dim> &>(tangent) :
                                   static_cast<const Function<dim> &>(normal),
                         box,
                         face_no);
      FaceRule<dim> rule;
      for (const bool inside : {true, false})
        {
          const Quadrature<dim - 1> &side =
            (inside ? generator.get_inside_quadrature() :
                      generator.get_outside_quadrature());
          for (unsigned int q = 0; q < side.size(); ++q)
            {
              rule.points.push_back(in_cell(side.point(q)));
              rule.weights.push_back(side.weight(q));
              rule.on_lip.push_back(in_face && inside);
              Assert(in_face ||
                       (normal.value(rule.points.back()) < 0) == inside ||
                       std::abs(normal.value(rule.points.back())) <= zero,
                     ExcMessage("Face rule on the wrong side of the crack."));
            }
        }
      return rule;
    }



    template <int dim>
    NonMatching::ImmersedSurfaceQuadrature<dim>
    lip_rule(const std::vector<double> &lsn,
             const std::vector<double> &lst,
             const unsigned int         n_points_1d,
             const unsigned int         subdivisions)
    {
      const ReferenceCellLevelSet<dim>      level_set(lsn);
      const ReferenceCellLevelSet<dim>      tangent(lst);
      const hp::QCollection<1>              q1d(QGauss<1>{n_points_1d});
      NonMatching::QuadratureGenerator<dim> generator(q1d);
      const bool front_in_cell = *std::max_element(lst.begin(), lst.end()) > 0;
      if (*std::min_element(lst.begin(), lst.end()) > 0)
        return {};
      // The boxes to generate surface rules on: the cell; in 2D with the
      // tip inside, the two halves split at the tip across the lip's
      // direction there, so that the lip ends on a box boundary and each
      // half holds lip either all behind the tip or all ahead of it
      // (exact); otherwise subdivisions^dim boxes.
      std::vector<BoundingBox<dim>> boxes;
      Point<dim>                    one;
      for (unsigned int d = 0; d < dim; ++d)
        one[d] = 1;
      const BoundingBox<dim>  cell(std::make_pair(Point<dim>(), one));
      std::vector<Point<dim>> tips;
      if (front_in_cell && dim == 2)
        tips = front_points<dim>(lsn, lst);
      if (tips.size() == 1)
        {
          // The lip from the tip T to where it leaves the cell, E: the
          // segment T + u^2 (E - T), Gauss points in u. The grading makes
          // the r^(-1/2) of the jumps of the auxiliary fields' gradients and
          // the sqrt(r) of the branch functions' jumps smooth in u.
          Point<dim> exit;
          double     exit_lst = 0;
          for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
            {
              const unsigned int a =
                GeometryInfo<dim>::line_to_cell_vertices(l, 0);
              const unsigned int b =
                GeometryInfo<dim>::line_to_cell_vertices(l, 1);
              if (lsn[a] * lsn[b] > 0 || lsn[a] == lsn[b])
                continue;
              const Point<dim> x = GeometryInfo<dim>::unit_cell_vertex(a) +
                                   lsn[a] / (lsn[a] - lsn[b]) *
                                     (GeometryInfo<dim>::unit_cell_vertex(b) -
                                      GeometryInfo<dim>::unit_cell_vertex(a));
              const double t = tangent.value(x);
              if (t < exit_lst)
                {
                  exit     = x;
                  exit_lst = t;
                }
            }
          if (exit_lst < 0)
            {
              NonMatching::ImmersedSurfaceQuadrature<dim> rule;
              const QGauss<1>                             gauss(n_points_1d);
              const Tensor<1, dim> chord = exit - tips[0];
              for (unsigned int q = 0; q < gauss.size(); ++q)
                {
                  const double     u = gauss.point(q)[0];
                  const Point<dim> x = tips[0] + u * u * chord;
                  Tensor<1, dim>   n = level_set.gradient(x);
                  rule.push_back(x,
                                 2 * u * chord.norm() * gauss.weight(q),
                                 n / n.norm());
                }
              return rule;
            }
        }
      if (!front_in_cell)
        boxes.push_back(cell);
      else if (tips.size() == 1)
        {
          const Tensor<1, dim> g = level_set.gradient(tips[0]);
          // The lip runs normal to grad lsn: split along the axis it
          // follows most closely (in 2D the other axis has the larger
          // gradient component).
          const unsigned int axis  = (std::abs(g[0]) > std::abs(g[1]) ? 1 : 0);
          Point<dim>         upper = one, lower;
          upper[axis]              = tips[0][axis];
          lower[axis]              = tips[0][axis];
          for (const auto &box :
               {BoundingBox<dim>(std::make_pair(Point<dim>(), upper)),
                BoundingBox<dim>(std::make_pair(lower, one))})
            if (box.side_length(axis) > 1e-12)
              boxes.push_back(box);
        }
      else
        for (unsigned int b = 0; b < Utilities::pow(subdivisions, dim); ++b)
          {
            Point<dim> lower, upper;
            for (unsigned int d = 0, k = b; d < dim; ++d, k /= subdivisions)
              {
                lower[d] = double(k % subdivisions) / subdivisions;
                upper[d] = double(k % subdivisions + 1) / subdivisions;
              }
            boxes.emplace_back(std::make_pair(lower, upper));
          }

      NonMatching::ImmersedSurfaceQuadrature<dim> rule;
      for (const auto &box : boxes)
        {
          generator.generate(level_set, box);
          const auto &surface = generator.get_surface_quadrature();
          for (unsigned int q = 0; q < surface.size(); ++q)
            if (!front_in_cell || tangent.value(surface.point(q)) <= 0)
              rule.push_back(surface.point(q),
                             surface.weight(q),
                             surface.normal_vector(q));
        }
      return rule;
    }



    namespace
    {
      std::vector<Point<2>>
      front_points_2d(const std::vector<double> &lsn,
                      const std::vector<double> &lst)
      {
        return common_zeros(square_of(lsn), square_of(lst));
      }



      std::vector<Point<3>>
      front_points_3d(const std::vector<double> &lsn,
                      const std::vector<double> &lst)
      {
        std::vector<Point<3>> points;
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int side = 0; side < 2; ++side)
            {
              // The face x_d = side, with local coordinates (x_i, x_j), i < j.
              const unsigned int i = (d == 0 ? 1 : 0), j = (d == 2 ? 1 : 2);
              Square             f, g;
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int b = 0; b < 2; ++b)
                  {
                    std::array<unsigned int, 3> bits;
                    bits[d]      = side;
                    bits[i]      = a;
                    bits[j]      = b;
                    f[a + 2 * b] = lsn[cube_vertex(bits)];
                    g[a + 2 * b] = lst[cube_vertex(bits)];
                  }
              for (const Point<2> &q : common_zeros(f, g))
                {
                  Point<3> p;
                  p[d]       = side;
                  p[i]       = q[0];
                  p[j]       = q[1];
                  bool known = false;
                  for (const auto &r : points)
                    known = known || r.distance(p) < 1e-10;
                  if (!known)
                    points.push_back(p);
                }
            }
        return points;
      }



      Quadrature<2>
      tip_cell_rule_2d(const std::vector<double> &lsn,
                       const std::vector<double> &lst,
                       const unsigned int         n_points_1d)
      {
        const std::vector<Point<2>> tips = front_points_2d(lsn, lst);
        if (!tips.empty())
          return fan_rule(tips[0], square_of(lsn), n_points_1d);
        // A cell (or slice of a 3D cell) the front does not touch but passes
        // close to: fan out from the point of the cell nearest to the front,
        // so that the near-singular integrands get the graded rule. Where the
        // crack plane crosses the cell that is where it leaves the cell
        // nearest to the front (smallest |lst|), so that no triangle straddles
        // the lips; otherwise the front's position (the common zero of the
        // interpolants, extended beyond the cell) clipped to the cell.
        const std::vector<Point<2>> crossings = boundary_zeros(square_of(lsn));
        if (crossings.size() >= 2)
          {
            Point<2> centre = crossings[0];
            for (const auto &p : crossings)
              if (std::abs(bilinear(square_of(lst), p)) <
                  std::abs(bilinear(square_of(lst), centre)))
                centre = p;
            return fan_rule(centre, square_of(lsn), n_points_1d);
          }
        const std::vector<Point<2>> extended =
          common_zeros(square_of(lsn), square_of(lst), /*clip=*/false);
        if (extended.empty())
          return cut_cell_rule<2>(lsn, n_points_1d).first;
        Point<2> nearest = extended[0];
        for (const auto &p : extended)
          if (p.distance(Point<2>(0.5, 0.5)) <
              nearest.distance(Point<2>(0.5, 0.5)))
            nearest = p;
        for (unsigned int d = 0; d < 2; ++d)
          nearest[d] = std::clamp(nearest[d], 0., 1.);
        return fan_rule(nearest, square_of(lsn), n_points_1d);
      }



      Quadrature<3>
      tip_cell_rule_3d(const std::vector<double> &lsn,
                       const std::vector<double> &lst,
                       const unsigned int         n_points_1d)
      {
        // Where the front crosses the faces; none for a cell it passes close
        // to without touching (the slices then fan out from their points
        // nearest to it).
        const std::vector<Point<3>> crossings = front_points_3d(lsn, lst);

        // The axis the front runs most nearly along: its tangent is normal to
        // both level-set gradients.
        Point<3> centre(0.5, 0.5, 0.5);
        if (!crossings.empty())
          {
            centre = Point<3>();
            for (const auto &p : crossings)
              centre += p / static_cast<double>(crossings.size());
          }
        const Tensor<1, 3> tangent =
          cross_product_3d(trilinear_gradient(lsn, centre),
                           trilinear_gradient(lst, centre));
        unsigned int k = 2;
        for (unsigned int d = 0; d < 3; ++d)
          if (std::abs(tangent[d]) > std::abs(tangent[k]))
            k = d;
        const unsigned int i = (k == 0 ? 1 : 0), j = (k == 2 ? 1 : 2);

        // Break the axis where the front enters or leaves a slice.
        std::vector<double> breaks = {0., 1.};
        for (const auto &p : crossings)
          breaks.push_back(p[k]);
        std::sort(breaks.begin(), breaks.end());

        const QGauss<1>       gauss(n_points_1d);
        std::vector<Point<3>> points;
        std::vector<double>   weights;
        for (unsigned int b = 0; b + 1 < breaks.size(); ++b)
          {
            const double z0 = breaks[b], length = breaks[b + 1] - breaks[b];
            if (length < 1e-10)
              continue;
            for (unsigned int q = 0; q < n_points_1d; ++q)
              {
                const double        zeta = z0 + length * gauss.point(q)[0];
                std::vector<double> slice_lsn(4), slice_lst(4);
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int c = 0; c < 2; ++c)
                    {
                      std::array<unsigned int, 3> bits;
                      bits[i]                 = a;
                      bits[j]                 = c;
                      bits[k]                 = 0;
                      const unsigned int low  = cube_vertex(bits);
                      bits[k]                 = 1;
                      const unsigned int high = cube_vertex(bits);
                      slice_lsn[a + 2 * c] =
                        (1 - zeta) * lsn[low] + zeta * lsn[high];
                      slice_lst[a + 2 * c] =
                        (1 - zeta) * lst[low] + zeta * lst[high];
                    }
                const Quadrature<2> slice =
                  tip_cell_rule_2d(slice_lsn, slice_lst, n_points_1d);
                for (unsigned int s = 0; s < slice.size(); ++s)
                  {
                    Point<3> p;
                    p[i] = slice.point(s)[0];
                    p[j] = slice.point(s)[1];
                    p[k] = zeta;
                    points.push_back(p);
                    weights.push_back(length * gauss.weight(q) *
                                      slice.weight(s));
                  }
              }
          }
        return Quadrature<3>(points, weights);
      }
    } // namespace



    template <int dim>
    double
    front_distance(const std::vector<double> &lsn,
                   const std::vector<double> &lst)
    {
      // The interpolants linear about the centre c: lsn ~ ln + a . (x - c),
      // lst ~ lt + b . (x - c), in reference coordinates.
      static const FE_Q<dim> q1(1);
      Point<dim>             c;
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = 0.5;
      double         ln = 0, lt = 0;
      Tensor<1, dim> a, b;
      for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_cell; ++i)
        {
          ln += lsn[i] * q1.shape_value(i, c);
          lt += lst[i] * q1.shape_value(i, c);
          a += lsn[i] * q1.shape_grad(i, c);
          b += lst[i] * q1.shape_grad(i, c);
        }
      // The front: the point of both zero sets nearest to c (a point in
      // 2D, a line along a x b in 3D); the Gram matrix of a and b gives it.
      const double aa = a * a, ab = a * b, bb = b * b;
      const double det = aa * bb - ab * ab;
      if (!(det > 1e-24 * aa * bb))
        return std::numeric_limits<double>::infinity();
      const double     alpha     = (-ln * bb + lt * ab) / det;
      const double     beta      = (-lt * aa + ln * ab) / det;
      const Point<dim> p         = c + alpha * a + beta * b;
      const auto       onto_cell = [](Point<dim> x) {
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = std::clamp(x[d], 0., 1.);
        return x;
      };
      if constexpr (dim == 2)
        return p.distance(onto_cell(p));
      else
        {
          // The distance from a point of the line to the cell is convex
          // along the line: a golden-section search over the stretch that
          // passes within the cell's reach of c.
          Tensor<1, dim> t = cross_product_3d(a, b);
          t /= t.norm();
          const auto gap = [&](const double u) {
            const Point<dim> x = p + u * t;
            return x.distance(onto_cell(x));
          };
          const double reach = (p - c) * t;
          double       lo = -reach - 1, hi = -reach + 1;
          const double golden = 0.5 * (std::sqrt(5.) - 1);
          double u1 = hi - golden * (hi - lo), u2 = lo + golden * (hi - lo);
          double g1 = gap(u1), g2 = gap(u2);
          for (unsigned int iteration = 0; iteration < 60; ++iteration)
            if (g1 < g2)
              {
                hi = u2;
                u2 = u1;
                g2 = g1;
                u1 = hi - golden * (hi - lo);
                g1 = gap(u1);
              }
            else
              {
                lo = u1;
                u1 = u2;
                g1 = g2;
                u2 = lo + golden * (hi - lo);
                g2 = gap(u2);
              }
          return std::min(g1, g2);
        }
    }



    unsigned int
    graded_gauss_points(const double distance, const double tolerance)
    {
      if (!(distance > 0))
        return std::numeric_limits<unsigned int>::max();
      // The Bernstein ellipse of [0, 1] through a point at this distance
      // from its midpoint, off the real axis: the worst place for the
      // singularity of a line of the tensor rule (beside the middle of a
      // face, not beyond a corner).
      const double rho = 2 * distance + std::sqrt(1 + 4 * distance * distance);
      const double n   = std::log(1 / tolerance) / (2 * std::log(rho));
      if (n > 1000)
        return std::numeric_limits<unsigned int>::max();
      return std::max(1u, static_cast<unsigned int>(std::ceil(n)));
    }



    template <int dim>
    std::vector<Point<dim>>
    front_points(const std::vector<double> &lsn, const std::vector<double> &lst)
    {
      AssertDimension(lsn.size(), GeometryInfo<dim>::vertices_per_cell);
      AssertDimension(lst.size(), GeometryInfo<dim>::vertices_per_cell);
      if constexpr (dim == 2)
        return front_points_2d(lsn, lst);
      else
        return front_points_3d(lsn, lst);
    }



    template <int dim>
    Quadrature<dim>
    tip_cell_rule(const std::vector<double> &lsn,
                  const std::vector<double> &lst,
                  const unsigned int         n_points_1d)
    {
      if constexpr (dim == 2)
        return tip_cell_rule_2d(lsn, lst, n_points_1d);
      else
        return tip_cell_rule_3d(lsn, lst, n_points_1d);
    }



    template <int dim>
    Quadrature<dim>
    boundary_face_rule(const std::vector<double> &lsn,
                       const std::vector<double> &lst,
                       const unsigned int         face_no,
                       const unsigned int         n_points_1d)
    {
      if constexpr (dim == 3)
        {
          // The face's coordinates p, cyclic after its normal direction as
          // in face_rule(); the face's Q1 level sets are the cell's
          // restricted to it.
          const unsigned int direction = face_no / 2;
          const auto         in_cell   = [&](const Point<dim - 1> &p) {
            Point<dim> x;
            x[direction] = face_no % 2;
            for (unsigned int k = 0; k + 1 < dim; ++k)
              x[(direction + 1 + k) % dim] = p[k];
            return x;
          };
          const ReferenceCellLevelSet<dim> normal(lsn);
          const ReferenceCellLevelSet<dim> tangent(lst);
          std::vector<double>              face_lsn, face_lst;
          for (unsigned int v = 0; v < GeometryInfo<dim - 1>::vertices_per_cell;
               ++v)
            {
              const Point<dim> x =
                in_cell(GeometryInfo<dim - 1>::unit_cell_vertex(v));
              face_lsn.push_back(normal.value(x));
              face_lst.push_back(tangent.value(x));
            }
          const auto [lsn_min, lsn_max] =
            std::minmax_element(face_lsn.begin(), face_lsn.end());
          Quadrature<dim - 1> rule = QGauss<dim - 1>(n_points_1d);
          if (*lsn_min < 0 && *lsn_max > 0)
            rule = (*std::max_element(face_lst.begin(), face_lst.end()) > 0 ?
                      tip_cell_rule<dim - 1>(face_lsn, face_lst, n_points_1d) :
                      cut_cell_rule<dim - 1>(face_lsn, n_points_1d).first);
          std::vector<Point<dim>> points;
          for (const Point<dim - 1> &p : rule.get_points())
            points.push_back(in_cell(p));
          return Quadrature<dim>(points, rule.get_weights());
        }
      else
        {
          (void)lsn, (void)lst, (void)face_no, (void)n_points_1d;
          return Quadrature<dim>();
        }
    }



    template Quadrature<2>
    boundary_face_rule<2>(const std::vector<double> &,
                          const std::vector<double> &,
                          const unsigned int,
                          const unsigned int);
    template Quadrature<3>
    boundary_face_rule<3>(const std::vector<double> &,
                          const std::vector<double> &,
                          const unsigned int,
                          const unsigned int);
    template double
    front_distance<2>(const std::vector<double> &, const std::vector<double> &);
    template double
    front_distance<3>(const std::vector<double> &, const std::vector<double> &);
    template std::vector<Point<2>>
    front_points<2>(const std::vector<double> &, const std::vector<double> &);
    template std::vector<Point<3>>
    front_points<3>(const std::vector<double> &, const std::vector<double> &);
    template Quadrature<2>
    tip_cell_rule<2>(const std::vector<double> &,
                     const std::vector<double> &,
                     const unsigned int);
    template Quadrature<3>
    tip_cell_rule<3>(const std::vector<double> &,
                     const std::vector<double> &,
                     const unsigned int);
    template std::pair<Quadrature<2>, double>
    cut_cell_rule<2>(const std::vector<double> &, const unsigned int);
    template std::pair<Quadrature<3>, double>
    cut_cell_rule<3>(const std::vector<double> &, const unsigned int);
    template FaceRule<2>
    face_rule<2>(const std::vector<double> &,
                 const std::vector<double> &,
                 const unsigned int,
                 const BoundingBox<2> &,
                 const unsigned int,
                 const double);
    template FaceRule<3>
    face_rule<3>(const std::vector<double> &,
                 const std::vector<double> &,
                 const unsigned int,
                 const BoundingBox<3> &,
                 const unsigned int,
                 const double);
    template NonMatching::ImmersedSurfaceQuadrature<2>
    lip_rule<2>(const std::vector<double> &,
                const std::vector<double> &,
                const unsigned int,
                const unsigned int);
    template NonMatching::ImmersedSurfaceQuadrature<3>
    lip_rule<3>(const std::vector<double> &,
                const std::vector<double> &,
                const unsigned int,
                const unsigned int);
  } // namespace CellQuadrature
} // namespace xcrack
