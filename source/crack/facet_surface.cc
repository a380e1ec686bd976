#include <deal.II/base/bounding_box.h>

#include <xcrack/crack/facet_surface.h>
#include <xcrack/input_error.h>

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <limits>
#include <ostream>
#include <sstream>

namespace xcrack
{
  namespace bg  = boost::geometry;
  namespace bgi = boost::geometry::index;

  template <int dim>
  struct FacetSurface<dim>::Index
  {
    using BPoint = bg::model::point<double, dim, bg::cs::cartesian>;
    using BBox   = bg::model::box<BPoint>;
    using Value  = std::pair<BBox, unsigned int>;

    static BPoint
    to_boost(const Point<dim> &p)
    {
      BPoint b;
      bg::set<0>(b, p[0]);
      bg::set<1>(b, p[1]);
      if constexpr (dim == 3)
        bg::set<2>(b, p[2]);
      return b;
    }

    /// The box of half-width @p r around @p p, widened by rounding so
    /// that boxes at distance exactly r count.
    static BBox
    ball_box(const Point<dim> &p, const double r)
    {
      const double w = r * (1 + 1e-9) + 1e-300;
      BBox         box(to_boost(p), to_boost(p));
      for (unsigned int d = 0; d < dim; ++d)
        {
          Point<dim> x = p;
          x[d] -= w;
          bg::expand(box, to_boost(x));
          x[d] += 2 * w;
          bg::expand(box, to_boost(x));
        }
      return box;
    }

    template <typename Container>
    static BBox
    box_of(const Container &points)
    {
      BBox box(to_boost(points[0]), to_boost(points[0]));
      for (const auto &p : points)
        bg::expand(box, to_boost(p));
      return box;
    }

    bgi::rtree<Value, bgi::rstar<16>> facets;
    /// Front segments, numbered through `segments`.
    bgi::rtree<Value, bgi::rstar<16>>                  front;
    std::vector<std::pair<unsigned int, unsigned int>> segments;
    double                                             tolerance = 0;
  };



  namespace
  {
    /// The point of segment [a, b] nearest to @p p.
    template <int dim>
    Point<dim>
    closest_on_segment(const Point<dim> &a,
                       const Point<dim> &b,
                       const Point<dim> &p,
                       double           &w)
    {
      const Tensor<1, dim> t = b - a;
      w                      = (t.norm_square() > 0 ?
                                  std::clamp((p - a) * t / t.norm_square(), 0., 1.) :
                                  0.);
      return a + w * t;
    }



    /// The point of triangle (a, b, c) nearest to @p p, by the Voronoi
    /// regions of its corners, edges and interior (Ericson, Real-Time
    /// Collision Detection, 5.1.5).
    Point<3>
    closest_on_triangle(const Point<3> &a,
                        const Point<3> &b,
                        const Point<3> &c,
                        const Point<3> &p)
    {
      const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
      const double       d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0 && d2 <= 0)
        return a;
      const Tensor<1, 3> bp = p - b;
      const double       d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0 && d4 <= d3)
        return b;
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + d1 / (d1 - d3) * ab;
      const Tensor<1, 3> cp = p - c;
      const double       d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0 && d5 <= d6)
        return c;
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + d2 / (d2 - d6) * ac;
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
      const double denominator = 1. / (va + vb + vc);
      return a + vb * denominator * ab + vc * denominator * ac;
    }



    template <int dim>
    double
    extent(const std::array<Point<dim>, dim> &corners)
    {
      if constexpr (dim == 2)
        return corners[0].distance(corners[1]);
      else
        return cross_product_3d(corners[1] - corners[0],
                                corners[2] - corners[0])
          .norm();
    }
  } // namespace



  template <int dim>
  FacetSurface<dim>::FacetSurface() = default;



  template <int dim>
  FacetSurface<dim>::FacetSurface(const FacetSurface &other)
    : facet_list(other.facet_list)
    , front_list(other.front_list)
  {}



  template <int dim>
  FacetSurface<dim> &
  FacetSurface<dim>::operator=(const FacetSurface &other)
  {
    facet_list = other.facet_list;
    front_list = other.front_list;
    index.reset();
    return *this;
  }



  template <int dim>
  FacetSurface<dim>::~FacetSurface() = default;



  template <int dim>
  void
  FacetSurface<dim>::add(const std::vector<Facet> &new_facets)
  {
    for (const Facet &f : new_facets)
      if (extent<dim>(f.corners) > 0 && f.normal.norm() > 0)
        facet_list.push_back(f);
    index.reset();
  }



  template <int dim>
  void
  FacetSurface<dim>::set_fronts(
    const std::vector<std::vector<FrontNode>> &new_fronts)
  {
    front_list = new_fronts;
    index.reset();
  }



  template <int dim>
  const std::vector<typename FacetSurface<dim>::Facet> &
  FacetSurface<dim>::facets() const
  {
    return facet_list;
  }



  template <int dim>
  const std::vector<std::vector<typename FacetSurface<dim>::FrontNode>> &
  FacetSurface<dim>::fronts() const
  {
    return front_list;
  }



  template <int dim>
  bool
  FacetSurface<dim>::empty() const
  {
    return facet_list.empty();
  }



  template <int dim>
  void
  FacetSurface<dim>::build_index() const
  {
    if (index)
      return;
    index = std::make_unique<Index>();
    std::vector<typename Index::Value> values;
    for (unsigned int f = 0; f < facet_list.size(); ++f)
      values.emplace_back(Index::box_of(facet_list[f].corners), f);
    index->facets = decltype(index->facets)(values.begin(), values.end());

    values.clear();
    for (unsigned int k = 0; k < front_list.size(); ++k)
      {
        const auto &nodes = front_list[k];
        // A 2D tip is a segment of one point.
        for (unsigned int i = 0; i + 1 < std::max<std::size_t>(nodes.size(), 2);
             ++i)
          {
            const unsigned int j =
              std::min<unsigned int>(i + 1, nodes.size() - 1);
            const std::vector<Point<dim>> ends = {nodes[i].position,
                                                  nodes[j].position};
            values.emplace_back(Index::box_of(ends), index->segments.size());
            index->segments.emplace_back(k, i);
          }
      }
    index->front = decltype(index->front)(values.begin(), values.end());

    // A point of the surface this close to a front is on it: rounding
    // apart, the strips end on the front nodes.
    BoundingBox<dim> box;
    for (const Facet &f : facet_list)
      for (const Point<dim> &x : f.corners)
        box.merge_with(BoundingBox<dim>(std::make_pair(x, x)));
    index->tolerance =
      1e-6 * (facet_list.empty() ? 0. :
                                   box.get_boundary_points().first.distance(
                                     box.get_boundary_points().second));
  }



  template <int dim>
  void
  FacetSurface<dim>::drop_index()
  {
    index.reset();
  }



  template <int dim>
  std::pair<Point<dim>, Tensor<1, dim>>
  FacetSurface<dim>::nearest(const Point<dim> &p) const
  {
    Assert(!facet_list.empty(), ExcInternalError());
    build_index();
    const auto closest = [&](const unsigned int f) {
      const auto &c = facet_list[f].corners;
      if constexpr (dim == 2)
        {
          double w;
          return closest_on_segment(c[0], c[1], p, w);
        }
      else
        return closest_on_triangle(c[0], c[1], c[2], p);
    };
    // The facet whose box is nearest bounds the distance d; the nearest
    // facets are among those whose boxes meet the box of half-width d.
    const auto first =
      index->facets.qbegin(bgi::nearest(Index::to_boost(p), 1));
    const double                       d = p.distance(closest(first->second));
    std::vector<typename Index::Value> candidates;
    index->facets.query(bgi::intersects(Index::ball_box(p, d)),
                        std::back_inserter(candidates));
    double best_distance = std::numeric_limits<double>::max();
    for (const auto &[box, f] : candidates)
      best_distance = std::min(best_distance, p.distance(closest(f)));
    // Of the facets at that distance (an edge or corner they share, up to
    // rounding), the one whose normal p - c follows best.
    const double   tolerance = 1e-9 * best_distance + 1e-14;
    Point<dim>     c;
    Tensor<1, dim> n;
    double         largest = -1;
    for (const auto &[box, f] : candidates)
      {
        const Point<dim> y = closest(f);
        if (p.distance(y) <= best_distance + tolerance)
          {
            const double value = std::abs((p - y) * facet_list[f].normal);
            if (value > largest)
              {
                largest = value;
                c       = y;
                n       = facet_list[f].normal;
              }
          }
      }
    return {c, n};
  }



  template <int dim>
  double
  FacetSurface<dim>::lsn(const Point<dim> &p) const
  {
    const auto [c, n] = nearest(p);
    return (p - c) * n;
  }



  template <int dim>
  std::pair<Point<dim>, Tensor<1, dim>>
  FacetSurface<dim>::nearest_on_front(const Point<dim> &p) const
  {
    Assert(!front_list.empty(), ExcInternalError());
    build_index();
    const auto closest = [&](const unsigned int k) {
      const auto &[front, i]   = index->segments[k];
      const auto        &nodes = front_list[front];
      const unsigned int j = std::min<unsigned int>(i + 1, nodes.size() - 1);
      double             w;
      const Point<dim>   y =
        closest_on_segment(nodes[i].position, nodes[j].position, p, w);
      Tensor<1, dim> e1 = (1 - w) * nodes[i].e1 + w * nodes[j].e1;
      return std::make_pair(y, Tensor<1, dim>(e1 / e1.norm()));
    };
    const auto first = index->front.qbegin(bgi::nearest(Index::to_boost(p), 1));
    auto       best  = closest(first->second);
    double     d     = p.distance(best.first);
    std::vector<typename Index::Value> candidates;
    index->front.query(bgi::intersects(Index::ball_box(p, d)),
                       std::back_inserter(candidates));
    for (const auto &[box, k] : candidates)
      {
        const auto y = closest(k);
        if (p.distance(y.first) < d)
          {
            d    = p.distance(y.first);
            best = y;
          }
      }
    return best;
  }



  template <int dim>
  double
  FacetSurface<dim>::lst(const Point<dim> &p) const
  {
    // Where p's nearest point c of the surface lies on a front, p is ahead
    // of it or beside it: lst = (p - f) . e1. Where c lies inside the
    // surface (or on its mouth), p is behind: lst = -|c - f|, the distance
    // to the front from there (continuous with the former across the
    // normal at the front, where both vanish). A plane through the front
    // alone, (p - f) . e1 everywhere, cuts through a crack that turned by
    // more than 90 degrees.
    const Point<dim> c = nearest(p).first;
    const auto [f, e1] = nearest_on_front(c);
    if (c.distance(f) > index->tolerance)
      return -c.distance(f);
    return (p - f) * e1;
  }



  template <int dim>
  void
  FacetSurface<dim>::write_vtu(std::ostream &out) const
  {
    // Facets first (VTK_LINE or VTK_TRIANGLE), then each front as a
    // polyline (VTK_POLY_LINE) or, in 2D, a vertex (VTK_VERTEX).
    std::vector<Point<dim>>                points;
    std::vector<std::vector<unsigned int>> cells;
    std::vector<unsigned int>              types;
    for (const Facet &f : facet_list)
      {
        cells.emplace_back();
        for (const Point<dim> &x : f.corners)
          {
            cells.back().push_back(points.size());
            points.push_back(x);
          }
        types.push_back(dim == 2 ? 3 : 5);
      }
    for (const auto &nodes : front_list)
      {
        cells.emplace_back();
        for (const FrontNode &node : nodes)
          {
            cells.back().push_back(points.size());
            points.push_back(node.position);
          }
        types.push_back(nodes.size() == 1 ? 1 : 4);
      }
    {
      out << std::setprecision(10);
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
          << "<UnstructuredGrid>\n"
          << "<Piece NumberOfPoints=\"" << points.size()
          << "\" NumberOfCells=\"" << cells.size() << "\">\n"
          << "<Points>\n<DataArray type=\"Float64\" Name=\"Points\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const Point<dim> &x : points)
        out << x[0] << ' ' << x[1] << ' ' << (dim == 3 ? x[dim - 1] : 0.)
            << '\n';
      out << "</DataArray>\n</Points>\n<Cells>\n"
          << "<DataArray type=\"Int64\" Name=\"connectivity\" "
             "format=\"ascii\">\n";
      for (const auto &cell : cells)
        for (const unsigned int v : cell)
          out << v << ' ';
      out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
             "format=\"ascii\">\n";
      std::size_t offset = 0;
      for (const auto &cell : cells)
        out << (offset += cell.size()) << ' ';
      out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
      for (const unsigned int t : types)
        out << t << ' ';
      out << "\n</DataArray>\n</Cells>\n<CellData>\n"
          << "<DataArray type=\"Int32\" Name=\"step\" format=\"ascii\">\n";
      // Fronts get -1: they belong to no step's strip.
      for (const Facet &f : facet_list)
        out << f.step << ' ';
      for (unsigned int k = 0; k < front_list.size(); ++k)
        out << -1 << ' ';
      out << "\n</DataArray>\n<DataArray type=\"Float64\" Name=\"normal\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const Facet &f : facet_list)
        out << f.normal[0] << ' ' << f.normal[1] << ' '
            << (dim == 3 ? f.normal[dim - 1] : 0.) << '\n';
      for (unsigned int k = 0; k < front_list.size(); ++k)
        out << "0 0 0\n";
      // The direction of growth at the front nodes (zero at the facets'
      // corners): what a run started from this file grows along.
      out << "</DataArray>\n</CellData>\n<PointData>\n"
          << "<DataArray type=\"Float64\" Name=\"e1\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < dim * facet_list.size(); ++k)
        out << "0 0 0\n";
      for (const auto &nodes : front_list)
        for (const FrontNode &node : nodes)
          out << node.e1[0] << ' ' << node.e1[1] << ' '
              << (dim == 3 ? node.e1[dim - 1] : 0.) << '\n';
      out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
          << "</VTKFile>\n";
    }
  }



  namespace
  {
    /// The numbers of the DataArray named @p name in the VTU text @p text
    /// (empty if there is none).
    std::vector<double>
    data_array(const std::string &text, const std::string &name)
    {
      const std::size_t at = text.find("Name=\"" + name + "\"");
      if (at == std::string::npos)
        return {};
      const std::size_t   begin = text.find('>', at) + 1;
      const std::size_t   end   = text.find("</DataArray>", begin);
      std::istringstream  numbers(text.substr(begin, end - begin));
      std::vector<double> values;
      double              x;
      while (numbers >> x)
        values.push_back(x);
      return values;
    }
  } // namespace



  template <int dim>
  FacetSurface<dim>
  FacetSurface<dim>::read_vtu(std::istream &in, const std::string &what)
  {
    const std::string         text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    const std::vector<double> points       = data_array(text, "Points"),
                              connectivity = data_array(text, "connectivity"),
                              offsets      = data_array(text, "offsets"),
                              types        = data_array(text, "types"),
                              steps        = data_array(text, "step"),
                              normals      = data_array(text, "normal"),
                              e1           = data_array(text, "e1");
    check_input(!points.empty() && points.size() == e1.size() &&
                  !types.empty() && types.size() == offsets.size() &&
                  steps.size() == types.size() &&
                  normals.size() == 3 * types.size(),
                what + ": not a crack surface written by xcrack's `crack mesh` "
                       "level-set update (crack_mesh-<step>.vtu, with the cell "
                       "data step and normal and the point data e1).");
    const auto point = [&](const unsigned int i, const std::vector<double> &v) {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = v[3 * i + d];
      return x;
    };
    FacetSurface<dim>                   surface;
    std::vector<Facet>                  facets;
    std::vector<std::vector<FrontNode>> fronts;
    std::size_t                         start = 0;
    for (unsigned int c = 0; c < types.size(); ++c)
      {
        const std::size_t end  = static_cast<std::size_t>(offsets[c]);
        const int         type = static_cast<int>(types[c]);
        check_input(end <= connectivity.size() && end >= start,
                    what + ": the cells' offsets do not fit its connectivity.");
        if (type == 3 || type == 5)
          {
            check_input(type == (dim == 2 ? 3 : 5),
                        what + ": a surface of " +
                          (type == 5 ? "triangles (a 3D crack)" :
                                       "segments (a 2D crack)") +
                          " cannot start a " + std::to_string(dim) + "D run.");
            check_input(end - start == dim,
                        what + ": a facet with the wrong number of corners.");
            Facet facet;
            for (unsigned int k = 0; k < dim; ++k)
              facet.corners[k] =
                point(static_cast<unsigned int>(connectivity[start + k]),
                      points);
            for (unsigned int d = 0; d < dim; ++d)
              facet.normal[d] = normals[3 * c + d];
            facet.step = static_cast<unsigned int>(steps[c]);
            facets.push_back(facet);
          }
        else if (type == 1 || type == 4)
          {
            fronts.emplace_back();
            for (std::size_t k = start; k < end; ++k)
              {
                const unsigned int i =
                  static_cast<unsigned int>(connectivity[k]);
                Tensor<1, dim> direction = point(i, e1);
                check_input(direction.norm() > 0,
                            what + ": a front node without a direction e1.");
                fronts.back().push_back(
                  {point(i, points), direction / direction.norm()});
              }
          }
        else
          throw InputError(what + ": a cell of VTK type " +
                           std::to_string(type) +
                           " (a crack surface holds segments or triangles "
                           "and its fronts).");
        start = end;
      }
    if (dim == 2)
      for (unsigned int i = 0; i < points.size() / 3; ++i)
        check_input(points[3 * i + 2] == 0,
                    what + ": a point with z != 0 cannot start a 2D run.");
    check_input(!facets.empty() && !fronts.empty(),
                what + ": a crack surface needs facets and a front.");
    surface.add(facets);
    surface.set_fronts(fronts);
    return surface;
  }



  template class FacetSurface<2>;
  template class FacetSurface<3>;
} // namespace xcrack
