#ifndef xcrack_fracture_williams_h
#define xcrack_fracture_williams_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * The first (singular) term of the crack-tip fields of Williams and
   * Westergaard, modes I, II and III, in the local tip frame of
   * doc/benchmarks.md (Case 1): polar coordinates (r, theta) about the tip,
   * theta measured from e1 (ahead of the tip), the lips at theta = +-pi.
   * They are the exact solution of elasticity with traction-free lips for
   * every r, the X-FEM branch functions, and the auxiliary fields of the
   * interaction integral.
   *
   * mu is the shear modulus and kappa the Kolosov constant (3 - 4 nu in
   * plane strain and 3D, (3 - nu)/(1 + nu) in plane stress).
   */
  struct WilliamsField
  {
    double k_I   = 0;
    double k_II  = 0;
    double k_III = 0;
    double mu    = 1;
    double kappa = 1.8;

    /// (u1, u2, u3) in the local frame at polar coordinates (r, theta).
    Tensor<1, 3>
    displacement(const double r, const double theta) const;

    /// Gradient d u_i / d x_j in the local frame (x1 along e1, x2 along e2).
    Tensor<2, 3>
    displacement_gradient(const double r, const double theta) const;

    /**
     * The displacements and gradients of the three unit fields (K_I = 1,
     * K_II = 1, K_III = 1 in turn, this field's mu and kappa; its K's are
     * not used), with the trigonometric functions evaluated once: the
     * interaction integral needs all three at every point of its domain.
     * displacement() and displacement_gradient() combine them with this
     * field's K's.
     */
    void
    unit_modes(const double r,
               const double theta,
               Tensor<1, 3> (&u)[3],
               Tensor<2, 3> (&grad)[3]) const;

    /// In-plane stresses (s11, s22, s12) and the antiplane (s13, s23) as a
    /// 3D tensor; s33 is left zero (it depends on the plane model).
    SymmetricTensor<2, 3>
    stress(const double r, const double theta) const;
  };



  /**
   * The Williams field of one straight crack tip as a displacement field in
   * global coordinates: the exact solution of doc/benchmarks.md Case 1 (used as
   * Dirichlet data on the whole boundary and to measure errors). In 3D the
   * front is the straight line through @p tip along e3 = e1 x e2 and the
   * field does not vary along it (plane strain with u3 from mode III only).
   */
  template <int dim>
  class WilliamsSolution : public Function<dim>
  {
  public:
    /// @p e1 points ahead of the tip, @p e2 to the upper lip.
    WilliamsSolution(const WilliamsField  &field,
                     const Point<dim>     &tip,
                     const Tensor<1, dim> &e1,
                     const Tensor<1, dim> &e2);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;

    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

    void
    vector_gradient(const Point<dim>            &p,
                    std::vector<Tensor<1, dim>> &gradients) const override;

  private:
    /// Polar coordinates of @p p about the tip.
    std::pair<double, double>
    polar(const Point<dim> &p) const;

    WilliamsField field;
    Point<dim>    tip;
    /// Rows: the local frame e1, e2 (and e3) in global coordinates.
    Tensor<2, dim> rotation;
  };
} // namespace xcrack

#endif
