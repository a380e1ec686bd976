#ifndef xcrack_xfem_cell_level_sets_h
#define xcrack_xfem_cell_level_sets_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>

#include <array>

namespace xcrack
{
  using namespace dealii;

  /**
   * A crack's level sets inside one cell: the d-linear interpolants of their
   * values at the cell's vertices,
   *
   *   lsn_h(x) = sum_v lsn_v N_v(xi(x)),   lst_h(x) = sum_v lst_v N_v(xi(x)),
   *
   * xi(x) the reference coordinates of x in the cell's d-linear map.
   *
   * Why: the crack of a run is its level-set fields on the mesh, and the
   * cut-cell and tip rules are built from the vertex values. The jump and
   * branch functions evaluate this object, so every quadrature point lies
   * on the side, and at the distance from the front, that the rule put it
   * (a crack fitted to a vertex is a zero vertex value here; evaluated at
   * the vertex itself, round-off picks the sign: callers that need the
   * vertex's value take it from the vertex values). lsn_h and
   * lst_h are continuous across cells (the hats are), so the enriched
   * functions stay conforming; their gradients are exact cell by cell.
   */
  template <int dim>
  class CellLevelSets : public LevelSetFunctions<dim>
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;

    /// The level sets with values @p lsn and @p lst at the vertices of
    /// @p cell (in deal.II's vertex order).
    CellLevelSets(const typename Triangulation<dim>::cell_iterator &cell,
                  const std::array<double, n_vertices>             &lsn,
                  const std::array<double, n_vertices>             &lst);

    double
    lsn(const Point<dim> &p) const override;

    double
    lst(const Point<dim> &p) const override;

    std::pair<Tensor<1, dim>, Tensor<1, dim>>
    gradients(const Point<dim> &p) const override;

    /**
     * Coordinates of @p p in the reference cell of the d-linear map of the
     * cell: directly on parallelograms and parallelepipeds, by Newton's
     * method on other cells. A point outside the cell gets the
     * continuation of the map.
     */
    Point<dim>
    reference_point(const Point<dim> &p) const;

  private:
    /// The d-linear interpolant of @p values at reference point @p xi.
    double
    interpolate(const std::array<double, n_vertices> &values,
                const Point<dim>                     &xi) const;

    std::array<Point<dim>, n_vertices> vertices;
    std::array<double, n_vertices>     normal, tangent;
    /// Whether the cell is an affine image of the reference cell, and the
    /// inverse of its map's (constant) Jacobian then.
    bool           affine = false;
    Tensor<2, dim> inverse_jacobian;
  };
} // namespace xcrack

#endif
