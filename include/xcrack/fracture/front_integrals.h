#ifndef xcrack_fracture_front_integrals_h
#define xcrack_fracture_front_integrals_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/fracture/crown.h>
#include <xcrack/fracture/integral_derivatives.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/material.h>

#include <cmath>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /// Where a point of the crown lies relative to the front, and the
  /// displacement gradient there: what every integrand reads.
  template <int dim>
  struct CrownPoint
  {
    /// Reference and real coordinates.
    Point<dim> xi, x;
    /// The foot on the front, the local coordinates in its frame, the
    /// distance r from the front and the angle from e1 in (e1, e2).
    typename FrontCurve<dim>::Projection projection;
    Tensor<1, dim>                       xl;
    double                               r, angle;
    Tensor<2, dim>                       du;

    CrownPoint(const Crown<dim>  &crown,
               const Point<dim>  &xi,
               const Point<dim>  &x,
               const unsigned int first,
               const unsigned int last)
      : xi(xi)
      , x(x)
      , projection(crown.curve.project(x, first, last))
      , xl(projection.R * (x - projection.foot))
      , r(std::hypot(xl[0], xl[1]))
      , angle(std::atan2(xl[1], xl[0]))
    {}
  };



  /**
   * The integrals b_jm = I_m(theta_j) of one front (m: the interaction
   * integral of each mode's unit auxiliary field, then G), summed cell by
   * cell, and with derivatives also d b_jm / dU. Each term of the
   * identity in InteractionIntegral's documentation is a function of its
   * own: the domain term, the body force, the divergence of the
   * auxiliary stress (3D), the lips.
   */
  template <int dim>
  class FrontIntegrals
  {
  public:
    static constexpr unsigned int n_modes     = (dim == 3 ? 3 : 2);
    static constexpr unsigned int n_integrals = n_modes + 1;

    FrontIntegrals(const Material                      &material,
                   const WilliamsField                 &unit,
                   const Crown<dim>                    &crown,
                   const TrilinosWrappers::MPI::Vector &solution,
                   IntegralDerivatives<dim>            *d_b)
      : b(crown.basis.n_test_functions() * n_integrals, 0.)
      , material(material)
      , unit(unit)
      , crown(crown)
      , solution(solution)
      , d_b(d_b)
      , grad_theta(crown.basis.n_test_functions())
      , theta(crown.basis.n_test_functions())
    {}

    /// The terms over the cell's X-FEM rule @p fe_values: the domain
    /// term, the body force @p body_force (if not null), the divergence
    /// term (3D).
    void
    add_domain_terms(const FEValues<dim>  &fe_values,
                     const CellTheta<dim> &cell_theta,
                     const unsigned int    first,
                     const unsigned int    last,
                     const Function<dim>  *body_force);

    /// The lip terms on the lip rule of @p cell (reference points,
    /// weights, normals), under the pressure @p lip_pressure (may be
    /// null) and the traction @p lip_traction (may be empty).
    void
    add_lip_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const CellTheta<dim>                                 &cell_theta,
      const unsigned int                                    first,
      const unsigned int                                    last,
      const std::vector<Point<dim>>                        &points,
      const std::vector<double>                            &weights,
      const std::vector<Tensor<1, dim>>                    &normals,
      const Function<dim>                                  *lip_pressure,
      const typename InteractionIntegral<dim>::LipTraction &lip_traction);

    /// The term of the boundary face @p face_no of @p cell, which the
    /// crown crosses: see InteractionIntegral.
    void
    add_face_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const CellTheta<dim> &cell_theta,
                   const unsigned int    first,
                   const unsigned int    last,
                   const unsigned int    face_no,
                   const typename InteractionIntegral<dim>::BoundaryFace &face);

    /// b_jm at index j * n_integrals + m (this rank's part).
    std::vector<double> b;

  private:
    /**
     * int T_m : grad theta_j with T_m,kj = sigma_ij u^aux_i,k +
     * sigma^aux_ij u_i,k - sigma_il eps^aux_il delta_jk for the modes
     * and sigma_ij u_i,k - W delta_jk for G; its derivative for du = G
     * is G : A with A = C : sym(du_aux Theta) + sigma_aux Theta^T -
     * tr(Theta) sigma_aux.
     */
    void
    domain_term(const CrownPoint<dim> &p,
                const Tensor<2, dim> (&du_aux)[n_modes],
                const std::vector<unsigned int> &active,
                const double                     JxW);

    /// - int f_i u^aux_i,k theta_k (modes), - int f_i u_i,k theta_k (G):
    /// the energy-momentum tensor's divergence where f acts.
    void
    body_force_term(const CrownPoint<dim> &p,
                    const Tensor<1, dim>  &f,
                    const Tensor<2, dim> (&du_aux)[n_modes],
                    const std::vector<unsigned int> &active,
                    const double                     JxW);

    /// + int div(sigma^aux)_i u_i,k theta_k: along a curved 3D front the
    /// auxiliary stress is not in equilibrium (aux_stress_divergence()).
    void
    divergence_term(const CrownPoint<dim>           &p,
                    const std::vector<unsigned int> &active,
                    const double                     JxW);

    const Material                      &material;
    const WilliamsField                 &unit;
    const Crown<dim>                    &crown;
    const TrilinosWrappers::MPI::Vector &solution;
    IntegralDerivatives<dim>            *d_b;
    const FEValuesExtractors::Vector     displacement{0};
    const MappingQ1<dim>                 mapping;
    /// Per point and test function: grad theta_j, theta_j.
    std::vector<Tensor<2, dim>> grad_theta;
    std::vector<Tensor<1, dim>> theta;
    std::vector<Tensor<2, dim>> grad_u;
  };
} // namespace xcrack

#endif
