#ifndef xcrack_xfem_front_gathering_h
#define xcrack_xfem_front_gathering_h

#include <deal.II/base/point.h>

#include <xcrack/crack/crack_geometry.h>

#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The one-dimensional partition of unity along a crack's fronts that DOF
   * gathering ties the branch DoFs with.
   *
   * With gathering, the branch DoF of a node of the tip zone (for one
   * function and one displacement component) is not free: it takes
   *
   *   a_j = sum_k phi_k(s_j) A_k,
   *
   * where s_j is the abscissa of the node's projection on its front, phi_k
   * the piecewise linear hats of a partition of that front and A_k the
   * branch DoFs of a few master nodes. The partition's nodes are the
   * masters' own abscissae, so a master takes its own value (phi_k(s_k) =
   * delta) and the constraints a_j = sum_k phi_k(s_j) a_{master k} say
   * exactly this. The zone then carries F times a coefficient that varies
   * linearly from master to master along the front: K(s) in 3D at the cost
   * of 4 x dim unknowns per front segment, a single set per 2D tip.
   *
   * A front is an ordered chain of points with abscissa s (CrackSurface's
   * fronts: a closed front repeats its first point last; a 2D tip is a
   * front of one point). Beyond the ends of an open front the coefficient
   * is continued by the end master's value.
   *
   * This class only does the geometry: where a point projects, where the
   * masters should be, and the weights. Enrichment::make_constraints picks
   * the master nodes among the DoFs (the same on every rank) and writes the
   * constraints, interpolating each function's vector of coefficients in
   * the local crack-tip frame (rotated from the masters' frames to the
   * node's) rather than component by component.
   */
  template <int dim>
  class FrontGathering
  {
  public:
    /// Where a point projects: front, abscissa, distance to the front.
    struct Location
    {
      unsigned int front    = 0;
      double       s        = 0;
      double       distance = 0;
    };

    explicit FrontGathering(
      const std::vector<std::vector<FrontPoint<dim>>> &fronts);

    unsigned int
    n_fronts() const;

    /// Whether front @p f is a closed curve.
    bool
    closed(const unsigned int f) const;

    /// Projection of @p x on the nearest front.
    Location
    locate(const Point<dim> &x) const;

    /**
     * Where the masters of front @p f should sit, about @p spacing apart:
     * equal steps over an open front including its ends (at least two),
     * over a closed one (at least three); the one point of a 2D tip.
     */
    std::vector<double>
    targets(const unsigned int f, const double spacing) const;

    /// Distance from @p s1 to @p s2 along front @p f (around a closed one).
    double
    separation(const unsigned int f, const double s1, const double s2) const;

    /**
     * The partition of front @p f: the masters' abscissae, increasing
     * (in [0, length) for a closed front).
     */
    void
    set_nodes(const unsigned int f, const std::vector<double> &s);

    /// The nonzero hats at @p location: (index among its front's nodes,
    /// value), values adding up to one.
    std::vector<std::pair<unsigned int, double>>
    weights(const Location &location) const;

  private:
    std::vector<std::vector<FrontPoint<dim>>> fronts;
    std::vector<bool>                         is_closed;
    std::vector<std::vector<double>>          nodes;
  };
} // namespace xcrack

#endif
