#include <deal.II/base/tensor.h>

#include <xcrack/xfem/fitted_crack.h>

#include <cmath>
#include <limits>

namespace xcrack
{
  template <int dim>
  FittedCrack<dim>::FittedCrack(
    const CrackGeometry<dim>                         &crack,
    const typename Triangulation<dim>::cell_iterator &cell,
    const std::array<double, n_vertices>             &shift)
    : crack(crack)
    , shift(shift)
  {
    for (unsigned int v = 0; v < n_vertices; ++v)
      vertices[v] = cell->vertex(v);
  }



  template <int dim>
  Point<dim>
  FittedCrack<dim>::reference_point(const Point<dim> &p) const
  {
    Point<dim> xi;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] = 0.5;
    // Newton on x(xi) = p. The cells are at most mildly distorted: a few
    // steps reach round-off; a point outside the cell (never asked for by
    // the rules) still converges to the continuation of the map.
    for (unsigned int step = 0; step < 20; ++step)
      {
        Point<dim>     x;
        Tensor<2, dim> jacobian;
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            x +=
              GeometryInfo<dim>::d_linear_shape_function(xi, v) * vertices[v];
            const Tensor<1, dim> g =
              GeometryInfo<dim>::d_linear_shape_function_gradient(xi, v);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                jacobian[i][j] += vertices[v][i] * g[j];
          }
        const Tensor<1, dim> correction = invert(jacobian) * (p - x);
        xi += correction;
        if (correction.norm() < 1e-14)
          break;
      }
    return xi;
  }



  template <int dim>
  double
  FittedCrack<dim>::lsn(const Point<dim> &p) const
  {
    const Point<dim> xi       = reference_point(p);
    const double     original = crack.lsn(p);
    double           value    = original;
    double           size     = std::abs(original);
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        value -= shift[v] * GeometryInfo<dim>::d_linear_shape_function(xi, v);
        size = std::max(size, std::abs(shift[v]));
      }
    // At a fitted vertex lsn* is zero; Newton leaves round-off there, whose
    // sign would pick a side (zero counts as the + side).
    return (std::abs(value) <=
                64 * std::numeric_limits<double>::epsilon() * size ?
              0. :
              value);
  }



  template <int dim>
  double
  FittedCrack<dim>::lst(const Point<dim> &p) const
  {
    return crack.lst(p);
  }



  template <int dim>
  std::vector<FrontPoint<dim>>
  FittedCrack<dim>::front(const unsigned int      n_points,
                          const BoundingBox<dim> &body) const
  {
    return crack.front(n_points, body);
  }



  template <int dim>
  BoundingBox<dim>
  FittedCrack<dim>::bounding_box(const BoundingBox<dim> &body) const
  {
    return crack.bounding_box(body);
  }



  template class FittedCrack<2>;
  template class FittedCrack<3>;
} // namespace xcrack
