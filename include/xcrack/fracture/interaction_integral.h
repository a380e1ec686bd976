#ifndef xcrack_fracture_interaction_integral_h
#define xcrack_fracture_interaction_integral_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/material.h>
#include <xcrack/parsed_function.h>

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
   */
  struct FractureParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse; throws InputError naming the entry.
    void
    parse_parameters(ParameterHandler &prm, const FunctionConstants &constants);

    bool   compute        = true;
    double crown_inner    = 2;
    double crown_outer    = 4;
    bool   crown_in_cells = true;
    /// K_I; K_II (2D) or K_I; K_II; K_III (3D); null if not given.
    std::shared_ptr<Function<2>> reference_2d;
    std::shared_ptr<Function<3>> reference_3d;
  };



  /// K, G at one front point.
  template <int dim>
  struct FrontValues
  {
    FrontPoint<dim> point;
    double          k_I = 0, k_II = 0, k_III = 0;
    /// G from the domain form of the J integral (G-theta).
    double g = 0;
    /// G from the K's by Irwin's relation.
    double g_irwin = 0;
    /// The crown radii used.
    double r_inf = 0, r_sup = 0;
    /**
     * Whether the crown stays clear of the body's boundary and of the other
     * tips: the domain form assumes q = 0 on the boundary and a single
     * singularity inside; if not, K is unreliable.
     */
    bool crown_clear = true;
  };



  /**
   * Stress intensity factors by the interaction integral (Yau, Wang and
   * Corten; domain form of Moës, Dolbow and Belytschko 1999) and G by the
   * domain J integral, at the tips of a 2D crack:
   *
   *   I = int_A (sigma_ij du^aux_i/dx_1 + sigma^aux_ij du_i/dx_1
   *              - sigma_ik eps^aux_ik delta_1j) dq/dx_j dA
   *       - int_lips q t_i [du^aux_i/dx_1]
   *
   * in the tip frame (x_1 along e1, x_2 along e2), with the Williams fields
   * of K^aux_I = 1 (then K_I = E* I / 2) and of K^aux_II = 1 (K_II), E* =
   * E / (1 - nu^2) in plane strain, E in plane stress; the lip term is
   * there when the lips carry a pressure. The domain terms are integrated
   * with the cell's X-FEM rule (cut and tip rules where the crack is), as
   * the solution's jumps and singular gradients require.
   *
   * 3D (with smoothing of K(s) along the front) is not implemented yet.
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

    InteractionIntegral(const FractureParameters &parameters,
                        const Material           &material);

    /**
     * K and G at each of @p tips (the tips of a 2D crack, frames of
     * BENCHMARKS.md) from the ghosted @p solution on @p dof_handler.
     * @p lip_pressure may be null. Collective.
     */
    std::vector<FrontValues<dim>>
    compute(const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &solution,
            const std::vector<FrontPoint<dim>>  &tips,
            const FEValuesOf                    &fe_values_of,
            const Function<dim>                 *lip_pressure,
            const LipsOf                        &lips_of) const;

  private:
    const FractureParameters &parameters;
    const Material           &material;
  };
} // namespace xcrack

#endif
