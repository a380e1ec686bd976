#ifndef xcrack_fracture_crown_h
#define xcrack_fracture_crown_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/fracture/front_basis.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/hanging_vertices.h>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  struct FractureParameters;

  /**
   * The crown of one front: the domain over which InteractionIntegral
   * integrates, and the virtual crack extensions theta_j = psi_j(s) q(r)
   * e1(s) on it. q = 1 within r_inf of the front, 0 beyond r_sup; the
   * radii are multiples of the size of the cells the front crosses (Crown
   * unit = cells) or lengths; psi_j are the test functions of the front's
   * FrontBasis (one, psi = 1, at a 2D tip).
   *
   * A class of its own because everything the crown decides (its radii,
   * which cells it reaches, whether it is clear of other fronts) is what
   * the reliability of the K's rests on, and CellTheta reads theta on its
   * cells.
   */
  template <int dim>
  class Crown
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /// The crown of front @p f of @p fronts on the mesh of @p dof_handler
    /// (collective: the cell size at the front is a minimum over ranks).
    Crown(const FractureParameters                        &parameters,
          const DoFHandler<dim>                           &dof_handler,
          const std::vector<std::vector<FrontPoint<dim>>> &fronts,
          const unsigned int                               f);

    /// q(r): linear from r_inf to r_sup, or a smooth step.
    double
    q(const double r) const;

    /// dq/dr of the smooth step.
    double
    dq_dr(const double r) const;

    /**
     * 3D: the radius of the tube about the front that the domain terms
     * leave out, 1e-3 r_inf. The auxiliary fields are singular on the
     * front's polyline, while the tip rule grades its points towards the
     * level sets' front, which bends between the polyline's points (by
     * up to about 1e-3 of a cell). A point that the rule puts much nearer
     * the polyline than the level-set front samples the singularity where
     * no weight expects it: one point 7e-8 from the polyline gave a K_III
     * of 5 % of K_I on a grown penny (doc/verification/growth.md, "A
     * plane crack stays plane"). The tube's share of the integrals is of
     * order core / r_sup. Zero in 2D, where both fronts are one point.
     */
    double
    core() const
    {
      return dim == 3 ? 1e-3 * r_inf : 0.;
    }

    /// The segments of the front that can be nearest to a point of
    /// @p cell, [first, last), or nothing if the crown cannot reach it.
    std::optional<std::pair<unsigned int, unsigned int>>
    segments_near(const CellIterator &cell) const;

    /// Segments of the front (0 for a 2D tip).
    unsigned int n_segments;
    /// The radii's unit: the size of the smallest cell the front crosses
    /// (Crown unit = cells), or 1.
    double unit;
    double r_inf;
    double r_sup;
    /// Crown weight = smooth: q evaluated at every point.
    bool smooth;
    /// The front, with frames differenced over half of r_sup.
    FrontCurve<dim> curve;
    FrontBasis      basis;
    /// Whether no point of another front lies within r_sup of this one.
    bool clear_of_other_fronts;

  private:
    /// The front's bounding box grown by r_sup: cells beyond it carry no
    /// theta.
    Point<dim> box_low, box_high;
  };



  /**
   * theta_j on one cell of a crown: the vertices' q e1 and psi_j,
   * interpolated on the cell's Q1 hats, so that grad theta_j is exact cell
   * by cell. q at a hanging vertex is its masters' interpolation (q stays
   * continuous across faces of coarser neighbours). At the vertices on the
   * body's boundary, a 3D theta is made tangent to the boundary faces:
   * the domain form of G holds on a traction-free face only if theta . n =
   * 0 there, the end of an open front on a free surface.
   *
   * With a smooth weight the vertices carry e1 alone and q(r) multiplies
   * the interpolant at each point.
   */
  template <int dim>
  class CellTheta
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;

    /// @p hanging: the mesh's hanging vertices (null with a smooth
    /// weight, which is not interpolated).
    CellTheta(const Crown<dim> &crown, const HangingVertices<dim> *hanging);

    /**
     * Theta on @p cell, whose nearest segments are [@p first, @p last).
     * Returns false where theta vanishes on the whole cell.
     */
    bool
    reinit(const CellIterator &cell,
           const unsigned int  first,
           const unsigned int  last);

    /**
     * Whether q > 0 at a vertex of face @p face_no of the cell (the crown
     * crosses that face), counting vertices whose foot lies beyond an end
     * of the front only if @p beyond_ends.
     */
    bool
    reaches(const CellIterator &cell,
            const unsigned int  face_no,
            const bool          beyond_ends) const;

    /// Whether q varies on the cell (where a 2D domain term lives).
    bool
    varies() const
    {
      return q_max > q_min;
    }

    /// The test functions that do not vanish on the cell.
    const std::vector<unsigned int> &
    active_tests() const
    {
      return active;
    }

    /// theta_j at reference point @p xi, at distance @p r from the front.
    Tensor<1, dim>
    value(const Point<dim> &xi, const double r, const unsigned int j) const;

    /**
     * grad theta_j at reference point @p xi, whose shape gradients in
     * real space are @p grad_N (shape_gradients()), at local coordinates
     * @p xl of the foot @p projection (distance @p r). With a smooth weight
     * q'(r) I_h(psi_j e1) (x) grad r + q(r) grad I_h(psi_j e1).
     */
    Tensor<2, dim>
    gradient(const Point<dim>                             &xi,
             const std::array<Tensor<1, dim>, n_vertices> &grad_N,
             const typename FrontCurve<dim>::Projection   &projection,
             const Tensor<1, dim>                         &xl,
             const double                                  r,
             const unsigned int                            j) const;

    /// The real-space gradients of the Q1 hats at reference point @p xi,
    /// (d xi / d x)^T grad_xi N_v, with @p inverse = d xi / d x.
    static std::array<Tensor<1, dim>, n_vertices>
    shape_gradients(const Point<dim>                  &xi,
                    const DerivativeForm<1, dim, dim> &inverse);

  private:
    /// The interpolant of the vertices' psi_j w at @p xi.
    Tensor<1, dim>
    interpolant(const Point<dim> &xi, const unsigned int j) const;

    /// Make w_vertex tangent to the boundary faces of @p cell.
    void
    tangent_to_boundary(const CellIterator &cell);

    const Crown<dim>           &crown;
    const HangingVertices<dim> *hanging;
    /// Per vertex: q e1 (e1 with a smooth weight), and psi_j(s).
    std::array<Tensor<1, dim>, n_vertices>      w_vertex;
    std::array<std::vector<double>, n_vertices> psi_vertex;
    std::vector<unsigned int>                   active;
    /// Per vertex: q > 0; the foot lies beyond an end of the front.
    std::array<bool, n_vertices> positive, beyond_end;
    double                       q_min = 1, q_max = 0;
  };
} // namespace xcrack

#endif
