#ifndef xcrack_fracture_interaction_integral_h
#define xcrack_fracture_interaction_integral_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/fracture/front_basis.h>
#include <xcrack/material.h>
#include <xcrack/parsed_function.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * `subsection Fracture parameters`: how K and G are extracted along the
   * front.
   *
   * The virtual crack extension q (theta) is 1 within `Crown radii` r_inf of
   * the front point, 0 beyond r_sup, linear between, interpolated on the
   * mesh's Q1 hats so that the integrands are smooth in every cell; the
   * radii are absolute lengths or (`Crown unit = cells`) multiples of the
   * size of the cell holding the tip, which keeps the same number of cell
   * layers in the crown as the mesh is refined. `Reference K` gives exact
   * or handbook values (expressions of x, y[, z] of the front point) to
   * print the error against.
   *
   * Along a 3D front, `Smoothing`, `Legendre degree` and `Front segments`
   * choose the FrontBasis on which K(s) and G(s) are discretised.
   * `Error estimate` adds to every K the estimate of its error
   * (KErrorEstimator, Simulator::estimate_k_errors()).
   */
  struct FractureParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse; throws InputError naming the entry.
    void
    parse_parameters(ParameterHandler &prm, const FunctionConstants &constants);

    bool compute = true;
    /// Estimate the error of every K (KErrorEstimator).
    bool             error_estimate  = false;
    double           crown_inner     = 2;
    double           crown_outer     = 4;
    bool             crown_in_cells  = true;
    FrontBasis::Type smoothing       = FrontBasis::Type::legendre;
    unsigned int     legendre_degree = 5;
    /// Equal segments of a 3D front (nodes of the Lagrange bases, points
    /// where K is reported); 0: about r_sup long each.
    unsigned int front_segments = 0;
    /// Not a parameter: per front, the segments of its K nodes, which
    /// override Front segments (the K error estimate puts the K of its
    /// wide crown on the nodes of the reported K's); empty: none.
    std::vector<unsigned int> node_segments;
    /// `Crown weight = smooth`: the crown's weight q falls from 1 to 0 as
    /// a smooth step of r (zero slope at both radii), evaluated at every
    /// point rather than interpolated from the vertices. The K error
    /// estimate's wide crown always uses it: its dual problems are loaded
    /// by the gradient of q, and a load that jumps from cell to cell or at
    /// the crown's edges gives a dual solution no recovery can see the
    /// error of. The reported K with it is steadier at the ends of a 3D
    /// front on faces with Dirichlet data (doc/verification.md, "Along a 3D
    /// front").
    bool smooth_weight = false;
    /// K_I; K_II (2D) or K_I; K_II; K_III (3D); null if not given.
    std::shared_ptr<Function<2>> reference_2d;
    std::shared_ptr<Function<3>> reference_3d;
  };



  /// K, G at one front point.
  template <int dim>
  struct FrontValues
  {
    /// Which front (of CrackSurface::fronts()) the point lies on.
    unsigned int front = 0;
    /// The FrontBasis of that front (FrontBasis::description()).
    std::string     basis;
    FrontPoint<dim> point;
    double          k_I = 0, k_II = 0, k_III = 0;
    /// G from the domain form of the J integral (G-theta).
    double g = 0;
    /// G from the K's by Irwin's relation.
    double g_irwin = 0;
    /// The crown radii used.
    double r_inf = 0, r_sup = 0;
    /// K_I, K_II, K_III from the displacement jumps over the crown (the
    /// cross-check; filled by the Simulator).
    std::array<double, 3> k_jump = {{0, 0, 0}};
    /// Estimates of K_exact - K for K_I, K_II, K_III (KErrorEstimator;
    /// filled by the Simulator with Error estimate = true).
    std::array<double, 3> k_error = {{0, 0, 0}};
    /**
     * Whether the crown stays clear of the other tips and of the boundary
     * it cannot integrate over (2D: all of it; 3D: faces with Dirichlet
     * data, whose reaction is unknown; free and loaded faces add their
     * term): the domain form assumes a single singularity inside and no
     * unknown traction on its boundary; if not, K is unreliable.
     */
    bool crown_clear = true;
    /**
     * Whether the lips are closed at the point (contact: most of the lips
     * within r_inf press on each other). A closed point has no opening
     * singularity: K_I counts as 0 where it is used (the growth model),
     * whatever the extraction gives, whose lip term then carries the
     * error of the contact pressures (filled by the Simulator).
     */
    bool closed = false;

    /**
     * Why the point's K, and so its growth, cannot be trusted (a few words
     * without commas, for the files' `reason` columns); empty if it can.
     */
    std::string
    unreliable_reason() const
    {
      return crown_clear ? "" : "crown reaches the boundary or another front";
    }
  };



  /**
   * The derivatives of the K's that InteractionIntegral::compute() returns
   * with respect to the displacement DoFs. Each K is a linear functional of
   * u (up to a constant from the lip pressure and the body force), K(u) =
   * dK . U + c, and dK is the load of the dual problem a(v, z) = dK . v
   * whose solution z weights the residual of u_h in a goal-oriented
   * estimate of K's error (KErrorEstimator).
   */
  struct KDerivatives
  {
    /// Condenses the derivatives: homogeneous Dirichlet and hanging-node
    /// constraints (the dual problems' test space).
    const AffineConstraints<double> *constraints = nullptr;
    /**
     * Stored per test function, not per K node: along a 3D front the
     * nodes outnumber the test functions, and a dual problem per test
     * function serves all nodes. test_loads[t][m]: the derivative of mode
     * m's (K_I, K_II, K_III) integral against test function t (those of
     * all fronts one after the other, scaled as the K's; owned entries,
     * compressed). The derivative of K mode m at the i-th value compute()
     * returns is the sum over (t, w) in node_weights[i] of w
     * test_loads[t][m] (in 2D, one test function per tip and a weight 1).
     */
    std::vector<std::vector<TrilinosWrappers::MPI::Vector>>   test_loads;
    std::vector<std::vector<std::pair<unsigned int, double>>> node_weights;
  };



  /**
   * Stress intensity factors by the interaction integral (Yau, Wang and
   * Corten; domain form of Moes, Dolbow and Belytschko 1999; in 3D the
   * G-theta form of Destuynder and Djaoua with the smoothing of Code_Aster)
   * and G by G-theta, along the fronts of a crack.
   *
   * A virtual crack extension theta (vanishing far from the front, equal
   * to e1 on it) gives
   *
   *   G(theta) = int_V (sigma_ij u_i,k - W delta_jk) theta_k,j dV
   *              - int_lips t_i u_i,k theta_k dA  =  int_front G theta.e1 ds
   *
   * and, with u replaced by u + u^aux, the interaction integral
   *
   *   I(theta) = int_V (sigma_ij u^aux_i,k + sigma^aux_ij u_i,k
   *                     - sigma_il eps^aux_il delta_jk) theta_k,j dV
   *              - int_lips t_i u^aux_i,k theta_k dA
   *            = int_front (2/E* (K_I K^aux_I + K_II K^aux_II)
   *                         + K_III K^aux_III / mu) theta.e1 ds,
   *
   * E* = E/(1 - nu^2) (3D, plane strain) or E (plane stress). u^aux are
   * the Williams fields of a unit K in the frame (e1, e2, e3) of the point
   * of the front nearest to x, r and the angle from e1 in the plane (e1,
   * e2) (plane strain fields, their curvature terms neglected: the error
   * vanishes with the crown). The lip term is there when the lips carry a
   * pressure. A body force f adds - int_V f_i u_i,k theta_k dV to G and
   * - int_V f_i u^aux_i,k theta_k dV to I (the divergence of the energy
   * momentum tensor is no longer zero where f acts), over the whole
   * support of theta, also where q = 1.
   *
   * theta_j = psi_j(s) q(r) e1(s), with q = 1 within r_inf of the front, 0
   * beyond r_sup, is interpolated on the Q1 hats of the mesh (its gradient
   * is then exact cell by cell), and made tangent to the boundary at the
   * boundary vertices of a 3D body (the free surface a front may end on);
   * the test functions psi_j are those of the FrontBasis (one, psi = 1, at
   * a 2D tip), and the b_j = I(theta_j) give K(s) at the basis nodes. The
   * domain terms are integrated with the cell's X-FEM rule (cut and tip
   * rules where the crack is), as the jumps and singular gradients need.
   *
   * Where a crown crosses a face of the body without Dirichlet data (with
   * theta . n = 0 there), that face is part of the boundary of the
   * identity's domain: with the traction t on it (zero on a free face),
   *
   *   G gains  - int_face t_i u_i,k theta_k dA,
   *   I gains  - int_face (t_i u^aux_i,k + sigma^aux_ij n_j u_i,k) theta_k dA.
   *
   * On a free face the first vanishes, but the auxiliary fields do not
   * satisfy the face's traction condition (their sigma^aux n is not zero:
   * plane-strain fields carry sigma^aux_33 = nu (sigma^aux_11 +
   * sigma^aux_22) across a face normal to the front), so the second does
   * not; without it, K at the ends of a surface crack's front falls far
   * below the G-theta value (doc/verification/sif-3d.md, "Where the front
   * meets a free surface"). Walters, Paulino and Dodds (2005) carry the
   * same term for loaded crack faces.
   */
  template <int dim>
  class InteractionIntegral
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    /// Gives the FEValues (values, gradients, quadrature points, JxW and
    /// inverse Jacobians) of a cell reinitialised with its X-FEM rule.
    using FEValuesOf =
      std::function<const FEValues<dim> &(const CellIterator &)>;
    /// The lip rule of a cell: reference points, weights, reference
    /// normals (none for a cell without lips).
    using LipsOf = std::function<void(const CellIterator &,
                                      std::vector<Point<dim>> &,
                                      std::vector<double> &,
                                      std::vector<Tensor<1, dim>> &)>;
    /// A traction on the lsn > 0 lip (force per area; -it on the other)
    /// at the k-th point of a cell's lip rule, besides the lip pressure:
    /// the lips' contact.
    using LipTraction =
      std::function<Tensor<1, dim>(const CellIterator &, const unsigned int)>;

    /**
     * A boundary face of a cell that a crown crosses, and what the body's
     * boundary carries there. On a face without a Dirichlet condition the
     * identity gains the face's term (InteractionIntegral), integrated by
     * @p rule; a face with one makes the crown unreliable (its reaction is
     * not known).
     */
    struct BoundaryFace
    {
      /// A Dirichlet condition (of any component) holds there.
      bool constrained = false;
      /// The traction on the face (force per area, dim components; null:
      /// a traction-free face).
      const Function<dim> *traction = nullptr;
      /// Reference points of the cell on the face and their weights (the
      /// face's reference measure), the crack's jump and front resolved.
      Quadrature<dim> rule;
    };
    /// The BoundaryFace of face @p face_no of a cell (at the boundary).
    using BoundaryFaceOf =
      std::function<BoundaryFace(const CellIterator &, const unsigned int)>;

    InteractionIntegral(const FractureParameters &parameters,
                        const Material           &material);

    /**
     * K and G along each of @p fronts (ordered front points with frames of
     * doc/benchmarks.md, a closed front repeating its first point at the end;
     * a 2D tip is a front of one point) from the ghosted @p solution on
     * @p dof_handler, at the nodes of each front's FrontBasis.
     * @p lip_pressure and @p body_force (dim components) may be null;
     * @p lip_traction adds to the pressure where given. With
     * @p derivatives, also dK/dU of every K returned (of K's linear part:
     * the lip traction counts as given). With @p boundary_face_of, the
     * faces of the body a crown crosses add their term (free and loaded
     * faces) or flag the K's (Dirichlet faces); without, any crown that
     * reaches the boundary other than beyond an end of its front is
     * flagged. Collective.
     */
    std::vector<FrontValues<dim>>
    compute(const DoFHandler<dim>                           &dof_handler,
            const TrilinosWrappers::MPI::Vector             &solution,
            const std::vector<std::vector<FrontPoint<dim>>> &fronts,
            const FEValuesOf                                &fe_values_of,
            const Function<dim>                             *lip_pressure,
            const LipsOf                                    &lips_of,
            const Function<dim>  *body_force       = nullptr,
            KDerivatives         *derivatives      = nullptr,
            const LipTraction    &lip_traction     = LipTraction(),
            const BoundaryFaceOf &boundary_face_of = BoundaryFaceOf()) const;

  private:
    const FractureParameters &parameters;
    const Material           &material;
  };
} // namespace xcrack

#endif
