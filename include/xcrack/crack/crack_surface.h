#ifndef xcrack_crack_crack_surface_h
#define xcrack_crack_crack_surface_h

#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/level_set_fields.h>

#include <functional>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The crack as the mesh sees it: the zero set of the Q1 interpolant of
   * lsn where lst <= 0 (the lips: a polygon per cell in 3D, a segment in
   * 2D), and the front where both level sets vanish, extracted cell by cell
   * and ordered along the front.
   *
   * This is what the enrichment and the quadrature actually use, so it is
   * what the user should look at (crack-<step>.vtu, with the opening of the
   * lips), and it is the front that fracture parameters and propagation
   * work on once the level sets are no longer analytic (after the first
   * propagation step, or for a crack given as a surface mesh).
   *
   * Front extraction: the front crosses the faces of the cells it passes
   * through (CellQuadrature::front_points gives the crossings on the
   * reference faces); each cell with two crossings contributes a segment,
   * segments are joined at common points across all ranks, and the chains
   * are oriented so that e3 = e1 x e2 points along increasing s
   * (doc/benchmarks.md). The frame at a point comes from the level-set
   * gradients averaged over the cells that share the point: e2 along grad
   * lsn, e1 along grad lst made normal to e2. In 2D every tip is a front of
   * one point, and e2 is e1 turned by +90 degrees as for the analytic
   * shapes.
   */
  template <int dim>
  class CrackSurface
  {
  public:
    /**
     * Extract the lips and the front of crack @p crack from the level-set
     * fields (collective: every rank gets every front).
     */
    void
    extract(const LevelSetFields<dim> &level_sets, const unsigned int crack);

    /// The fronts, each ordered along itself with abscissa s from 0.
    const std::vector<std::vector<FrontPoint<dim>>> &
    fronts() const;

    /// Total length (3D) of the fronts; 0 in 2D.
    double
    front_length() const;

    /**
     * The lip pieces of all ranks (collective), each as its corners (a
     * segment in 2D, a polygon in its order in 3D) and its unit normal to
     * the lsn > 0 side; pieces of no extent are left out.
     */
    std::vector<std::pair<std::vector<Point<dim>>, Tensor<1, dim>>>
    lips() const;

    /// Area of the lips (3D) or length of the crack (2D), over all ranks.
    double
    measure() const;

    /**
     * The largest opening |u(lsn > 0 side) - u(lsn < 0 side)| of the lips
     * of the solution @p solution (ghosted) on @p dof_handler, whose mesh
     * is the level sets' mesh.
     */
    double
    max_opening(const DoFHandler<dim>               &dof_handler,
                const TrilinosWrappers::MPI::Vector &solution) const;

    /**
     * Values that a term on the lips (contact) gives per cell, written as
     * cell data of the lip pieces: @p name, @p n_components (1, or 3 for a
     * vector), and the values on the cell with id @p cell (zeros where the
     * term has none; the fronts' cells get zeros).
     */
    struct LipField
    {
      std::string                                        name;
      unsigned int                                       n_components = 1;
      std::function<std::vector<double>(const CellId &)> value;
    };

    /**
     * Write the lips (with the opening [[u]], the gap n . [[u]] and the
     * slip [[u]] - (n . [[u]]) n as point data, n the unit normal to the
     * lsn > 0 lip; the gap is negative where the lips interpenetrate) and
     * the fronts (with s) to @p file_name, a VTU file written by rank 0
     * from the pieces of all ranks; @p fields add cell data to the lips.
     */
    void
    write_vtu(const std::string                   &file_name,
              const DoFHandler<dim>               &dof_handler,
              const TrilinosWrappers::MPI::Vector &solution,
              const std::vector<LipField>         &fields = {}) const;

  private:
    /// A piece of lip in one locally owned cell.
    struct Piece
    {
      unsigned int level, index;
      /// Corners in reference and real coordinates (a segment in 2D, a
      /// polygon in its order around the piece in 3D).
      std::vector<Point<dim>> reference, real;
      /// Unit reference-space gradient of lsn at each corner: the side
      /// toward which the lsn > 0 lip lies.
      std::vector<Tensor<1, dim>> reference_normal;
    };

    /// The unit normal of @p piece in real space, to its lsn > 0 side
    /// (zero for a piece of no extent).
    static Tensor<1, dim>
    real_normal(const Piece &piece);

    /// Displacement jumps at the corners of the local pieces.
    std::vector<std::vector<Tensor<1, dim>>>
    openings(const DoFHandler<dim>               &dof_handler,
             const TrilinosWrappers::MPI::Vector &solution) const;

    MPI_Comm                                  communicator = MPI_COMM_SELF;
    std::vector<Piece>                        pieces;
    std::vector<std::vector<FrontPoint<dim>>> front_chains;
    double                                    lips_measure = 0;
  };
} // namespace xcrack

#endif
