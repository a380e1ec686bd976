#ifndef xcrack_elastic_cell_matrix_h
#define xcrack_elastic_cell_matrix_h

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The stiffness matrix of one cell for isotropic linear elasticity,
   * computed as two symmetric BLAS products instead of a loop over points
   * and pairs of shape functions:
   * @f[
   *   K = \sum_q w_q \left( 2\mu\, M_q^T M_q + \lambda\, d_q d_q^T \right),
   * @f]
   * where the rows of $M_q$ hold the shape functions' strains in Mandel
   * notation (the shear entries times $\sqrt 2$, so that $M_q^T M_q$ is
   * the double contraction of the strains) and $d_q$ their divergences.
   *
   * Why: a cell near the crack's front carries 120 to 144 DoFs in 3D and
   * is integrated by a tip rule of several hundred to three thousand
   * points; the pair loop made the assembly of such cells the largest cost
   * of a 3D step. BLAS's symmetric rank-k update (dsyrk) does the same
   * arithmetic several times faster and only one triangle of it. The
   * results equal the loop's to round-off.
   *
   * The element must be primitive with <tt>dim</tt> components (the
   * displacement): every shape function has one nonzero component. The
   * object keeps its work arrays between calls: use one per thread.
   */
  template <int dim>
  class ElasticCellMatrix
  {
  public:
    /**
     * Set @p cell_matrix (resized to the cell's DoFs) to the stiffness of
     * the cell that @p fe_values was reinitialised on, for the Lamé
     * constants @p lambda (any sign) and @p mu (> 0).
     */
    void
    compute(const FEValues<dim> &fe_values,
            const double         lambda,
            const double         mu,
            FullMatrix<double>  &cell_matrix);

  private:
    /// Points per block: rows of a block stay in cache across the update.
    static constexpr unsigned int points_per_block = 32;

    /// Strain rows per point in Mandel notation.
    static constexpr unsigned int n_strains = dim * (dim + 1) / 2;

    /// The displacement component of each shape function.
    std::vector<unsigned int> component;

    /// Column-major blocks: strains (n_strains rows per point) and
    /// divergences (one row per point), both times sqrt(w_q).
    std::vector<double> strains;
    std::vector<double> divergences;

    /// Column-major result of the updates, lower triangle.
    std::vector<double> product;
  };
} // namespace xcrack

#endif
