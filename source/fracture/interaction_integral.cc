#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/crown.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/hanging_vertices.h>
#include <xcrack/fracture/integral_derivatives.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/input_error.h>
#include <xcrack/xfem/cell_quadrature.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace xcrack
{
  void
  FractureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture parameters");
    {
      prm.declare_entry("Compute",
                        "true",
                        Patterns::Bool(),
                        "Extract K_I, K_II (, K_III) and G at the crack "
                        "tips or along the fronts after each solve and "
                        "write front_<step>.csv.");
      prm.declare_entry(
        "Error estimate",
        "false",
        Patterns::Bool(),
        "Estimate the error of every K (K_exact - K, written as "
        "K_I_error, ... beside the K's): a goal-oriented estimate with "
        "recovered stresses on a crown as wide as the body allows, one "
        "dual solve per K mode and tip (3D: per test function of the "
        "smoothing basis) with the solver's factorization. See "
        "doc/verification.md for its effectivity and cost.");
      prm.declare_entry("Crown radii",
                        "2, 4",
                        Patterns::Anything(),
                        "r_inf, r_sup of the virtual extension q: 1 within "
                        "r_inf of the tip, 0 beyond r_sup, linear between.");
      prm.declare_entry("Crown unit",
                        "cells",
                        Patterns::Selection("cells|absolute"),
                        "cells: the radii are multiples of the size of the "
                        "cell holding the tip; absolute: lengths.");
      prm.declare_entry(
        "Crown weight",
        "linear",
        Patterns::Selection("linear|smooth"),
        "The virtual extension's q across the crown: linear in r, "
        "interpolated from the cells' vertices (the usual G-theta "
        "domain), or a smooth step of r (zero slope at both radii) "
        "evaluated at every quadrature point, whose K varies less from "
        "mesh to mesh where the crown's cells are graded (adaptive "
        "refinement); doc/verification.md.");
      prm.declare_entry("Reference K",
                        "",
                        Patterns::Anything(),
                        "Exact or handbook K at the front, 'K_I; K_II' (2D) "
                        "or 'K_I; K_II; K_III' (3D) as expressions of x, y[, "
                        "z] of the front point; the run prints the error "
                        "against them. Empty: none.");
      prm.declare_entry("Smoothing",
                        "legendre",
                        Patterns::Selection(
                          "legendre|lagrange|lagrange regularized"),
                        "3D: functions of s on which K(s), G(s) and the "
                        "virtual extensions are built: Legendre polynomials "
                        "(their periodic analogue, a Fourier series, on a "
                        "closed front), hats on the front segments, or "
                        "hats spanning four segments with K at a node the "
                        "weighted average over them.");
      prm.declare_entry("Legendre degree",
                        "5",
                        Patterns::Integer(0, 7),
                        "3D, Smoothing = legendre: highest degree.");
      prm.declare_entry("Front segments",
                        "0",
                        Patterns::Integer(0, 10000),
                        "3D: number of equal segments of a front (nodes of "
                        "the Lagrange bases, points where K is reported); "
                        "0: segments about r_sup long.");
    }
    prm.leave_subsection();
  }



  void
  FractureParameters::parse_parameters(ParameterHandler        &prm,
                                       const FunctionConstants &constants)
  {
    const std::string section = "Fracture parameters/";
    prm.enter_subsection("Fracture parameters");
    compute                              = prm.get_bool("Compute");
    error_estimate                       = prm.get_bool("Error estimate");
    const std::string         radii_text = prm.get("Crown radii");
    const std::vector<double> radii =
      parse_numbers(radii_text, 2, section + "Crown radii");
    crown_in_cells              = (prm.get("Crown unit") == "cells");
    smooth_weight               = (prm.get("Crown weight") == "smooth");
    const std::string reference = prm.get("Reference K");
    smoothing                   = FrontBasis::parse_type(prm.get("Smoothing"));
    legendre_degree             = prm.get_integer("Legendre degree");
    front_segments              = prm.get_integer("Front segments");
    prm.leave_subsection();

    crown_inner = radii[0];
    crown_outer = radii[1];
    check_input(crown_inner > 0 && crown_outer > crown_inner,
                section + "Crown radii = " + radii_text +
                  ": need 0 < r_inf < r_sup.");
    reference_2d.reset();
    reference_3d.reset();
    if (!Utilities::trim(reference).empty())
      {
        // The same text serves both dimensions: parse it for the one whose
        // component count matches.
        const unsigned int n = split_and_trim(reference, ';').size();
        check_input(n == 2 || n == 3,
                    section + "Reference K = " + reference +
                      ": give 'K_I; K_II' (2D) or 'K_I; K_II; K_III' (3D).");
        if (n == 2)
          reference_2d = std::make_shared<ParsedVectorFunction<2>>(
            reference, 2, constants, section + "Reference K");
        else
          reference_3d = std::make_shared<ParsedVectorFunction<3>>(
            reference, 3, constants, section + "Reference K");
      }
  }



  namespace
  {
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
      add_face_terms(
        const typename DoFHandler<dim>::active_cell_iterator  &cell,
        const CellTheta<dim>                                  &cell_theta,
        const unsigned int                                     first,
        const unsigned int                                     last,
        const unsigned int                                     face_no,
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



    template <int dim>
    void
    FrontIntegrals<dim>::add_domain_terms(const FEValues<dim>  &fe_values,
                                          const CellTheta<dim> &cell_theta,
                                          const unsigned int    first,
                                          const unsigned int    last,
                                          const Function<dim>  *body_force)
    {
      const std::vector<unsigned int> &active = cell_theta.active_tests();
      grad_u.resize(fe_values.n_quadrature_points);
      fe_values[displacement].get_function_gradients(solution, grad_u);
      Vector<double> f_value(dim);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          CrownPoint<dim> p(crown,
                            fe_values.get_quadrature().point(q),
                            fe_values.quadrature_point(q),
                            first,
                            last);
          p.du             = grad_u[q];
          const double JxW = fe_values.JxW(q);
          const auto   grad_N =
            CellTheta<dim>::shape_gradients(p.xi,
                                            fe_values.inverse_jacobian(q));
          for (const unsigned int j : active)
            {
              grad_theta[j] =
                cell_theta.gradient(p.xi, grad_N, p.projection, p.xl, p.r, j);
              theta[j] = cell_theta.value(p.xi, p.r, j);
            }

          Tensor<2, dim> du_aux[n_modes];
          aux_gradients<dim, n_modes>(
            unit, p.projection, p.xl, p.r, p.angle, du_aux);
          domain_term(p, du_aux, active, JxW);
          if (body_force != nullptr)
            {
              body_force->vector_value(p.x, f_value);
              Tensor<1, dim> f;
              for (unsigned int d = 0; d < dim; ++d)
                f[d] = f_value[d];
              body_force_term(p, f, du_aux, active, JxW);
            }
          if constexpr (dim == 3)
            divergence_term(p, active, JxW);
          if (d_b)
            d_b->flush_point(fe_values, q);
        }
    }



    template <int dim>
    void
    FrontIntegrals<dim>::domain_term(const CrownPoint<dim> &p,
                                     const Tensor<2, dim> (&du_aux)[n_modes],
                                     const std::vector<unsigned int> &active,
                                     const double                     JxW)
    {
      const Tensor<2, dim>         &du    = p.du;
      const SymmetricTensor<2, dim> eps   = symmetrize(du);
      const SymmetricTensor<2, dim> sigma = material.stress<dim>(eps);
      Tensor<2, dim>                T[n_integrals];
      for (unsigned int m = 0; m < n_modes; ++m)
        {
          const SymmetricTensor<2, dim> eps_aux = symmetrize(du_aux[m]);
          const SymmetricTensor<2, dim> sigma_aux =
            material.stress<dim>(eps_aux);
          T[m] = transpose(du_aux[m]) * Tensor<2, dim>(sigma) +
                 transpose(du) * Tensor<2, dim>(sigma_aux);
          const double w = sigma * eps_aux;
          for (unsigned int k = 0; k < dim; ++k)
            T[m][k][k] -= w;
        }
      T[n_modes] = transpose(du) * Tensor<2, dim>(sigma);
      for (unsigned int k = 0; k < dim; ++k)
        T[n_modes][k][k] -= 0.5 * (sigma * eps);
      for (const unsigned int j : active)
        for (unsigned int m = 0; m < n_integrals; ++m)
          b[j * n_integrals + m] += scalar_product(T[m], grad_theta[j]) * JxW;
      if (d_b)
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            const Tensor<2, dim> sigma_aux(
              material.stress<dim>(symmetrize(du_aux[m])));
            for (const unsigned int j : active)
              {
                const Tensor<2, dim> &Theta = grad_theta[j];
                const Tensor<2, dim>  A =
                  Tensor<2, dim>(
                    material.stress<dim>(symmetrize(du_aux[m] * Theta))) +
                  sigma_aux * transpose(Theta) - trace(Theta) * sigma_aux;
                d_b->add(j, m, A * JxW);
              }
          }
    }



    template <int dim>
    void
    FrontIntegrals<dim>::body_force_term(
      const CrownPoint<dim> &p,
      const Tensor<1, dim>  &f,
      const Tensor<2, dim> (&du_aux)[n_modes],
      const std::vector<unsigned int> &active,
      const double                     JxW)
    {
      for (const unsigned int j : active)
        {
          for (unsigned int m = 0; m < n_modes; ++m)
            b[j * n_integrals + m] -= (f * (du_aux[m] * theta[j])) * JxW;
          b[j * n_integrals + n_modes] -= (f * (p.du * theta[j])) * JxW;
        }
    }



    template <int dim>
    void
    FrontIntegrals<dim>::divergence_term(
      const CrownPoint<dim>           &p,
      const std::vector<unsigned int> &active,
      const double                     JxW)
    {
      if constexpr (dim == 3)
        {
          Tensor<1, dim> div_aux[n_modes];
          aux_stress_divergence<n_modes>(
            unit, crown.curve, p.x, p.projection, p.xl, p.angle, div_aux);
          for (const unsigned int j : active)
            {
              const Tensor<1, dim> du_theta = p.du * theta[j];
              for (unsigned int m = 0; m < n_modes; ++m)
                {
                  b[j * n_integrals + m] += (div_aux[m] * du_theta) * JxW;
                  if (d_b)
                    d_b->add(j, m, outer_product(div_aux[m], theta[j]) * JxW);
                }
            }
        }
      else
        (void)p, (void)active, (void)JxW;
    }



    template <int dim>
    void
    FrontIntegrals<dim>::add_lip_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const CellTheta<dim>                                 &cell_theta,
      const unsigned int                                    first,
      const unsigned int                                    last,
      const std::vector<Point<dim>>                        &points,
      const std::vector<double>                            &weights,
      const std::vector<Tensor<1, dim>>                    &normals,
      const Function<dim>                                  *lip_pressure,
      const typename InteractionIntegral<dim>::LipTraction &lip_traction)
    {
      // With a traction t on the lsn > 0 lip and -t on the other (a
      // pressure: t = p n; contact): - int t_i [u_i,k] theta_k. Along a
      // curved 3D front the auxiliary fields load the lips too: their hoop
      // strain u_1 / rho is not zero on the lips in mode II, so sigma^aux .
      // n is not, and + int (sigma^aux n . u_,k theta_k) [+ lip] - (the
      // same) [- lip] completes the identity (it vanishes for straight
      // fronts and in mode I).
      const std::vector<unsigned int> &active = cell_theta.active_tests();
      const std::vector<Point<dim>>    sides =
        CellQuadrature::both_sides(points, normals);
      FEValues<dim> side_values(mapping,
                                cell->get_fe(),
                                Quadrature<dim>(sides),
                                update_gradients | update_jacobians |
                                  update_quadrature_points);
      side_values.reinit(cell);
      grad_u.resize(sides.size());
      side_values[displacement].get_function_gradients(solution, grad_u);
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          // n ds, to the lsn > 0 lip.
          const Tensor<1, dim> n_ds =
            CellQuadrature::mapped_normal<dim>(side_values.jacobian(2 * k),
                                               normals[k],
                                               weights[k]);
          const CrownPoint<dim> p(
            crown, points[k], side_values.quadrature_point(2 * k), first, last);
          // t ds on the lsn > 0 lip.
          Tensor<1, dim> t_ds =
            (lip_pressure ? lip_pressure->value(p.x) : 0.) * n_ds;
          if (lip_traction)
            t_ds += n_ds.norm() * lip_traction(cell, k);
          // The lsn > 0 lip lies at angle pi in the front frame if e2
          // points to it, else at -pi (the start tip of a segment).
          const double angle_plus =
            ((p.projection.R * n_ds)[1] > 0 ? 1. : -1.) * numbers::PI;
          Tensor<2, dim> plus[n_modes], minus[n_modes];
          aux_gradients<dim, n_modes>(
            unit, p.projection, p.xl, p.r, angle_plus, plus);
          aux_gradients<dim, n_modes>(
            unit, p.projection, p.xl, p.r, -angle_plus, minus);
          Tensor<2, dim> jump[n_integrals];
          for (unsigned int m = 0; m < n_modes; ++m)
            jump[m] = plus[m] - minus[m];
          jump[n_modes] = grad_u[2 * k] - grad_u[2 * k + 1];
          for (const unsigned int j : active)
            theta[j] = cell_theta.value(p.xi, p.r, j);
          for (const unsigned int j : active)
            for (unsigned int m = 0; m < n_integrals; ++m)
              b[j * n_integrals + m] -= t_ds * (jump[m] * theta[j]);
          if constexpr (dim == 3)
            {
              Tensor<1, dim> t_plus[n_modes], t_minus[n_modes];
              for (unsigned int m = 0; m < n_modes; ++m)
                {
                  t_plus[m] = material.stress<dim>(symmetrize(plus[m])) * n_ds;
                  t_minus[m] =
                    material.stress<dim>(symmetrize(minus[m])) * n_ds;
                }
              for (const unsigned int j : active)
                for (unsigned int m = 0; m < n_modes; ++m)
                  b[j * n_integrals + m] +=
                    t_plus[m] * (grad_u[2 * k] * theta[j]) -
                    t_minus[m] * (grad_u[2 * k + 1] * theta[j]);
              // The derivatives, one side after the other.
              if (d_b)
                for (const unsigned int side : {0u, 1u})
                  {
                    for (const unsigned int j : active)
                      for (unsigned int m = 0; m < n_modes; ++m)
                        d_b->add(j,
                                 m,
                                 side == 0 ?
                                   outer_product(t_plus[m], theta[j]) :
                                   -outer_product(t_minus[m], theta[j]));
                    d_b->flush_point(side_values, 2 * k + side);
                  }
            }
        }
    }



    template <int dim>
    void
    FrontIntegrals<dim>::add_face_terms(
      const typename DoFHandler<dim>::active_cell_iterator  &cell,
      const CellTheta<dim>                                  &cell_theta,
      const unsigned int                                     first,
      const unsigned int                                     last,
      const unsigned int                                     face_no,
      const typename InteractionIntegral<dim>::BoundaryFace &face)
    {
      // With t the face's traction and n its outward normal (theta . n =
      // 0): - t . (grad u^aux theta) - sigma^aux n . (grad u theta) for the
      // modes, - t . (grad u theta) for G.
      const Quadrature<dim> &rule = face.rule;
      if (rule.size() == 0)
        return;
      const std::vector<unsigned int> &active = cell_theta.active_tests();
      FEValues<dim>                    values(mapping,
                           cell->get_fe(),
                           rule,
                           update_gradients | update_jacobians |
                             update_quadrature_points);
      values.reinit(cell);
      grad_u.resize(rule.size());
      values[displacement].get_function_gradients(solution, grad_u);
      const Tensor<1, dim> normal =
        GeometryInfo<dim>::unit_normal_vector[face_no];
      Vector<double> traction(dim);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          // n dA, outward.
          const Tensor<1, dim> n_dA =
            CellQuadrature::mapped_normal<dim>(values.jacobian(q),
                                               normal,
                                               rule.weight(q));
          CrownPoint<dim> p(
            crown, rule.point(q), values.quadrature_point(q), first, last);
          p.du = grad_u[q];
          Tensor<1, dim> t_dA;
          if (face.traction)
            {
              face.traction->vector_value(p.x, traction);
              for (unsigned int d = 0; d < dim; ++d)
                t_dA[d] = traction[d] * n_dA.norm();
            }
          Tensor<2, dim> du_aux[n_modes];
          aux_gradients<dim, n_modes>(
            unit, p.projection, p.xl, p.r, p.angle, du_aux);
          Tensor<1, dim> aux_traction[n_modes];
          for (unsigned int m = 0; m < n_modes; ++m)
            aux_traction[m] =
              material.stress<dim>(symmetrize(du_aux[m])) * n_dA;
          for (const unsigned int j : active)
            {
              const Tensor<1, dim> theta_j  = cell_theta.value(p.xi, p.r, j);
              const Tensor<1, dim> du_theta = p.du * theta_j;
              for (unsigned int m = 0; m < n_modes; ++m)
                {
                  b[j * n_integrals + m] -=
                    t_dA * (du_aux[m] * theta_j) + aux_traction[m] * du_theta;
                  if (d_b)
                    d_b->add(j, m, -outer_product(aux_traction[m], theta_j));
                }
              b[j * n_integrals + n_modes] -= t_dA * du_theta;
            }
          if (d_b)
            d_b->flush_point(values, q);
        }
    }



    /// E* of the interaction integral's relation: E / (1 - nu^2) (3D,
    /// plane strain) or E (plane stress).
    template <int dim>
    double
    effective_modulus(const Material &material)
    {
      const double nu = material.poisson_ratio;
      return (dim == 2 &&
                  material.plane_model == Material::PlaneModel::plane_stress ?
                material.youngs_modulus :
                material.youngs_modulus / (1 - nu * nu));
    }



    /// The derivatives of @p d_b, per test function of @p basis and scaled
    /// as the K's, into @p derivatives with the weights that take them to
    /// the basis nodes (the map the b_j take to the K's).
    template <int dim>
    void
    store_derivatives(const FrontBasis         &basis,
                      const Material           &material,
                      IntegralDerivatives<dim> &d_b,
                      KDerivatives             &derivatives)
    {
      constexpr unsigned int           n_modes = FrontIntegrals<dim>::n_modes;
      const unsigned int               n_test  = basis.n_test_functions();
      std::vector<std::vector<double>> to_nodes(n_test);
      for (unsigned int j = 0; j < n_test; ++j)
        {
          std::vector<double> unit_b(n_test, 0.);
          unit_b[j]   = 1;
          to_nodes[j] = basis.values_at_nodes(unit_b);
        }
      const unsigned int first_test = derivatives.test_loads.size();
      for (unsigned int j = 0; j < n_test; ++j)
        {
          std::vector<TrilinosWrappers::MPI::Vector> loads;
          for (unsigned int m = 0; m < n_modes; ++m)
            loads.push_back(
              d_b.scaled(j,
                         m,
                         m < 2 ? 0.5 * effective_modulus<dim>(material) :
                                 material.mu()));
          derivatives.test_loads.push_back(std::move(loads));
        }
      for (unsigned int k = 0; k < basis.nodes().size(); ++k)
        {
          std::vector<std::pair<unsigned int, double>> weights;
          for (unsigned int j = 0; j < n_test; ++j)
            if (to_nodes[j][k] != 0)
              weights.emplace_back(first_test + j, to_nodes[j][k]);
          derivatives.node_weights.push_back(std::move(weights));
        }
    }



    /// K and G at the nodes of @p crown's basis from the integrals @p b
    /// (b_jm at j * n_integrals + m): I_m = 2/E* K_m (modes I, II),
    /// K_III / mu (mode III).
    template <int dim>
    std::vector<FrontValues<dim>>
    nodal_values(const Crown<dim>          &crown,
                 const std::vector<double> &b,
                 const Material            &material)
    {
      constexpr unsigned int n_modes     = FrontIntegrals<dim>::n_modes;
      constexpr unsigned int n_integrals = FrontIntegrals<dim>::n_integrals;
      const unsigned int     n_test      = crown.basis.n_test_functions();
      const double           e_star      = effective_modulus<dim>(material);
      std::vector<std::vector<double>> nodal(n_integrals);
      for (unsigned int m = 0; m < n_integrals; ++m)
        {
          std::vector<double> b_m(n_test);
          for (unsigned int j = 0; j < n_test; ++j)
            b_m[j] = b[j * n_integrals + m];
          nodal[m] = crown.basis.values_at_nodes(b_m);
        }
      std::vector<FrontValues<dim>> result;
      for (unsigned int k = 0; k < crown.basis.nodes().size(); ++k)
        {
          FrontValues<dim> values;
          values.basis = crown.basis.description();
          values.point = crown.curve.at(crown.basis.nodes()[k]);
          values.k_I   = 0.5 * e_star * nodal[0][k];
          values.k_II  = 0.5 * e_star * nodal[1][k];
          if (dim == 3)
            values.k_III = material.mu() * nodal[n_modes - 1][k];
          values.g = nodal[n_modes][k];
          values.g_irwin =
            (values.k_I * values.k_I + values.k_II * values.k_II) / e_star +
            values.k_III * values.k_III / (2 * material.mu());
          values.r_inf = crown.r_inf;
          values.r_sup = crown.r_sup;
          result.push_back(values);
        }
      return result;
    }



    /// The error thrown when a crown holds no vertex of the mesh.
    template <int dim>
    InputError
    empty_crown(const Point<dim>  &first_point,
                const unsigned int f,
                const double       r_sup)
    {
      std::ostringstream message;
      message << "Fracture parameters/Crown radii: the crown of "
              << (dim == 2 ? "tip " : "front ") << f + 1 << " at ("
              << first_point << ") (r_sup = " << r_sup
              << ") holds no vertex of the mesh, so K and G would be 0 "
                 "there; use radii of at least a cell there, or Crown "
                 "unit = cells.";
      return InputError(message.str());
    }
  } // namespace



  template <int dim>
  InteractionIntegral<dim>::InteractionIntegral(
    const FractureParameters &parameters,
    const Material           &material)
    : parameters(parameters)
    , material(material)
  {}



  template <int dim>
  std::vector<FrontValues<dim>>
  InteractionIntegral<dim>::compute(
    const DoFHandler<dim>                           &dof_handler,
    const TrilinosWrappers::MPI::Vector             &solution,
    const std::vector<std::vector<FrontPoint<dim>>> &fronts,
    const FEValuesOf                                &fe_values_of,
    const Function<dim>                             *lip_pressure,
    const LipsOf                                    &lips_of,
    const Function<dim>                             *body_force,
    KDerivatives                                    *derivatives,
    const LipTraction                               &lip_traction,
    const BoundaryFaceOf                            &boundary_face_of) const
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    constexpr unsigned int n_modes = FrontIntegrals<dim>::n_modes;
    // Auxiliary fields: unit K_I, K_II (, K_III).
    WilliamsField unit;
    unit.mu    = material.mu();
    unit.kappa = material.kappa(dim);

    // Only the linear weight is interpolated from the vertices.
    std::optional<HangingVertices<dim>> hanging;
    if (!parameters.smooth_weight)
      hanging.emplace(dof_handler.get_triangulation());

    std::vector<FrontValues<dim>> result;
    for (unsigned int f = 0; f < fronts.size(); ++f)
      {
        const Crown<dim>   crown(parameters, dof_handler, fronts, f);
        const unsigned int n_test = crown.basis.n_test_functions();
        std::optional<IntegralDerivatives<dim>> d_b;
        if (derivatives)
          d_b.emplace(dof_handler.locally_owned_dofs(), comm, n_test, n_modes);
        FrontIntegrals<dim> integrals(
          material, unit, crown, solution, d_b ? &*d_b : nullptr);
        CellTheta<dim> theta(crown, hanging ? &*hanging : nullptr);

        // Whether the crown is cut by the boundary, and whether it holds a
        // vertex of the mesh at all (with crowns smaller than the cells, q
        // vanishes at every vertex, and so do K and G).
        bool on_boundary = false;
        bool sees_crown  = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            const auto segments = crown.segments_near(cell);
            if (!segments)
              continue;
            const auto [first, last] = *segments;
            if (!theta.reinit(cell, first, last))
              continue;
            sees_crown = true;
            if (derivatives)
              d_b->reinit(cell, theta.active_tests());

            // Domain terms: where theta varies (2D: where q does), and
            // wherever theta is not zero under a body force.
            if (dim == 3 || theta.varies() || body_force != nullptr)
              integrals.add_domain_terms(
                fe_values_of(cell), theta, first, last, body_force);
            if (derivatives)
              d_b->flush_cell(*derivatives->constraints);

            // The body's faces the crown crosses: free and loaded ones add
            // their term; the others make the K's unreliable, except where
            // the front ends on them (as in a plane-strain slice).
            if (cell->at_boundary())
              for (const unsigned int face : cell->face_indices())
                if (cell->face(face)->at_boundary() &&
                    theta.reaches(cell, face, true))
                  {
                    BoundaryFace boundary_face;
                    boundary_face.constrained = true;
                    if (dim == 3 && boundary_face_of)
                      boundary_face = boundary_face_of(cell, face);
                    if (boundary_face.constrained)
                      on_boundary =
                        on_boundary || theta.reaches(cell, face, false);
                    else
                      {
                        integrals.add_face_terms(
                          cell, theta, first, last, face, boundary_face);
                        if (derivatives)
                          d_b->flush_cell(*derivatives->constraints);
                      }
                  }

            if (lip_pressure == nullptr && !lip_traction && dim == 2)
              continue;
            std::vector<Point<dim>>     points;
            std::vector<double>         weights;
            std::vector<Tensor<1, dim>> normals;
            lips_of(cell, points, weights, normals);
            if (points.empty())
              continue;
            integrals.add_lip_terms(cell,
                                    theta,
                                    first,
                                    last,
                                    points,
                                    weights,
                                    normals,
                                    lip_pressure,
                                    lip_traction);
            if (derivatives)
              d_b->flush_cell(*derivatives->constraints);
          }

        std::vector<double> b(integrals.b.size());
        Utilities::MPI::sum(ArrayView<const double>(integrals.b),
                            comm,
                            ArrayView<double>(b));
        const bool clear = crown.clear_of_other_fronts &&
                           !Utilities::MPI::logical_or(on_boundary, comm);
        if (!Utilities::MPI::logical_or(sees_crown, comm))
          throw empty_crown(fronts[f][0].position, f, crown.r_sup);

        if (derivatives)
          store_derivatives(crown.basis, material, *d_b, *derivatives);
        for (FrontValues<dim> &values : nodal_values(crown, b, material))
          {
            values.front       = f;
            values.crown_clear = clear;
            result.push_back(values);
          }
      }
    return result;
  }



  template class InteractionIntegral<2>;
  template class InteractionIntegral<3>;
} // namespace xcrack
