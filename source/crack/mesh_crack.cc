#include <deal.II/base/exceptions.h>

#include <xcrack/crack/crack_surface_file.h>
#include <xcrack/crack/mesh_crack.h>
#include <xcrack/crack/nearest_feature.h>
#include <xcrack/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace xcrack
{
  template <int dim>
  struct MeshCrack<dim>::Index
  {
    NearestFeature::BoxTree<dim> facets, front;
  };



  namespace
  {
    /// Distance from @p p to the box @p box (0 inside).
    template <int dim>
    double
    distance_to_box(const BoundingBox<dim> &box, const Point<dim> &p)
    {
      double square = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double out = std::max(
            {0., box.lower_bound(d) - p[d], p[d] - box.upper_bound(d)});
          square += out * out;
        }
      return std::sqrt(square);
    }

    template <int dim>
    std::string
    to_string(const Point<dim> &p)
    {
      std::ostringstream s;
      s << '(' << p << ')';
      return s.str();
    }
  } // namespace



  template <int dim>
  MeshCrack<dim>::MeshCrack(const std::string &file_name,
                            const std::string &entry,
                            const double       band)
    : band(band)
    , index(std::make_unique<Index>())
  {
    read(file_name, entry);
    orient_and_connect(entry + " = " + file_name);
    build_front();
  }



  template <int dim>
  MeshCrack<dim>::~MeshCrack() = default;



  template <int dim>
  void
  MeshCrack<dim>::read(const std::string &file_name, const std::string &entry)
  {
    const std::string what = entry + " = " + file_name;
    const RawMesh     raw  = read_crack_surface_file(file_name, what);
    for (const auto &x : raw.points)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = x[d];
        vertices.push_back(p);
      }
    if constexpr (dim == 3)
      {
        // Triangles; polygons of more corners are split into a fan.
        for (const auto &polygon : raw.polygons)
          for (unsigned int k = 1; k + 1 < polygon.size(); ++k)
            facets.push_back({{polygon[0], polygon[k], polygon[k + 1]}});
        check_input(!facets.empty(),
                    what + ": no triangles or quadrilaterals in this file; a "
                           "3D crack is a surface mesh.");
      }
    else
      {
        for (const auto &line : raw.lines)
          for (unsigned int k = 0; k + 1 < line.size(); ++k)
            facets.push_back({{line[k], line[k + 1], 0}});
        check_input(!facets.empty(),
                    what + ": no line segments in this file; a 2D crack is "
                           "a polyline.");
      }
  }



  template <int dim>
  void
  MeshCrack<dim>::orient_and_connect(const std::string &what)
  {
    const unsigned int n_corners = (dim == 3 ? 3 : 2);
    // The "edges" between facets: mesh edges in 3D, vertices in 2D.
    std::map<std::array<unsigned int, 2>, unsigned int> edge_index;
    facet_edges.assign(facets.size(), {{0, 0, 0}});
    for (unsigned int f = 0; f < facets.size(); ++f)
      for (unsigned int k = 0; k < (dim == 3 ? 3u : 2u); ++k)
        {
          std::array<unsigned int, 2> key;
          if (dim == 3)
            key = {{std::min(facets[f][k], facets[f][(k + 1) % 3]),
                    std::max(facets[f][k], facets[f][(k + 1) % 3])}};
          else
            key = {{facets[f][k], facets[f][k]}};
          const auto [it, inserted] = edge_index.emplace(key, edges.size());
          if (inserted)
            {
              edges.push_back(key);
              edge_facets.emplace_back();
            }
          edge_facets[it->second].push_back(f);
          facet_edges[f][k] = it->second;
        }
    for (unsigned int e = 0; e < edges.size(); ++e)
      check_input(edge_facets[e].size() <= 2,
                  what + ": " + std::to_string(edge_facets[e].size()) +
                    (dim == 3 ? " triangles share the edge from " :
                                " segments meet at ") +
                    to_string(vertices[edges[e][0]]) +
                    (dim == 3 ? " to " + to_string(vertices[edges[e][1]]) :
                                std::string()) +
                    "; a crack surface must not branch.");

    // Orient every facet like its neighbours, starting from the first of
    // each connected piece. In 3D two neighbours agree if they run through
    // their common edge in opposite directions; in 2D if one starts where
    // the other ends.
    const auto runs_forward = [&](const unsigned int f, const unsigned int e) {
      if (dim == 3)
        {
          for (unsigned int k = 0; k < 3; ++k)
            if (facets[f][k] == edges[e][0] &&
                facets[f][(k + 1) % 3] == edges[e][1])
              return true;
          return false;
        }
      else
        return facets[f][1] == edges[e][0]; // f ends at the shared vertex
    };
    const auto flip = [&](const unsigned int f) {
      std::swap(facets[f][0], facets[f][1]);
      // Keep the local edge numbering in step with the corners.
      if (dim == 3)
        std::swap(facet_edges[f][1], facet_edges[f][2]);
      else
        std::swap(facet_edges[f][0], facet_edges[f][1]);
    };
    std::vector<bool> visited(facets.size(), false);
    for (unsigned int seed = 0; seed < facets.size(); ++seed)
      {
        if (visited[seed])
          continue;
        visited[seed] = true;
        std::vector<unsigned int> stack{seed};
        while (!stack.empty())
          {
            const unsigned int f = stack.back();
            stack.pop_back();
            for (unsigned int k = 0; k < n_corners; ++k)
              {
                const unsigned int e = facet_edges[f][k];
                for (const unsigned int g : edge_facets[e])
                  if (g != f)
                    {
                      const bool agree =
                        (runs_forward(f, e) != runs_forward(g, e));
                      if (!visited[g])
                        {
                          if (!agree)
                            flip(g);
                          visited[g] = true;
                          stack.push_back(g);
                        }
                      else
                        check_input(agree,
                                    what +
                                      ": the surface cannot be oriented "
                                      "(a Moebius band?), so its two lips "
                                      "cannot be told apart; near " +
                                      to_string(vertices[facets[f][0]]) + ".");
                    }
              }
          }
      }

    // Normals: of each facet, and angle-weighted at vertices, averaged at
    // edges.
    facet_normal.resize(facets.size());
    vertex_normal.assign(vertices.size(), Tensor<1, dim>());
    for (unsigned int f = 0; f < facets.size(); ++f)
      {
        const auto    &c = facets[f];
        Tensor<1, dim> n;
        if constexpr (dim == 3)
          n = cross_product_3d(vertices[c[1]] - vertices[c[0]],
                               vertices[c[2]] - vertices[c[0]]);
        else
          {
            const Tensor<1, 2> t = vertices[c[1]] - vertices[c[0]];
            n[0]                 = -t[1];
            n[1]                 = t[0];
          }
        check_input(n.norm() > 0,
                    what + ": a degenerate " +
                      (dim == 3 ? std::string("triangle") :
                                  std::string("segment")) +
                      " (zero size) at " + to_string(vertices[c[0]]) + ".");
        facet_normal[f] = n / n.norm();
        for (unsigned int k = 0; k < n_corners; ++k)
          {
            double weight = 1;
            if constexpr (dim == 3)
              {
                const Tensor<1, 3> a =
                  vertices[c[(k + 1) % 3]] - vertices[c[k]];
                const Tensor<1, 3> b =
                  vertices[c[(k + 2) % 3]] - vertices[c[k]];
                weight =
                  std::acos(std::clamp(a * b / (a.norm() * b.norm()), -1., 1.));
              }
            vertex_normal[c[k]] += weight * facet_normal[f];
          }
      }
    for (auto &n : vertex_normal)
      if (n.norm() > 0)
        n /= n.norm();
    edge_normal.resize(edges.size());
    for (unsigned int e = 0; e < edges.size(); ++e)
      {
        for (const unsigned int f : edge_facets[e])
          edge_normal[e] += facet_normal[f];
        edge_normal[e] /= edge_normal[e].norm();
      }

    // The boundary, with its outward in-plane normal.
    for (unsigned int e = 0; e < edges.size(); ++e)
      if (edge_facets[e].size() == 1)
        {
          const unsigned int f = edge_facets[e][0];
          Tensor<1, dim>     e1;
          if constexpr (dim == 3)
            {
              const Tensor<1, 3> t =
                vertices[edges[e][1]] - vertices[edges[e][0]];
              e1 = cross_product_3d(t, facet_normal[f]);
              const Point<3> centroid =
                (vertices[facets[f][0]] + vertices[facets[f][1]] +
                 vertices[facets[f][2]]) /
                3.;
              const Point<3> middle =
                (vertices[edges[e][0]] + vertices[edges[e][1]]) / 2.;
              if (e1 * (middle - centroid) < 0)
                e1 = -e1;
            }
          else
            {
              const unsigned int other =
                (facets[f][0] == edges[e][0] ? facets[f][1] : facets[f][0]);
              e1 = vertices[edges[e][0]] - vertices[other];
            }
          boundary.push_back(e);
          boundary_e1.push_back(e1 / e1.norm());
        }
    boundary_is_front.assign(boundary.size(), true);

    box           = BoundingBox<dim>(vertices);
    index->facets = NearestFeature::BoxTree<dim>();
    for (unsigned int f = 0; f < facets.size(); ++f)
      {
        std::vector<Point<dim>> corners;
        for (unsigned int k = 0; k < n_corners; ++k)
          corners.push_back(vertices[facets[f][k]]);
        index->facets.add(corners, f);
      }
    index->facets.build();
  }



  template <int dim>
  void
  MeshCrack<dim>::build_front()
  {
    front_elements.clear();
    front_vertex_e1.assign(vertices.size(), Tensor<1, dim>());
    index->front = NearestFeature::BoxTree<dim>();
    for (unsigned int b = 0; b < boundary.size(); ++b)
      if (boundary_is_front[b])
        {
          const auto             &edge = edges[boundary[b]];
          std::vector<Point<dim>> ends = {vertices[edge[0]], vertices[edge[1]]};
          index->front.add(ends, front_elements.size());
          front_elements.push_back(b);
          front_vertex_e1[edge[0]] += boundary_e1[b];
          if (dim == 3)
            front_vertex_e1[edge[1]] += boundary_e1[b];
        }
    for (auto &e1 : front_vertex_e1)
      if (e1.norm() > 0)
        e1 /= e1.norm();
    index->front.build();
  }



  template <int dim>
  void
  MeshCrack<dim>::locate_in(const Triangulation<dim> &mesh)
  {
    // Strictly inside: the point and points a little off it along every
    // axis lie in the body (the coarse cells, which every rank has).
    const auto inside = [&](const Point<dim> &p, const double delta) {
      const auto in_body = [&](const Point<dim> &x) {
        for (const auto &cell : mesh.cell_iterators_on_level(0))
          if (cell->point_inside(x))
            return true;
        return false;
      };
      if (!in_body(p))
        return false;
      for (unsigned int d = 0; d < dim; ++d)
        for (const double sign : {-1., 1.})
          {
            Point<dim> x = p;
            x[d] += sign * delta;
            if (!in_body(x))
              return false;
          }
      return true;
    };
    const double size = box.side_length(0) + box.side_length(1) +
                        (dim == 3 ? box.side_length(dim - 1) : 0.);
    for (unsigned int b = 0; b < boundary.size(); ++b)
      {
        const auto      &edge = edges[boundary[b]];
        const Point<dim> probe =
          (vertices[edge[0]] + vertices[edge[1]]) / 2.; // 2D: the vertex
        boundary_is_front[b] = inside(probe, 1e-6 * size);
      }
    build_front();
  }



  template <int dim>
  std::pair<Point<dim>, Tensor<1, dim>>
  MeshCrack<dim>::closest_on_facet(const unsigned int f,
                                   const Point<dim>  &p) const
  {
    // The feature the nearest point lies on decides the normal: a corner's,
    // an edge's or the facet's.
    const auto &c           = facets[f];
    const auto [x, feature] = [&]() {
      if constexpr (dim == 2)
        return NearestFeature::on_segment(vertices[c[0]], vertices[c[1]], p);
      else
        return NearestFeature::on_triangle(vertices[c[0]],
                                           vertices[c[1]],
                                           vertices[c[2]],
                                           p);
    }();
    if (feature.kind == NearestFeature::Feature::corner)
      return {x, vertex_normal[c[feature.index]]};
    if (feature.kind == NearestFeature::Feature::edge)
      return {x, edge_normal[facet_edges[f][feature.index]]};
    return {x, facet_normal[f]};
  }



  template <int dim>
  double
  MeshCrack<dim>::lsn(const Point<dim> &p) const
  {
    const double box_distance = distance_to_box(box, p);
    if (band > 0 && box_distance > band)
      {
        // Far from the crack: only the side matters.
        const unsigned int nearest = index->facets.nearest_box(p);
        const double       side =
          (p - vertices[facets[nearest][0]]) * facet_normal[nearest];
        return (side >= 0 ? 1. : -1.) * box_distance;
      }
    auto   best = closest_on_facet(index->facets.nearest_box(p), p);
    double d    = p.distance(best.first);
    for (const unsigned int f : index->facets.candidates(p, d))
      {
        const auto c = closest_on_facet(f, p);
        if (p.distance(c.first) < d)
          {
            d    = p.distance(c.first);
            best = c;
          }
      }
    return (p - best.first) * best.second;
  }



  template <int dim>
  double
  MeshCrack<dim>::lst(const Point<dim> &p) const
  {
    // No front: the crack runs through the body.
    if (front_elements.empty())
      return -1e100;
    const double box_distance = distance_to_box(box, p);
    if (band > 0 && box_distance > band)
      return box_distance;
    // The nearest front point and the outward normal e1 there.
    const auto closest = [&](const unsigned int k) {
      const unsigned int b    = front_elements[k];
      const auto        &edge = edges[boundary[b]];
      if (dim == 2)
        return std::make_pair(vertices[edge[0]], boundary_e1[b]);
      const Point<dim>    &a = vertices[edge[0]];
      const Tensor<1, dim> t = vertices[edge[1]] - a;
      const double         s = (p - a) * t / t.norm_square();
      if (s <= 0)
        return std::make_pair(a, front_vertex_e1[edge[0]]);
      if (s >= 1)
        return std::make_pair(vertices[edge[1]], front_vertex_e1[edge[1]]);
      return std::make_pair(Point<dim>(a + s * t), boundary_e1[b]);
    };
    auto   best = closest(index->front.nearest_box(p));
    double d    = p.distance(best.first);
    for (const unsigned int k : index->front.candidates(p, d))
      {
        const auto c = closest(k);
        if (p.distance(c.first) < d)
          {
            d    = p.distance(c.first);
            best = c;
          }
      }
    return (p - best.first) * best.second;
  }



  template <int dim>
  std::vector<FrontPoint<dim>>
  MeshCrack<dim>::front(const unsigned int, const BoundingBox<dim> &) const
  {
    std::vector<FrontPoint<dim>> points;
    const auto                   make_point = [&](const unsigned int v) {
      FrontPoint<dim> p;
      p.position = vertices[v];
      p.e1       = front_vertex_e1[v];
      if constexpr (dim == 2)
        {
          p.e2[0] = 0. - p.e1[1];
          p.e2[1] = p.e1[0];
        }
      else
        {
          p.e2 = vertex_normal[v] - (vertex_normal[v] * p.e1) * p.e1;
          p.e2 /= p.e2.norm();
          p.e3 = cross_product_3d(p.e1, p.e2);
        }
      return p;
    };
    if constexpr (dim == 2)
      {
        for (const unsigned int b : front_elements)
          points.push_back(make_point(edges[boundary[b]][0]));
        return points;
      }

    // Chain the front edges through their shared vertices.
    std::vector<std::pair<unsigned int, unsigned int>> front_edges;
    for (const unsigned int b : front_elements)
      front_edges.emplace_back(edges[boundary[b]][0], edges[boundary[b]][1]);
    for (const auto &chain : chain_edges(vertices.size(), front_edges))
      {
        std::vector<FrontPoint<dim>> front;
        for (const unsigned int v : chain)
          front.push_back(make_point(v));
        orient_front(front);
        points.insert(points.end(), front.begin(), front.end());
      }
    return points;
  }



  template <int dim>
  BoundingBox<dim>
  MeshCrack<dim>::bounding_box(const BoundingBox<dim> &body) const
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::max(box.lower_bound(d), body.lower_bound(d));
        upper[d] = std::min(box.upper_bound(d), body.upper_bound(d));
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template <int dim>
  unsigned int
  MeshCrack<dim>::n_facets() const
  {
    return facets.size();
  }



  template <int dim>
  unsigned int
  MeshCrack<dim>::n_front_elements() const
  {
    return front_elements.size();
  }



  template class MeshCrack<2>;
  template class MeshCrack<3>;
} // namespace xcrack
