#ifndef xcrack_xfem_cell_quadrature_h
#define xcrack_xfem_cell_quadrature_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>

#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * Quadrature rules on the reference cell [0,1]^dim for the cells an X-FEM
   * crack passes through. The crack is described by the Q1 interpolants of
   * its level sets, given by their values at the cell's vertices (deal.II's
   * vertex numbering): lsn (normal) and lst (tangent, negative on the
   * crack).
   */
  namespace CellQuadrature
  {
    /**
     * The rule of a cell cut by the zero set of lsn: Gauss rules of
     * @p n_points_1d points per direction on each side (deal.II's
     * NonMatching::QuadratureGenerator), joined. Also returns the reference
     * volume of the negative side.
     */
    template <int dim>
    std::pair<Quadrature<dim>, double>
    cut_cell_rule(const std::vector<double> &lsn,
                  const unsigned int         n_points_1d);

    /**
     * A rule on the lips in the cell, {lsn = 0, lst <= 0}, for loads on
     * them (pressure, and later contact): deal.II's surface rule of the
     * zero set of lsn with @p n_points_1d points per direction, its
     * weights and normals (grad lsn, pointing to the lsn > 0 lip) in
     * reference coordinates. Where the front crosses the cell, the lip
     * ends inside it: in 2D the cell is split at the tip across the lip,
     * and the half ahead of the tip dropped, which is exact; in 3D the
     * cell is divided into @p subdivisions^dim boxes, each with its own
     * surface rule, and the points ahead of the front are dropped, which
     * is first order in the box size on the cells the front crosses.
     */
    template <int dim>
    NonMatching::ImmersedSurfaceQuadrature<dim>
    lip_rule(const std::vector<double> &lsn,
             const std::vector<double> &lst,
             const unsigned int         n_points_1d,
             const unsigned int         subdivisions);

    /// Points on a face of the reference cell (see face_rule()).
    template <int dim>
    struct FaceRule
    {
      std::vector<Point<dim>> points;
      /// Measures in the face's reference coordinates.
      std::vector<double> weights;
      /// Whether the point lies on the lips (the crack runs in the face).
      std::vector<bool> on_lip;
    };

    /**
     * A rule on face @p face_no of @p box, a box of the reference cell
     * that shares that face with it (the whole cell, or the part next to
     * a finer neighbour), for residuals on faces: Gauss rules of
     * @p n_points_1d points per direction on each side of the zero set of
     * lsn (deal.II's NonMatching::FaceQuadratureGenerator), so that no
     * point straddles the crack where it crosses the face. Where the crack
     * lies in the face (|lsn| <= @p zero at the face's corners, a crack
     * along a row of nodes), the face is split by lst instead and its part
     * with lst < 0 is lip. Points are in the cell's reference coordinates.
     */
    template <int dim>
    FaceRule<dim>
    face_rule(const std::vector<double> &lsn,
              const std::vector<double> &lst,
              const unsigned int         face_no,
              const BoundingBox<dim>    &box,
              const unsigned int         n_points_1d,
              const double               zero);

    /**
     * A rule on face @p face_no of the reference cell (points in the
     * cell's coordinates, weights the face's reference measure) for
     * integrals over a face of the body the crack meets: where lsn changes
     * sign on the face, the displacement jumps across the crack's trace,
     * and where the front ends on the face its gradients grow like r^-1/2.
     * Such a face gets the 2D rule of the level sets restricted to it (the
     * fan of tip_cell_rule() about the point where the front meets the
     * face, or cut_cell_rule() behind the front), every other face a Gauss
     * rule; @p n_points_1d points per direction. 3D only (empty in 2D).
     */
    template <int dim>
    Quadrature<dim>
    boundary_face_rule(const std::vector<double> &lsn,
                       const std::vector<double> &lst,
                       const unsigned int         face_no,
                       const unsigned int         n_points_1d);

    /**
     * Where the jumps across the lips are read: for each lip point (reference
     * coordinates) with unit reference normal, the point @p offset along
     * the normal (the lsn > 0 side) and the point @p offset against it,
     * interleaved. The enrichment functions take their one-sided values
     * there while the polynomials have not moved.
     */
    template <int dim>
    std::vector<Point<dim>>
    both_sides(const std::vector<Point<dim>>     &points,
               const std::vector<Tensor<1, dim>> &normals,
               const double                       offset = 1e-8)
    {
      std::vector<Point<dim>> sides;
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          sides.push_back(points[k] + offset * normals[k]);
          sides.push_back(points[k] - offset * normals[k]);
        }
      return sides;
    }

    /**
     * Nanson's formula: the real vector n ds of a surface element whose
     * reference unit normal is @p normal and reference measure @p weight,
     * mapped with Jacobian @p J: det(J) J^-T normal weight.
     */
    template <int dim>
    Tensor<1, dim>
    mapped_normal(const Tensor<2, dim> &J,
                  const Tensor<1, dim> &normal,
                  const double          weight)
    {
      return determinant(J) * (transpose(invert(J)) * normal) * weight;
    }

    /**
     * The points where the crack front {lsn = 0, lst = 0} meets the closed
     * reference cell: in 2D the tip (if it lies in the cell), in 3D the
     * points where the front crosses the cell's faces. A front that runs
     * inside a face or along an edge contributes the ends of that piece.
     * Empty when the front does not touch the cell.
     */
    template <int dim>
    std::vector<Point<dim>>
    front_points(const std::vector<double> &lsn,
                 const std::vector<double> &lst);

    /**
     * The rule of a cell the crack front touches, built to integrate the
     * crack-tip fields: their gradients grow like r^(-1/2) toward the front,
     * and the lips (lsn = 0, lst < 0) carry a jump.
     *
     * In 2D the cell is split into triangles that fan out from the tip to
     * its boundary, with the points where lsn = 0 leaves the cell among the
     * triangles' corners so that no triangle straddles a lip. Each triangle
     * is mapped from the unit square by a Duffy collapse at the tip, whose
     * radial coordinate is graded as u = s^2: the Jacobian then contributes
     * r ~ s^2 ds, which cancels the 1/r of the products of two singular
     * gradients, and the integrands of the stiffness matrix become smooth
     * in (s, v). @p n_points_1d Gauss points per direction and triangle.
     *
     * In 3D the cell is cut into slices normal to the reference axis the
     * front runs most nearly along; each slice carries the 2D rule above
     * about the point where the front crosses it (or the cut rule when it
     * does not). The axis is split where the front leaves through a side
     * face, so that the integrand is smooth along it within each piece;
     * @p n_points_1d Gauss points along each piece.
     *
     * For a cell the front passes close to without touching it, the fan
     * starts from the cell's point nearest to the front: where the crack
     * plane leaves the cell nearest to it if it crosses the cell, else the
     * front's position clipped to the cell. A Gauss rule there would see an
     * integrand singular just outside the cell (measured: a tip 4 % of a
     * cell from a neighbour multiplied the Q2 energy error by ten).
     */
    template <int dim>
    Quadrature<dim>
    tip_cell_rule(const std::vector<double> &lsn,
                  const std::vector<double> &lst,
                  const unsigned int         n_points_1d);

    /**
     * The distance, in reference coordinates (the cell's width 1), from the
     * reference cell to the crack front {lsn = 0, lst = 0}, for a cell the
     * front does not touch and the crack does not cut: where the branch
     * functions and their products stop being analytic (the lips behind
     * the front are no obstacle: a function of the half angle that is
     * smooth in the cell continues analytically around them, up to the
     * front). The level sets are taken linear about the cell's centre (the
     * front a line there). Infinite where their gradients are parallel.
     */
    template <int dim>
    double
    front_distance(const std::vector<double> &lsn,
                   const std::vector<double> &lst);

    /**
     * The number of Gauss points per direction with which the integrands
     * of the branch functions (their gradients ~ 1/sqrt(r), products ~ 1/r)
     * reach the relative error @p tolerance in a cell at reference
     * distance @p distance from the front (front_distance()). Gauss on
     * [0, 1] converges like rho^(-2n) for a function analytic inside the
     * Bernstein ellipse of parameter rho; along a line of the tensor rule
     * the front is a complex singularity at about that distance from the
     * line, at worst beside its midpoint: rho = 2 d + sqrt(1 + 4 d^2).
     * (tests/near_front_rule checks the tolerance is met.)
     */
    unsigned int
    graded_gauss_points(const double distance, const double tolerance);
  } // namespace CellQuadrature
} // namespace xcrack

#endif
