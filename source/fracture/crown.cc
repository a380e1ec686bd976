#include <deal.II/base/mpi.h>

#include <xcrack/fracture/crown.h>
#include <xcrack/fracture/interaction_integral.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  namespace
  {
    /// The distance of @p x from the polyline @p curve through @p front
    /// (from its point, a 2D tip).
    template <int dim>
    double
    distance_to_front(const FrontCurve<dim>              &curve,
                      const std::vector<FrontPoint<dim>> &front,
                      const Point<dim>                   &x)
    {
      if (front.size() == 1)
        return x.distance(front[0].position);
      double d = std::numeric_limits<double>::max();
      for (unsigned int i = 0; i + 1 < front.size(); ++i)
        d = std::min(d, curve.segment_distance(i, x));
      return d;
    }



    /// The crown's unit: the size of the smallest cell the front crosses
    /// (Crown unit = cells), or 1.
    template <int dim>
    double
    crown_scale(const FractureParameters           &parameters,
                const DoFHandler<dim>              &dof_handler,
                const std::vector<FrontPoint<dim>> &front)
    {
      if (!parameters.crown_in_cells)
        return 1.;
      const FrontCurve<dim> polyline(front, 0);
      double                h = std::numeric_limits<double>::max();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (dim == 2 ? cell->point_inside(front[0].position) :
                        distance_to_front(polyline, front, cell->center()) <
                          0.5 * cell->diameter()))
          h = std::min(h, cell->diameter() / std::sqrt(double(dim)));
      return Utilities::MPI::min(
        h, dof_handler.get_triangulation().get_communicator());
    }



    /// The basis of a front of @p curve: a test function must not vary
    /// along the front on a scale shorter than the crown, or theta_j is not
    /// resolved by the crown cells, so the Legendre degree is capped at L /
    /// (2 r_sup) (said on screen).
    template <int dim>
    FrontBasis
    crown_basis(const FractureParameters &parameters,
                const FrontCurve<dim>    &curve,
                const double              r_sup,
                const unsigned int        f)
    {
      if (dim == 2)
        return FrontBasis();
      const unsigned int degree =
        std::min<unsigned int>(parameters.legendre_degree,
                               static_cast<unsigned int>(curve.length /
                                                         (2 * r_sup)));
      return FrontBasis(parameters.smoothing,
                        degree,
                        curve.length,
                        curve.closed,
                        f < parameters.node_segments.size() ?
                          parameters.node_segments[f] :
                        parameters.front_segments > 0 ?
                          parameters.front_segments :
                          static_cast<unsigned int>(
                            std::round(curve.length / r_sup)));
    }



    /// The distance of x from the front, in the normal plane of its foot.
    template <int dim>
    double
    distance_to_foot(const typename FrontCurve<dim>::Projection &projection,
                     const Point<dim>                           &x)
    {
      const Tensor<1, dim> xl = projection.R * (x - projection.foot);
      return std::hypot(xl[0], xl[1]);
    }



    /// The boundary faces of @p cell that hold its vertex @p v.
    template <int dim>
    std::vector<unsigned int>
    boundary_faces_at(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                    v)
    {
      std::vector<unsigned int> faces;
      for (const unsigned int face : cell->face_indices())
        if (cell->face(face)->at_boundary())
          for (const unsigned int fv : cell->face(face)->vertex_indices())
            if (cell->face(face)->vertex_index(fv) == cell->vertex_index(v))
              faces.push_back(face);
      return faces;
    }
  } // namespace



  template <int dim>
  Crown<dim>::Crown(const FractureParameters &parameters,
                    const DoFHandler<dim>    &dof_handler,
                    const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                    const unsigned int                               f)
    : n_segments(fronts[f].size() - 1)
    , unit(crown_scale(parameters, dof_handler, fronts[f]))
    , r_inf(parameters.crown_inner * unit)
    , r_sup(parameters.crown_outer * unit)
    , smooth(parameters.smooth_weight)
    , curve(fronts[f], 0.5 * r_sup)
    , basis(crown_basis(parameters, curve, r_sup, f))
    , clear_of_other_fronts(true)
  {
    for (unsigned int g = 0; g < fronts.size(); ++g)
      if (g != f)
        for (const auto &other : fronts[g])
          if (distance_to_front(curve, fronts[f], other.position) < r_sup)
            clear_of_other_fronts = false;

    box_low  = fronts[f][0].position;
    box_high = box_low;
    for (const auto &p : fronts[f])
      for (unsigned int d = 0; d < dim; ++d)
        {
          box_low[d]  = std::min(box_low[d], p.position[d] - r_sup);
          box_high[d] = std::max(box_high[d], p.position[d] + r_sup);
        }
  }



  template <int dim>
  double
  Crown<dim>::q(const double r) const
  {
    const double t = std::clamp((r_sup - r) / (r_sup - r_inf), 0., 1.);
    return smooth ? t * t * (3 - 2 * t) : t;
  }



  template <int dim>
  double
  Crown<dim>::dq_dr(const double r) const
  {
    const double t = std::clamp((r_sup - r) / (r_sup - r_inf), 0., 1.);
    return 6 * t * (1 - t) / (r_inf - r_sup);
  }



  template <int dim>
  std::optional<std::pair<unsigned int, unsigned int>>
  Crown<dim>::segments_near(const CellIterator &cell) const
  {
    const Point<dim> c      = cell->center();
    const double     margin = cell->diameter();
    for (unsigned int d = 0; d < dim; ++d)
      if (!(c[d] > box_low[d] - margin && c[d] < box_high[d] + margin))
        return {};
    if (n_segments <= 1)
      return std::make_pair(0u, std::max(n_segments, 1u));
    const auto near = curve.near_segments(c, cell->diameter());
    if (near.distance > r_sup + cell->diameter())
      return {};
    return std::make_pair(near.first, near.last);
  }



  template <int dim>
  CellTheta<dim>::CellTheta(const Crown<dim>           &crown,
                            const HangingVertices<dim> *hanging)
    : crown(crown)
    , hanging(hanging)
  {}



  template <int dim>
  bool
  CellTheta<dim>::reinit(const CellIterator &cell,
                         const unsigned int  first,
                         const unsigned int  last)
  {
    const FrontBasis  &basis  = crown.basis;
    const unsigned int n_test = basis.n_test_functions();
    const bool         smooth = crown.smooth;
    q_min                     = 1;
    q_max                     = 0;
    for (const unsigned int v : cell->vertex_indices())
      {
        const auto projection =
          crown.curve.project(cell->vertex(v), first, last);
        const double r = distance_to_foot(projection, cell->vertex(v));
        // At a hanging vertex, the linear q is its masters' interpolation
        // (any segment of the front may be nearest to them).
        std::vector<std::pair<Point<dim>, double>> masters;
        if (hanging)
          masters = hanging->masters(cell, v);
        double q = (masters.empty() ? crown.q(r) : 0.);
        for (const auto &[x, c] : masters)
          q += c *
               crown.q(distance_to_foot(
                 crown.curve.project(x, 0, std::max(crown.n_segments, 1u)), x));
        // A smooth weight is read at the points: the cell's range of it,
        // from the vertices' distances widened by the cell.
        q_min = std::min(q_min, smooth ? crown.q(r + cell->diameter()) : q);
        q_max = std::max(q_max, smooth ? crown.q(r - cell->diameter()) : q);
        Tensor<1, dim> e1;
        for (unsigned int d = 0; d < dim; ++d)
          e1[d] = projection.R[0][d];
        w_vertex[v] = (smooth ? 1. : q) * e1;
        psi_vertex[v].resize(n_test);
        for (unsigned int j = 0; j < n_test; ++j)
          psi_vertex[v][j] = basis.test_function(j, projection.s);
        positive[v]   = q > 0;
        beyond_end[v] = projection.at_end;
      }
    if (q_max == 0)
      return false;
    if constexpr (dim == 3)
      tangent_to_boundary(cell);
    active.clear();
    for (unsigned int j = 0; j < n_test; ++j)
      for (const unsigned int v : cell->vertex_indices())
        if (psi_vertex[v][j] != 0 && w_vertex[v].norm() > 0)
          {
            active.push_back(j);
            break;
          }
    return true;
  }



  template <int dim>
  bool
  CellTheta<dim>::reaches(const CellIterator &cell,
                          const unsigned int  face_no,
                          const bool          beyond_ends) const
  {
    for (const unsigned int fv : cell->face(face_no)->vertex_indices())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->face(face_no)->vertex_index(fv) == cell->vertex_index(v) &&
            positive[v] && (beyond_ends || !beyond_end[v]))
          return true;
    return false;
  }



  template <int dim>
  void
  CellTheta<dim>::tangent_to_boundary(const CellIterator &cell)
  {
    // Gram-Schmidt over the normals of the boundary faces at each vertex.
    for (const unsigned int v : cell->vertex_indices())
      {
        std::vector<Tensor<1, dim>> normals;
        for (const unsigned int face : boundary_faces_at<dim>(cell, v))
          {
            Tensor<1, dim> n;
            if constexpr (dim == 3)
              n = cross_product_3d(cell->face(face)->vertex(1) -
                                     cell->face(face)->vertex(0),
                                   cell->face(face)->vertex(2) -
                                     cell->face(face)->vertex(0));
            for (const auto &m : normals)
              n -= (n * m) * m;
            if (n.norm() > 1e-12 * cell->diameter() * cell->diameter())
              normals.push_back(n / n.norm());
          }
        for (const auto &n : normals)
          w_vertex[v] -= (w_vertex[v] * n) * n;
      }
  }



  template <int dim>
  Tensor<1, dim>
  CellTheta<dim>::interpolant(const Point<dim> &xi, const unsigned int j) const
  {
    Tensor<1, dim> value;
    for (unsigned int v = 0; v < n_vertices; ++v)
      value +=
        (psi_vertex[v][j] * GeometryInfo<dim>::d_linear_shape_function(xi, v)) *
        w_vertex[v];
    return value;
  }



  template <int dim>
  Tensor<1, dim>
  CellTheta<dim>::value(const Point<dim>  &xi,
                        const double       r,
                        const unsigned int j) const
  {
    return (crown.smooth ? crown.q(r) : 1.) * interpolant(xi, j);
  }



  template <int dim>
  std::array<Tensor<1, dim>, CellTheta<dim>::n_vertices>
  CellTheta<dim>::shape_gradients(const Point<dim>                  &xi,
                                  const DerivativeForm<1, dim, dim> &inverse)
  {
    std::array<Tensor<1, dim>, n_vertices> grad_N;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        const Tensor<1, dim> g =
          GeometryInfo<dim>::d_linear_shape_function_gradient(xi, v);
        grad_N[v] = Tensor<1, dim>();
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            grad_N[v][j] += g[k] * inverse[k][j];
      }
    return grad_N;
  }



  template <int dim>
  Tensor<2, dim>
  CellTheta<dim>::gradient(
    const Point<dim>                             &xi,
    const std::array<Tensor<1, dim>, n_vertices> &grad_N,
    const typename FrontCurve<dim>::Projection   &projection,
    const Tensor<1, dim>                         &xl,
    const double                                  r,
    const unsigned int                            j) const
  {
    Tensor<2, dim> gradient;
    for (unsigned int v = 0; v < n_vertices; ++v)
      gradient += outer_product(psi_vertex[v][j] * w_vertex[v], grad_N[v]);
    if (!crown.smooth)
      return gradient;
    // grad r: the unit vector from the foot in the normal plane.
    Tensor<1, dim> grad_r;
    if (r > 0)
      for (unsigned int d = 0; d < dim; ++d)
        grad_r[d] =
          (projection.R[0][d] * xl[0] + projection.R[1][d] * xl[1]) / r;
    return crown.q(r) * gradient +
           crown.dq_dr(r) * outer_product(interpolant(xi, j), grad_r);
  }



  template class Crown<2>;
  template class Crown<3>;
  template class CellTheta<2>;
  template class CellTheta<3>;
} // namespace xcrack
