#ifndef xcrack_material_h
#define xcrack_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <xcrack/parsed_function.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * Isotropic linear elastic material. In 2D the out-of-plane behaviour is
   * either plane strain (eps_zz = 0) or plane stress (sigma_zz = 0); plane
   * stress enters the 2D equations through an effective Lame constant
   * lambda* = 2 lambda mu / (lambda + 2 mu), so the assembly is the same for
   * both.
   *
   * Parameters live in `subsection Material`.
   */
  class Material
  {
  public:
    enum class PlaneModel
    {
      plane_strain,
      plane_stress
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse and check the entries; throws InputError naming the entry.
    void
    parse_parameters(ParameterHandler &prm);

    /// Shear modulus mu = E / (2 (1 + nu)).
    double
    mu() const;

    /// Lame's first constant as it enters the @p dim dimensional equations.
    double
    lambda(const unsigned int dim) const;

    /// Kolosov constant: 3 - 4 nu (plane strain, 3D) or (3 - nu)/(1 + nu).
    double
    kappa(const unsigned int dim) const;

    /// E' = E / (1 - nu^2) (plane strain, 3D) or E (plane stress): G =
    /// (K_I^2 + K_II^2) / E'.
    double
    e_prime(const unsigned int dim) const;

    /// sigma = lambda tr(eps) I + 2 mu eps.
    template <int dim>
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const;

    /**
     * Von Mises stress of the in-plane stress @p stress, with the
     * out-of-plane stress sigma_zz = nu (sigma_xx + sigma_yy) of plane strain
     * included in 2D.
     */
    template <int dim>
    double
    von_mises(const SymmetricTensor<2, dim> &stress) const;

    /// E, nu, mu, lambda for use in parsed expressions.
    FunctionConstants
    constants(const unsigned int dim) const;

    double     youngs_modulus = 1.;
    double     poisson_ratio  = 0.3;
    PlaneModel plane_model    = PlaneModel::plane_strain;
    /// K_Ic (0: not given), for the laws and criteria that need it.
    double fracture_toughness = 0;
  };
} // namespace xcrack

#endif
