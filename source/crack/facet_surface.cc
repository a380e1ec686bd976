#include <deal.II/base/bounding_box.h>

#include <xcrack/crack/facet_surface.h>
#include <xcrack/crack/nearest_feature.h>
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
  template <int dim>
  struct FacetSurface<dim>::Index
  {
    NearestFeature::BoxTree<dim> facets;
    /// Front segments, numbered through `segments`.
    NearestFeature::BoxTree<dim>                       front;
    std::vector<std::pair<unsigned int, unsigned int>> segments;
    /// A point of the surface this close to a front is on it.
    double tolerance = 0;
  };



  namespace
  {
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
    std::vector<Point<dim>> corners;
    for (unsigned int f = 0; f < facet_list.size(); ++f)
      {
        index->facets.add(facet_list[f].corners, f);
        corners.insert(corners.end(),
                       facet_list[f].corners.begin(),
                       facet_list[f].corners.end());
      }
    index->facets.build();

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
            index->front.add(ends, index->segments.size());
            index->segments.emplace_back(k, i);
          }
      }
    index->front.build();

    // A point of the surface this close to a front is on it: rounding
    // apart, the strips end on the front nodes.
    if (!corners.empty())
      {
        const auto [lower, upper] =
          BoundingBox<dim>(corners).get_boundary_points();
        index->tolerance = 1e-6 * lower.distance(upper);
      }
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
        return NearestFeature::on_segment(c[0], c[1], p).first;
      else
        return NearestFeature::on_triangle(c[0], c[1], c[2], p).first;
    };
    const std::vector<unsigned int> candidates = index->facets.candidates(
      p, p.distance(closest(index->facets.nearest_box(p))));
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidates)
      best_distance = std::min(best_distance, p.distance(closest(f)));
    // Of the facets at that distance (an edge or corner they share, up to
    // rounding), the one whose normal p - c follows best.
    const double   tolerance = 1e-9 * best_distance + 1e-14;
    Point<dim>     c;
    Tensor<1, dim> n;
    double         largest = -1;
    for (const unsigned int f : candidates)
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
      // The nearest point of the segment, and e1 interpolated there.
      const Tensor<1, dim> t = nodes[j].position - nodes[i].position;
      const double         w =
        (t.norm_square() > 0 ?
           std::clamp((p - nodes[i].position) * t / t.norm_square(), 0., 1.) :
           0.);
      const Point<dim> y  = nodes[i].position + w * t;
      Tensor<1, dim>   e1 = (1 - w) * nodes[i].e1 + w * nodes[j].e1;
      return std::make_pair(y, Tensor<1, dim>(e1 / e1.norm()));
    };
    auto   best = closest(index->front.nearest_box(p));
    double d    = p.distance(best.first);
    for (const unsigned int k : index->front.candidates(p, d))
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
