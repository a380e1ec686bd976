#ifndef xcrack_fracture_front_basis_h
#define xcrack_fracture_front_basis_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The functions of the curvilinear abscissa s along a 3D front on which
   * K(s) and G(s) are discretised, and the test functions psi_j(s) that
   * shape the virtual extensions theta_j = psi_j(s) q(r) e1(s).
   *
   * The domain integral of theta_j gives b_j = int_front K(s) psi_j(s) ds
   * (times 2/E* for K_I, K_II, 1/mu for K_III, 1 for G). With K(s) =
   * sum_i K_i phi_i(s) this is the Galerkin system A K = b, A_ji = int
   * phi_i psi_j ds; values_at_nodes() maps b to K at the nodes.
   *
   * - `legendre` (Code_Aster's LEGENDRE): phi_i = psi_i = the Legendre
   *   polynomials P_0..P_N of s mapped to [-1, 1]. On a closed front a
   *   polynomial would make theta jump where s wraps around (theta must be
   *   continuous), so the periodic analogue is used: 1, cos(2 pi k s / L),
   *   sin(2 pi k s / L), k = 1..N.
   * - `lagrange`: phi_i = psi_i = the hat functions of `n_segments`
   *   equal segments of the front; A is the consistent mass matrix. Exact
   *   for a piecewise-linear K, but the inverse mass matrix amplifies the
   *   noise of the b_j from node to node.
   * - `lagrange regularized`: psi_j are hats spanning four segments (two on
   *   each side of node j) and K at node j is b_j / int psi_j ds, a
   *   weighted average of K over those segments (the mass matrix lumped):
   *   it cannot oscillate; its bias is about K'' (2 l)^2 / 12 for segments
   *   of length l, zero where K is linear.
   *
   * The nodes (where K is reported) are the ends of the equal segments
   * (the first one only, once, on a closed front).
   */
  class FrontBasis
  {
  public:
    enum class Type
    {
      legendre,
      lagrange,
      lagrange_regularized
    };

    /// Parse `legendre | lagrange | lagrange regularized`.
    static Type
    parse_type(const std::string &name);

    /// The basis of a single point (a 2D tip): one test function, 1.
    FrontBasis();

    /**
     * The basis on a front of @p length (closed or open) with
     * @p n_segments equal segments; @p degree for Legendre.
     */
    FrontBasis(const Type         type,
               const unsigned int degree,
               const double       length,
               const bool         closed,
               const unsigned int n_segments);

    unsigned int
    n_test_functions() const;

    /// psi_j(s).
    double
    test_function(const unsigned int j, const double s) const;

    /// Abscissae of the nodes.
    const std::vector<double> &
    nodes() const;

    /// The values of K (or G) at the nodes from b_j = int K psi_j ds.
    std::vector<double>
    values_at_nodes(const std::vector<double> &b) const;

    /// E.g. "Fourier degree 5", "Lagrange, 25 segments" (for the screen).
    std::string
    description() const;

  private:
    /// phi_i(s).
    double
    shape_function(const unsigned int i, const double s) const;

    /// Hat of node @p j with half-width @p width segments.
    double
    hat(const unsigned int j, const double s, const double width) const;

    Type                type     = Type::legendre;
    unsigned int        degree   = 0;
    double              length   = 0;
    bool                closed   = false;
    unsigned int        segments = 0;
    std::vector<double> node_s;
    /// values at the nodes = map * b.
    FullMatrix<double> map;
  };
} // namespace xcrack

#endif
