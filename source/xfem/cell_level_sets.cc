#include <xcrack/xfem/cell_level_sets.h>

#include <cmath>
#include <limits>

namespace xcrack
{
  namespace
  {
    /// The Jacobian of the d-linear map with @p vertices at @p xi.
    template <int dim>
    Tensor<2, dim>
    jacobian_at(
      const std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell>
                       &vertices,
      const Point<dim> &xi)
    {
      Tensor<2, dim> jacobian;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        {
          const Tensor<1, dim> g =
            GeometryInfo<dim>::d_linear_shape_function_gradient(xi, v);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              jacobian[i][j] += vertices[v][i] * g[j];
        }
      return jacobian;
    }
  } // namespace



  template <int dim>
  CellLevelSets<dim>::CellLevelSets(
    const typename Triangulation<dim>::cell_iterator &cell,
    const std::array<double, n_vertices>             &lsn,
    const std::array<double, n_vertices>             &lst)
    : normal(lsn)
    , tangent(lst)
  {
    for (unsigned int v = 0; v < n_vertices; ++v)
      vertices[v] = cell->vertex(v);
    // Affine if every vertex is where the map through vertex 0 and its
    // neighbours along the axes puts it (vertex v has bits v & 1, v & 2,
    // v & 4 along x, y, z).
    Tensor<2, dim> jacobian;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        jacobian[i][j] = vertices[1u << j][i] - vertices[0][i];
    affine = true;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        Point<dim> x = vertices[0];
        for (unsigned int j = 0; j < dim; ++j)
          if (v & (1u << j))
            for (unsigned int i = 0; i < dim; ++i)
              x[i] += jacobian[i][j];
        affine = affine && x.distance(vertices[v]) <= 1e-12 * cell->diameter();
      }
    if (affine)
      inverse_jacobian = invert(jacobian);
  }



  template <int dim>
  Point<dim>
  CellLevelSets<dim>::reference_point(const Point<dim> &p) const
  {
    if (affine)
      return Point<dim>(inverse_jacobian * (p - vertices[0]));
    Point<dim> xi;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] = 0.5;
    // Newton on x(xi) = p. The cells are at most mildly distorted: a few
    // steps reach round-off.
    for (unsigned int step = 0; step < 20; ++step)
      {
        Point<dim> x;
        for (unsigned int v = 0; v < n_vertices; ++v)
          x += GeometryInfo<dim>::d_linear_shape_function(xi, v) * vertices[v];
        const Tensor<1, dim> correction =
          invert(jacobian_at<dim>(vertices, xi)) * (p - x);
        xi += correction;
        if (correction.norm() < 1e-14)
          break;
      }
    return xi;
  }



  template <int dim>
  double
  CellLevelSets<dim>::interpolate(const std::array<double, n_vertices> &values,
                                  const Point<dim> &xi) const
  {
    double value = 0;
    for (unsigned int v = 0; v < n_vertices; ++v)
      value += values[v] * GeometryInfo<dim>::d_linear_shape_function(xi, v);
    return value;
  }



  template <int dim>
  double
  CellLevelSets<dim>::lsn(const Point<dim> &p) const
  {
    return interpolate(normal, reference_point(p));
  }



  template <int dim>
  double
  CellLevelSets<dim>::lst(const Point<dim> &p) const
  {
    return interpolate(tangent, reference_point(p));
  }



  template <int dim>
  std::pair<Tensor<1, dim>, Tensor<1, dim>>
  CellLevelSets<dim>::gradients(const Point<dim> &p) const
  {
    const Point<dim> xi = reference_point(p);
    Tensor<1, dim>   reference_n, reference_t;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        const Tensor<1, dim> g =
          GeometryInfo<dim>::d_linear_shape_function_gradient(xi, v);
        reference_n += normal[v] * g;
        reference_t += tangent[v] * g;
      }
    // grad_x f = J^{-T} grad_xi f.
    const Tensor<2, dim> inverse =
      (affine ? inverse_jacobian : invert(jacobian_at<dim>(vertices, xi)));
    return {transpose(inverse) * reference_n, transpose(inverse) * reference_t};
  }



  template class CellLevelSets<2>;
  template class CellLevelSets<3>;
} // namespace xcrack
