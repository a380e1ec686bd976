#ifndef xcrack_load_cycle_h
#define xcrack_load_cycle_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/load_state.h>

namespace xcrack
{
  /**
   * The load cycle of a fatigue run (entries of `subsection Propagation`):
   * its maximum, the loads of `Boundary conditions`, and its minimum,
   * either those loads times `Load ratio` R (proportional loading) or a
   * load set of its own (`subsection Minimum loads`: a pressure that stays
   * while a tension comes and goes, say).
   *
   * A step solves the maximum, and the minimum unless linearity gives it:
   * a proportional minimum of a linear problem (no contact) has K_min = R
   * K_max at no cost. Every other minimum (a load set of its own; lips in
   * contact, whose closure makes K a nonlinear function of the load) is
   * solved and its K extracted like the maximum's, and Delta K comes from
   * the two states.
   */
  template <int dim>
  class LoadCycle
  {
  public:
    /// Declare `Load ratio` and `subsection Minimum loads` (in the current
    /// subsection, Propagation).
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Parse them (in subsection Propagation), the maximum being
     * @p maximum; throws InputError naming the entry.
     */
    void
    parse_parameters(ParameterHandler              &prm,
                     const BoundaryConditions<dim> &maximum,
                     const FunctionConstants       &constants);

    const LoadState<dim> &
    maximum() const;

    const LoadState<dim> &
    minimum() const;

    /// Whether the minimum is the maximum's loads times R.
    bool
    proportional() const;

    /// R of a proportional cycle (0 with a load set of its own).
    double
    load_ratio() const;

    /// The load set of the minimum (empty() if the cycle is proportional).
    const BoundaryConditions<dim> &
    minimum_loads() const;

  private:
    double                  ratio = 0;
    BoundaryConditions<dim> own_minimum;
    LoadState<dim>          maximum_state, minimum_state;
  };
} // namespace xcrack

#endif
