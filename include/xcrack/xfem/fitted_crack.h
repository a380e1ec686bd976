#ifndef xcrack_xfem_fitted_crack_h
#define xcrack_xfem_fitted_crack_h

#include <deal.II/base/geometry_info.h>

#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>

#include <array>

namespace xcrack
{
  using namespace dealii;

  /**
   * A crack as one cell sees it after fit-to-vertex: the crack's normal
   * level set minus the d-linear interpolant of the shifts applied at the
   * cell's vertices,
   *
   *   lsn*(x) = lsn(x) - sum_v shift_v N_v(x),
   *
   * where shift_v = lsn(x_v) at a vertex the crack passes closer to than
   * the fit-to-vertex tolerance, 0 elsewhere. lsn* vanishes at those
   * vertices: the crack surface moves through them, by at most the
   * tolerance times the cell size, and only in the cells around them.
   *
   * Why a per-cell object: the cut-cell and tip rules are built from the
   * level sets at the vertices, and the enrichment functions (H = sign of
   * lsn, the branch functions' angle) must put every quadrature point on
   * the side the rule put it. Evaluating them with this lsn* keeps the two
   * consistent; lsn* is continuous across cells (the hats are), so the
   * enriched functions stay conforming.
   *
   * Everything else (lst, the front, the box) is the crack's own.
   */
  template <int dim>
  class FittedCrack : public CrackGeometry<dim>
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;

    /// The view of @p crack from @p cell, with @p shift at its vertices
    /// (in deal.II's vertex order).
    FittedCrack(const CrackGeometry<dim>                         &crack,
                const typename Triangulation<dim>::cell_iterator &cell,
                const std::array<double, n_vertices>             &shift);

    double
    lsn(const Point<dim> &p) const override;

    double
    lst(const Point<dim> &p) const override;

    std::vector<FrontPoint<dim>>
    front(const unsigned int      n_points,
          const BoundingBox<dim> &body) const override;

    BoundingBox<dim>
    bounding_box(const BoundingBox<dim> &body) const override;

    /**
     * Coordinates of @p p in the reference cell of the d-linear map of the
     * cell (Newton's method; exact after one step on parallelograms and
     * parallelepipeds).
     */
    Point<dim>
    reference_point(const Point<dim> &p) const;

  private:
    const CrackGeometry<dim>            &crack;
    std::array<Point<dim>, n_vertices>   vertices;
    const std::array<double, n_vertices> shift;
  };
} // namespace xcrack

#endif
