#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/auxiliary_fields.h>
#include <xcrack/fracture/crown.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/front_integrals.h>
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
