#include <deal.II/base/utilities.h>

#include <xcrack/input_error.h>
#include <xcrack/material.h>

#include <cmath>

namespace xcrack
{
  void
  Material::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1",
                        Patterns::Double(),
                        "Young's modulus E (> 0).");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(),
                        "Poisson's ratio nu, -1 < nu < 0.5.");
      prm.declare_entry("Plane model",
                        "plane strain",
                        Patterns::Selection("plane strain|plane stress"),
                        "Out-of-plane assumption of 2D runs (ignored in 3D).");
      prm.declare_entry("Fracture toughness",
                        "0",
                        Patterns::Double(0),
                        "K_Ic, in the units of the stress intensity factors "
                        "(0: not given). Needed by the growth laws forman "
                        "and quasi-static and by the termination criterion "
                        "'fracture toughness'.");
    }
    prm.leave_subsection();
  }



  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson's ratio");
      plane_model =
        (prm.get("Plane model") == "plane strain" ? PlaneModel::plane_strain :
                                                    PlaneModel::plane_stress);
      fracture_toughness = prm.get_double("Fracture toughness");
    }
    prm.leave_subsection();

    check_input(youngs_modulus > 0,
                "Material/Young's modulus = " +
                  Utilities::to_string(youngs_modulus) + ": must be positive.");
    check_input(std::isnormal(youngs_modulus) && youngs_modulus > 1e-200 &&
                  youngs_modulus < 1e200,
                "Material/Young's modulus = " +
                  Utilities::to_string(youngs_modulus) +
                  ": out of the range of numbers the solver can work with "
                  "(choose units in which it lies between 1e-200 and "
                  "1e200).");
    check_input(poisson_ratio > -1 && poisson_ratio < 0.5,
                "Material/Poisson's ratio = " +
                  Utilities::to_string(poisson_ratio) +
                  ": must satisfy -1 < nu < 0.5 (nu = 0.5 is incompressible, "
                  "which a displacement formulation cannot represent).");
  }



  double
  Material::mu() const
  {
    return youngs_modulus / (2. * (1. + poisson_ratio));
  }



  double
  Material::lambda(const unsigned int dim) const
  {
    const double nu        = poisson_ratio;
    const double lambda_3d = youngs_modulus * nu / ((1. + nu) * (1. - 2. * nu));
    if (dim == 2 && plane_model == PlaneModel::plane_stress)
      return 2. * lambda_3d * mu() / (lambda_3d + 2. * mu());
    return lambda_3d;
  }



  double
  Material::e_prime(const unsigned int dim) const
  {
    if (dim == 2 && plane_model == PlaneModel::plane_stress)
      return youngs_modulus;
    return youngs_modulus / (1. - poisson_ratio * poisson_ratio);
  }



  double
  Material::kappa(const unsigned int dim) const
  {
    const double nu = poisson_ratio;
    if (dim == 2 && plane_model == PlaneModel::plane_stress)
      return (3. - nu) / (1. + nu);
    return 3. - 4. * nu;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Material::stress(const SymmetricTensor<2, dim> &strain) const
  {
    return lambda(dim) * trace(strain) * unit_symmetric_tensor<dim>() +
           2. * mu() * strain;
  }



  template <int dim>
  double
  Material::von_mises(const SymmetricTensor<2, dim> &stress) const
  {
    double szz = 0;
    if (dim == 2 && plane_model == PlaneModel::plane_strain)
      szz = poisson_ratio * trace(stress);
    // Embed in 3D so that one formula serves 2D and 3D.
    SymmetricTensor<2, 3> s;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        s[i][j] = stress[i][j];
    if (dim == 2)
      s[2][2] = szz;
    return std::sqrt(1.5 * deviator(s) * deviator(s));
  }



  FunctionConstants
  Material::constants(const unsigned int dim) const
  {
    return {{"E", youngs_modulus},
            {"nu", poisson_ratio},
            {"mu", mu()},
            {"lambda", lambda(dim)}};
  }



  template SymmetricTensor<2, 2>
  Material::stress(const SymmetricTensor<2, 2> &) const;
  template SymmetricTensor<2, 3>
  Material::stress(const SymmetricTensor<2, 3> &) const;
  template double
  Material::von_mises(const SymmetricTensor<2, 2> &) const;
  template double
  Material::von_mises(const SymmetricTensor<2, 3> &) const;
} // namespace xcrack
