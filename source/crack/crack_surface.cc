#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/output_file.h>
#include <xcrack/xfem/cell_quadrature.h>

#include <algorithm>
#include <boost/serialization/utility.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace xcrack
{
  namespace
  {
    /// Value and reference gradient of the Q1 interpolant of the vertex
    /// values @p v at the reference point @p x.
    template <int dim>
    std::pair<double, Tensor<1, dim>>
    q1_value_and_gradient(const std::vector<double> &v, const Point<dim> &x)
    {
      double         value = 0;
      Tensor<1, dim> gradient;
      for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_cell; ++i)
        {
          value += v[i] * GeometryInfo<dim>::d_linear_shape_function(x, i);
          gradient +=
            v[i] * GeometryInfo<dim>::d_linear_shape_function_gradient(x, i);
        }
      return {value, gradient};
    }



    /// Add @p p to @p points unless a point within 1e-12 is there.
    template <int dim>
    void
    add_unique(std::vector<Point<dim>> &points, const Point<dim> &p)
    {
      for (const auto &q : points)
        if (q.distance(p) < 1e-12)
          return;
      points.push_back(p);
    }



    /**
     * The corners of the zero set of the Q1 field @p lsn in the reference
     * cell, from its crossings of the cell's edges, ordered around their
     * centroid (3D). Empty unless the field changes sign in the cell or
     * vanishes on a whole face of it, and in the latter case only the cell
     * on the negative side keeps the face, so that a crack along cell
     * faces is drawn once.
     */
    template <int dim>
    std::vector<Point<dim>>
    zero_set_corners(const std::vector<double> &lsn)
    {
      std::vector<Point<dim>> corners;
      for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
        {
          const unsigned int a = GeometryInfo<dim>::line_to_cell_vertices(l, 0);
          const unsigned int b = GeometryInfo<dim>::line_to_cell_vertices(l, 1);
          const Point<dim>   pa = GeometryInfo<dim>::unit_cell_vertex(a);
          const Point<dim>   pb = GeometryInfo<dim>::unit_cell_vertex(b);
          if (lsn[a] == 0)
            add_unique(corners, pa);
          if (lsn[b] == 0)
            add_unique(corners, pb);
          if ((lsn[a] < 0 && lsn[b] > 0) || (lsn[a] > 0 && lsn[b] < 0))
            add_unique(corners,
                       Point<dim>(pa + lsn[a] / (lsn[a] - lsn[b]) * (pb - pa)));
        }
      const double min = *std::min_element(lsn.begin(), lsn.end());
      const double max = *std::max_element(lsn.begin(), lsn.end());
      // Zero only on vertices (the surface touches the cell) or on a face
      // of a cell lying on the positive side: nothing to draw here.
      if (corners.size() < dim || min >= 0)
        return {};
      if (max == 0 && corners.size() < GeometryInfo<dim>::vertices_per_face)
        return {};

      if constexpr (dim == 3)
        {
          Point<3> centre;
          for (const auto &p : corners)
            centre += p / static_cast<double>(corners.size());
          Tensor<1, 3> n = q1_value_and_gradient<3>(lsn, centre).second;
          if (n.norm() == 0)
            return {};
          n /= n.norm();
          // Any unit vector normal to n, and a third one.
          Tensor<1, 3> a;
          a[std::abs(n[0]) < 0.9 ? 0 : 1] = 1;
          a -= (a * n) * n;
          a /= a.norm();
          const Tensor<1, 3> b = cross_product_3d(n, a);
          std::sort(corners.begin(),
                    corners.end(),
                    [&](const Point<3> &p, const Point<3> &q) {
                      return std::atan2((p - centre) * b, (p - centre) * a) <
                             std::atan2((q - centre) * b, (q - centre) * a);
                    });
        }
      return corners;
    }



    /**
     * Clip the polygon (3D) or segment (2D) @p corners to lst <= 0, with lst
     * interpolated linearly along its edges from the Q1 values at the
     * corners (Sutherland-Hodgman against one half-space).
     */
    template <int dim>
    std::vector<Point<dim>>
    clip_to_crack(const std::vector<Point<dim>> &corners,
                  const std::vector<double>     &lst)
    {
      if (corners.empty())
        return {};
      std::vector<double> values;
      for (const auto &p : corners)
        values.push_back(q1_value_and_gradient<dim>(lst, p).first);
      std::vector<Point<dim>> clipped;
      const unsigned int      n = corners.size();
      // A segment is a polygon of two corners whose closing edge is itself.
      const unsigned int n_edges = (dim == 2 ? 1 : n);
      for (unsigned int i = 0; i < n_edges; ++i)
        {
          const unsigned int j = (i + 1) % n;
          if (values[i] <= 0)
            add_unique(clipped, corners[i]);
          if ((values[i] < 0 && values[j] > 0) ||
              (values[i] > 0 && values[j] < 0))
            add_unique(clipped,
                       Point<dim>(corners[i] + values[i] /
                                                 (values[i] - values[j]) *
                                                 (corners[j] - corners[i])));
          if (dim == 2 && values[j] <= 0)
            add_unique(clipped, corners[j]);
        }
      if (clipped.size() < dim)
        return {};
      return clipped;
    }



    /// Measure of a piece in real space: a segment's length, a polygon's area.
    template <int dim>
    double
    piece_measure(const std::vector<Point<dim>> &p)
    {
      if constexpr (dim == 2)
        return p[0].distance(p[1]);
      else
        {
          Tensor<1, 3> twice_area;
          for (unsigned int i = 1; i + 1 < p.size(); ++i)
            twice_area += cross_product_3d(p[i] - p[0], p[i + 1] - p[0]);
          return 0.5 * twice_area.norm();
        }
    }



    /// The front frame from (averaged) level-set gradients, see the class doc.
    template <int dim>
    FrontPoint<dim>
    make_frame(const Point<dim>     &position,
               const Tensor<1, dim> &grad_lsn,
               const Tensor<1, dim> &grad_lst)
    {
      FrontPoint<dim> p;
      p.position = position;
      if constexpr (dim == 2)
        {
          p.e1 = grad_lst - (grad_lst * grad_lsn) /
                              std::max(grad_lsn.norm_square(), 1e-300) *
                              grad_lsn;
          p.e1 /= p.e1.norm();
          p.e2[0] = 0. - p.e1[1]; // 0. - : no -0 in the output
          p.e2[1] = p.e1[0];
        }
      else
        {
          p.e2 = grad_lsn / grad_lsn.norm();
          p.e1 = grad_lst - (grad_lst * p.e2) * p.e2;
          p.e1 /= p.e1.norm();
          p.e3 = cross_product_3d(p.e1, p.e2);
        }
      return p;
    }

    /**
     * Join the loose ends of front chains that lie within @p gap of each
     * other, the closest first: @p edges between nodes (positions
     * position[representative[k]]) are rewired to one of the two. Across a
     * face between a cell and its finer neighbours the fields do not
     * conform (their values at the hanging nodes are the shape's, not the
     * coarse face's interpolation), so the coarse cell's crossing of that
     * face and the fine cells' differ by O(h^2 / curvature radius) and the
     * chain would break there. An open front's true ends lie on the
     * boundary, much farther than a fraction of a cell from any other.
     */
    template <int dim>
    void
    join_loose_ends(const std::vector<Point<dim>>   &position,
                    const std::vector<unsigned int> &representative,
                    const double                     gap,
                    std::set<std::pair<unsigned int, unsigned int>> &edges)
    {
      std::vector<unsigned int> degree(representative.size(), 0);
      for (const auto &[a, b] : edges)
        {
          ++degree[a];
          ++degree[b];
        }
      std::vector<unsigned int> ends;
      for (unsigned int k = 0; k < degree.size(); ++k)
        if (degree[k] == 1)
          ends.push_back(k);
      std::vector<std::tuple<double, unsigned int, unsigned int>> pairs;
      for (unsigned int i = 0; i < ends.size(); ++i)
        for (unsigned int j = i + 1; j < ends.size(); ++j)
          {
            const double d = position[representative[ends[i]]].distance(
              position[representative[ends[j]]]);
            if (d <= gap)
              pairs.emplace_back(d, ends[i], ends[j]);
          }
      if (pairs.empty())
        return;
      std::sort(pairs.begin(), pairs.end());
      std::vector<unsigned int> node(representative.size());
      std::iota(node.begin(), node.end(), 0);
      std::vector<bool> joined(representative.size(), false);
      for (const auto &[d, a, b] : pairs)
        if (!joined[a] && !joined[b])
          {
            node[b]   = a;
            joined[a] = joined[b] = true;
          }
      std::set<std::pair<unsigned int, unsigned int>> rewired;
      for (const auto &[a, b] : edges)
        if (node[a] != node[b])
          rewired.emplace(std::min(node[a], node[b]),
                          std::max(node[a], node[b]));
      edges = std::move(rewired);
    }
  } // namespace



  template <int dim>
  void
  CrackSurface<dim>::extract(const LevelSetFields<dim> &level_sets,
                             const unsigned int         crack)
  {
    const DoFHandler<dim> &dof_handler = level_sets.get_dof_handler();
    communicator = dof_handler.get_triangulation().get_communicator();
    const auto          &lsn_field = level_sets.lsn(crack);
    const auto          &lst_field = level_sets.lst(crack);
    const MappingQ1<dim> mapping;
    pieces.clear();
    front_chains.clear();

    // Front points of the local cells: position and the two level-set
    // gradients, flattened for the exchange, and the segments between them.
    std::vector<double>       local_points;
    std::vector<unsigned int> local_segments;
    double                    local_measure = 0;
    // The smallest cell holding a front point: copies of a point lie much
    // closer than that to each other, distinct points not.
    double smallest_cell = std::numeric_limits<double>::max();

    Vector<double> lsn_values(GeometryInfo<dim>::vertices_per_cell);
    Vector<double> lst_values(GeometryInfo<dim>::vertices_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_values(lsn_field, lsn_values);
        cell->get_dof_values(lst_field, lst_values);
        const std::vector<double> lsn(lsn_values.begin(), lsn_values.end());
        const std::vector<double> lst(lst_values.begin(), lst_values.end());
        if (*std::min_element(lsn.begin(), lsn.end()) > 0 ||
            *std::max_element(lsn.begin(), lsn.end()) < 0 ||
            *std::min_element(lst.begin(), lst.end()) > 0)
          continue;

        // The lips in this cell.
        const std::vector<Point<dim>> corners =
          clip_to_crack<dim>(zero_set_corners<dim>(lsn), lst);
        if (!corners.empty())
          {
            Piece piece;
            piece.level     = cell->level();
            piece.index     = cell->index();
            piece.reference = corners;
            for (const auto &x : corners)
              {
                piece.real.push_back(
                  mapping.transform_unit_to_real_cell(cell, x));
                Tensor<1, dim> n = q1_value_and_gradient<dim>(lsn, x).second;
                piece.reference_normal.push_back(n / n.norm());
              }
            local_measure += piece_measure<dim>(piece.real);
            pieces.push_back(std::move(piece));
          }

        // The front in this cell.
        const std::vector<Point<dim>> crossings =
          CellQuadrature::front_points<dim>(lsn, lst);
        if (crossings.empty() || (dim == 3 && crossings.size() < 2))
          continue;
        smallest_cell = std::min(smallest_cell, cell->diameter());
        FEValues<dim> fe_values(mapping,
                                dof_handler.get_fe(),
                                Quadrature<dim>(crossings),
                                update_quadrature_points | update_gradients);
        fe_values.reinit(cell);
        std::vector<Tensor<1, dim>> grad_lsn(crossings.size()),
          grad_lst(crossings.size());
        fe_values.get_function_gradients(lsn_field, grad_lsn);
        fe_values.get_function_gradients(lst_field, grad_lst);
        const unsigned int first = local_points.size() / (3 * dim);
        for (unsigned int q = 0; q < crossings.size(); ++q)
          for (const Tensor<1, dim> &t :
               {Tensor<1, dim>(fe_values.quadrature_point(q)),
                grad_lsn[q],
                grad_lst[q]})
            for (unsigned int d = 0; d < dim; ++d)
              local_points.push_back(t[d]);
        if (dim == 3)
          {
            // Join the crossings in their order along the front's tangent
            // (two crossings unless the front enters the cell twice).
            Tensor<1, dim> tangent;
            for (unsigned int q = 0; q < crossings.size(); ++q)
              if constexpr (dim == 3)
                tangent += cross_product_3d(grad_lsn[q], grad_lst[q]);
            std::vector<unsigned int> order(crossings.size());
            std::iota(order.begin(), order.end(), 0);
            std::sort(order.begin(),
                      order.end(),
                      [&](const unsigned int a, const unsigned int b) {
                        return fe_values.quadrature_point(a) * tangent <
                               fe_values.quadrature_point(b) * tangent;
                      });
            for (unsigned int k = 0; k + 1 < order.size(); ++k)
              {
                local_segments.push_back(first + order[k]);
                local_segments.push_back(first + order[k + 1]);
              }
          }
      }
    lips_measure  = Utilities::MPI::sum(local_measure, communicator);
    smallest_cell = Utilities::MPI::min(smallest_cell, communicator);

    // Every rank assembles every front: they are small, and every rank
    // needs them (fracture parameters, propagation).
    const auto all_points =
      Utilities::MPI::all_gather(communicator, local_points);
    const auto all_segments =
      Utilities::MPI::all_gather(communicator, local_segments);
    std::vector<Point<dim>>                                position;
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>> gradients;
    std::vector<std::pair<unsigned int, unsigned int>>     segments;
    for (unsigned int r = 0; r < all_points.size(); ++r)
      {
        const unsigned int offset = position.size();
        for (unsigned int i = 0; i < all_points[r].size(); i += 3 * dim)
          {
            Point<dim>     x;
            Tensor<1, dim> gn, gt;
            for (unsigned int d = 0; d < dim; ++d)
              {
                x[d]  = all_points[r][i + d];
                gn[d] = all_points[r][i + dim + d];
                gt[d] = all_points[r][i + 2 * dim + d];
              }
            position.push_back(x);
            gradients.emplace_back(gn, gt);
          }
        for (unsigned int i = 0; i < all_segments[r].size(); i += 2)
          segments.emplace_back(offset + all_segments[r][i],
                                offset + all_segments[r][i + 1]);
      }
    if (position.empty())
      return;

    // Merge the copies of a point found by the cells sharing it (they
    // differ by round-off, or not at all): sweep in x with a tolerance
    // relative to the cells. (Relative to the extent of the front, as
    // before, a single 2D tip found by two cells stayed two tips.)
    const double              tolerance = 1e-9 * smallest_cell;
    std::vector<unsigned int> by_x(position.size());
    std::iota(by_x.begin(), by_x.end(), 0);
    std::sort(by_x.begin(), by_x.end(), [&](unsigned int a, unsigned int b) {
      return position[a][0] < position[b][0];
    });
    std::vector<unsigned int> node_of(position.size(),
                                      numbers::invalid_unsigned_int);
    std::vector<unsigned int> representative;
    for (unsigned int k = 0; k < by_x.size(); ++k)
      {
        const unsigned int i = by_x[k];
        if (node_of[i] != numbers::invalid_unsigned_int)
          continue;
        node_of[i] = representative.size();
        for (unsigned int m = k + 1;
             m < by_x.size() &&
             position[by_x[m]][0] - position[i][0] <= tolerance;
             ++m)
          if (position[by_x[m]].distance(position[i]) <= tolerance)
            node_of[by_x[m]] = representative.size();
        representative.push_back(i);
      }

    // Node frames from the gradients averaged over the copies.
    const unsigned int          n_nodes = representative.size();
    std::vector<Tensor<1, dim>> grad_n(n_nodes), grad_t(n_nodes);
    for (unsigned int i = 0; i < position.size(); ++i)
      {
        grad_n[node_of[i]] += gradients[i].first;
        grad_t[node_of[i]] += gradients[i].second;
      }
    std::vector<FrontPoint<dim>> nodes;
    for (unsigned int k = 0; k < n_nodes; ++k)
      nodes.push_back(
        make_frame<dim>(position[representative[k]], grad_n[k], grad_t[k]));

    if constexpr (dim == 2)
      {
        // Each tip is a front.
        for (const auto &p : nodes)
          front_chains.push_back({p});
        return;
      }

    // Chain the segments (each counted once) into fronts.
    // A front along an edge of a cell whose neighbours are finer passes
    // through their hanging node: the coarse cell's segment is cut at the
    // nodes on it, or the chain would fork there (a triangle of segments).
    std::set<std::pair<unsigned int, unsigned int>> edges;
    for (const auto &[i, j] : segments)
      {
        const unsigned int a = node_of[i], b = node_of[j];
        if (a == b)
          continue;
        const Point<dim>    &xa = position[representative[a]];
        const Tensor<1, dim> ab = position[representative[b]] - xa;
        std::vector<std::pair<double, unsigned int>> on_segment{{0., a},
                                                                {1., b}};
        for (unsigned int c = 0; c < n_nodes; ++c)
          if (c != a && c != b)
            {
              const Tensor<1, dim> ac = position[representative[c]] - xa;
              const double         t  = ac * ab / ab.norm_square();
              if (t > 0 && t < 1 && (ac - t * ab).norm() <= tolerance)
                on_segment.emplace_back(t, c);
            }
        std::sort(on_segment.begin(), on_segment.end());
        for (unsigned int k = 0; k + 1 < on_segment.size(); ++k)
          edges.emplace(
            std::min(on_segment[k].second, on_segment[k + 1].second),
            std::max(on_segment[k].second, on_segment[k + 1].second));
      }
    join_loose_ends(position, representative, 0.1 * smallest_cell, edges);
    for (const auto &chain : chain_edges(n_nodes, {edges.begin(), edges.end()}))
      {
        std::vector<FrontPoint<dim>> front;
        for (const unsigned int k : chain)
          front.push_back(nodes[k]);
        orient_front(front);
        front_chains.push_back(std::move(front));
      }
  }



  template <int dim>
  const std::vector<std::vector<FrontPoint<dim>>> &
  CrackSurface<dim>::fronts() const
  {
    return front_chains;
  }



  template <int dim>
  double
  CrackSurface<dim>::front_length() const
  {
    double length = 0;
    for (const auto &front : front_chains)
      length += front.back().s;
    return length;
  }



  template <int dim>
  double
  CrackSurface<dim>::measure() const
  {
    return lips_measure;
  }



  template <int dim>
  std::vector<std::vector<Tensor<1, dim>>>
  CrackSurface<dim>::openings(
    const DoFHandler<dim>               &dof_handler,
    const TrilinosWrappers::MPI::Vector &solution) const
  {
    // The lips are evaluated a hair's breadth off the zero set on each side,
    // in reference coordinates, where the enrichment functions take their
    // one-sided values and the polynomials have not moved.
    const double                             offset = 1e-7;
    const MappingQ1<dim>                     mapping;
    std::vector<std::vector<Tensor<1, dim>>> result;
    for (const Piece &piece : pieces)
      {
        const typename DoFHandler<dim>::active_cell_iterator cell(
          &dof_handler.get_triangulation(),
          piece.level,
          piece.index,
          &dof_handler);
        const std::vector<Point<dim>> points =
          CellQuadrature::both_sides(piece.reference,
                                     piece.reference_normal,
                                     offset);
        FEValues<dim> fe_values(mapping,
                                cell->get_fe(),
                                Quadrature<dim>(points),
                                update_values);
        fe_values.reinit(cell);
        std::vector<Vector<double>> values(points.size(), Vector<double>(dim));
        fe_values.get_function_values(solution, values);
        std::vector<Tensor<1, dim>> jumps(piece.reference.size());
        for (unsigned int k = 0; k < piece.reference.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            jumps[k][d] = values[2 * k][d] - values[2 * k + 1][d];
        result.push_back(std::move(jumps));
      }
    return result;
  }



  template <int dim>
  double
  CrackSurface<dim>::max_opening(
    const DoFHandler<dim>               &dof_handler,
    const TrilinosWrappers::MPI::Vector &solution) const
  {
    double max = 0;
    for (const auto &jumps : openings(dof_handler, solution))
      for (const auto &j : jumps)
        max = std::max(max, j.norm());
    return Utilities::MPI::max(max, communicator);
  }



  template <int dim>
  Tensor<1, dim>
  CrackSurface<dim>::real_normal(const Piece &piece)
  {
    // The normal of the corners' segment (2D: turned by +90 degrees) or
    // polygon (3D: Newell's), in real and in reference coordinates. The
    // mapping keeps orientation, so the real one points to the lsn > 0 side
    // exactly when the reference one agrees with lsn's reference gradient.
    const auto geometric = [](const std::vector<Point<dim>> &corners) {
      Tensor<1, dim> n;
      if (corners.size() < dim)
        return n;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t = corners[1] - corners[0];
          n[0]                   = -t[1];
          n[1]                   = t[0];
        }
      else
        for (unsigned int k = 0; k < corners.size(); ++k)
          n += cross_product_3d(corners[k] - corners[0],
                                corners[(k + 1) % corners.size()] - corners[0]);
      return n;
    };
    Tensor<1, dim> n         = geometric(piece.real);
    Tensor<1, dim> reference = geometric(piece.reference), gradient;
    for (const Tensor<1, dim> &g : piece.reference_normal)
      gradient += g;
    if (n.norm() == 0)
      return n;
    return (reference * gradient < 0 ? -1. : 1.) * n / n.norm();
  }



  template <int dim>
  std::vector<std::pair<std::vector<Point<dim>>, Tensor<1, dim>>>
  CrackSurface<dim>::lips() const
  {
    std::vector<std::pair<std::vector<Point<dim>>, Tensor<1, dim>>> local;
    for (const Piece &piece : pieces)
      {
        const Tensor<1, dim> n = real_normal(piece);
        if (n.norm() > 0)
          local.emplace_back(piece.real, n);
      }
    std::vector<std::pair<std::vector<Point<dim>>, Tensor<1, dim>>> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }



  template <int dim>
  void
  CrackSurface<dim>::write_vtu(const std::string                   &file_name,
                               const DoFHandler<dim>               &dof_handler,
                               const TrilinosWrappers::MPI::Vector &solution,
                               const std::vector<LipField> &fields) const
  {
    // Flatten the local pieces (corner count, then per corner x y z, the
    // opening and the normal, then the fields' values) and collect them on
    // rank 0.
    unsigned int n_field_values = 0;
    for (const LipField &field : fields)
      n_field_values += field.n_components;
    const auto          jumps = openings(dof_handler, solution);
    std::vector<double> local;
    for (unsigned int i = 0; i < pieces.size(); ++i)
      {
        const Tensor<1, dim> n = real_normal(pieces[i]);
        local.push_back(pieces[i].real.size());
        for (unsigned int k = 0; k < pieces[i].real.size(); ++k)
          {
            for (unsigned int d = 0; d < 3; ++d)
              local.push_back(d < dim ? pieces[i].real[k][d] : 0.);
            for (unsigned int d = 0; d < 3; ++d)
              local.push_back(d < dim ? jumps[i][k][d] : 0.);
            for (unsigned int d = 0; d < 3; ++d)
              local.push_back(d < dim ? n[d] : 0.);
          }
        const CellId id =
          typename Triangulation<dim>::cell_iterator(
            &dof_handler.get_triangulation(), pieces[i].level, pieces[i].index)
            ->id();
        for (const LipField &field : fields)
          {
            std::vector<double> values = field.value(id);
            values.resize(field.n_components, 0.);
            local.insert(local.end(), values.begin(), values.end());
          }
      }
    const auto all = Utilities::MPI::gather(communicator, local, 0);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;

    // Points: the lip corners (with their opening), then the front points
    // (with their abscissa). Cells: lip pieces, then one poly-line per front
    // (a vertex per tip in 2D).
    std::vector<std::array<double, 3>>     points, opening, slip;
    std::vector<double>                    abscissa, gap;
    std::vector<std::vector<unsigned int>> cells;
    std::vector<unsigned int>              types, kinds;
    // Per cell, the fields' values (zeros on the fronts).
    std::vector<std::vector<double>> field_values;
    for (const auto &rank : all)
      for (unsigned int i = 0; i < rank.size();)
        {
          const unsigned int        n = rank[i++];
          std::vector<unsigned int> cell;
          for (unsigned int k = 0; k < n; ++k, i += 9)
            {
              cell.push_back(points.size());
              points.push_back({{rank[i], rank[i + 1], rank[i + 2]}});
              opening.push_back({{rank[i + 3], rank[i + 4], rank[i + 5]}});
              double g = 0;
              for (unsigned int d = 0; d < 3; ++d)
                g += rank[i + 3 + d] * rank[i + 6 + d];
              gap.push_back(g);
              slip.push_back({{rank[i + 3] - g * rank[i + 6],
                               rank[i + 4] - g * rank[i + 7],
                               rank[i + 5] - g * rank[i + 8]}});
              abscissa.push_back(0);
            }
          field_values.emplace_back(rank.begin() + i,
                                    rank.begin() + i + n_field_values);
          i += n_field_values;
          cells.push_back(cell);
          types.push_back(dim == 2 ? 3 /*line*/ : 7 /*polygon*/);
          kinds.push_back(0);
        }
    for (const auto &front : front_chains)
      {
        std::vector<unsigned int> cell;
        for (const auto &p : front)
          {
            cell.push_back(points.size());
            points.push_back({{p.position[0],
                               p.position[1],
                               dim == 3 ? p.position[dim - 1] : 0.}});
            opening.push_back({{0., 0., 0.}});
            slip.push_back({{0., 0., 0.}});
            gap.push_back(0);
            abscissa.push_back(p.s);
          }
        field_values.emplace_back(n_field_values, 0.);
        cells.push_back(cell);
        types.push_back(front.size() == 1 ? 1 /*vertex*/ : 4 /*poly-line*/);
        kinds.push_back(1);
      }

    write_file(file_name, [&](std::ostream &out) {
      out << std::setprecision(10);
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
          << "<UnstructuredGrid>\n"
          << "<Piece NumberOfPoints=\"" << points.size()
          << "\" NumberOfCells=\"" << cells.size() << "\">\n"
          << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &p : points)
        out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      out
        << "</DataArray>\n</Points>\n<Cells>\n"
        << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (const auto &c : cells)
        {
          for (const unsigned int i : c)
            out << i << ' ';
          out << '\n';
        }
      out << "</DataArray>\n"
          << "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      unsigned int offset = 0;
      for (const auto &c : cells)
        out << (offset += c.size()) << '\n';
      out << "</DataArray>\n"
          << "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (const unsigned int t : types)
        out << t << '\n';
      out << "</DataArray>\n</Cells>\n"
          << "<PointData Vectors=\"opening\">\n"
          << "<DataArray type=\"Float64\" Name=\"opening\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &o : opening)
        out << o[0] << ' ' << o[1] << ' ' << o[2] << '\n';
      out << "</DataArray>\n"
          << "<DataArray type=\"Float64\" Name=\"gap\" format=\"ascii\">\n";
      for (const double g : gap)
        out << g << '\n';
      out << "</DataArray>\n"
          << "<DataArray type=\"Float64\" Name=\"slip\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &o : slip)
        out << o[0] << ' ' << o[1] << ' ' << o[2] << '\n';
      out << "</DataArray>\n"
          << "<DataArray type=\"Float64\" Name=\"front_abscissa\" "
             "format=\"ascii\">\n";
      for (const double s : abscissa)
        out << s << '\n';
      out << "</DataArray>\n</PointData>\n"
          << "<CellData Scalars=\"kind\">\n"
          << "<DataArray type=\"UInt8\" Name=\"kind\" format=\"ascii\">\n";
      for (const unsigned int k : kinds)
        out << k << '\n';
      out << "</DataArray>\n";
      unsigned int first = 0;
      for (const LipField &field : fields)
        {
          out << "<DataArray type=\"Float64\" Name=\"" << field.name << "\" "
              << (field.n_components > 1 ?
                    "NumberOfComponents=\"" +
                      std::to_string(field.n_components) + "\" " :
                    "")
              << "format=\"ascii\">\n";
          for (const std::vector<double> &values : field_values)
            {
              for (unsigned int c = 0; c < field.n_components; ++c)
                out << values[first + c]
                    << (c + 1 < field.n_components ? ' ' : '\n');
            }
          out << "</DataArray>\n";
          first += field.n_components;
        }
      out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n"
          << "</VTKFile>\n";
    });
  }



  template class CrackSurface<2>;
  template class CrackSurface<3>;
} // namespace xcrack
