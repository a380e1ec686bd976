#include <xcrack/input_error.h>
#include <xcrack/load_cycle.h>

namespace xcrack
{
  template <int dim>
  void
  LoadCycle<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Load ratio",
                      "0",
                      Patterns::Double(),
                      "R = K_min / K_max of the load cycle (< 1): the loads "
                      "at the minimum are those of Boundary conditions times "
                      "R. A negative R compresses: without contact a closed "
                      "crack carries no K_I, so Delta K_I = K_I,max. Leave "
                      "it at 0 when subsection Minimum loads gives the "
                      "minimum.");
    prm.enter_subsection("Minimum loads");
    {
      BoundaryConditions<dim>::declare_load_set(prm);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  LoadCycle<dim>::parse_parameters(ParameterHandler              &prm,
                                   const BoundaryConditions<dim> &maximum,
                                   const FunctionConstants       &constants)
  {
    ratio = prm.get_double("Load ratio");
    check_input(ratio < 1,
                "Propagation/Load ratio = " + prm.get("Load ratio") +
                  ": must be below 1 (R = K_min / K_max).");
    prm.enter_subsection("Minimum loads");
    try
      {
        own_minimum.parse_load_set(prm,
                                   "Propagation/Minimum loads",
                                   maximum,
                                   constants);
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
    check_input(own_minimum.empty() || ratio == 0,
                "Propagation/Load ratio = " + prm.get("Load ratio") +
                  " and Propagation/Minimum loads both give the minimum of "
                  "the load cycle: give one of them.");
    maximum_state = {"maximum", &maximum, 1.};
    minimum_state =
      (own_minimum.empty() ? LoadState<dim>{"minimum", &maximum, ratio} :
                             LoadState<dim>{"minimum", &own_minimum, 1.});
  }



  template <int dim>
  const LoadState<dim> &
  LoadCycle<dim>::maximum() const
  {
    return maximum_state;
  }



  template <int dim>
  const LoadState<dim> &
  LoadCycle<dim>::minimum() const
  {
    return minimum_state;
  }



  template <int dim>
  bool
  LoadCycle<dim>::proportional() const
  {
    return own_minimum.empty();
  }



  template <int dim>
  double
  LoadCycle<dim>::load_ratio() const
  {
    return (proportional() ? ratio : 0.);
  }



  template <int dim>
  const BoundaryConditions<dim> &
  LoadCycle<dim>::minimum_loads() const
  {
    return own_minimum;
  }



  template class LoadCycle<2>;
  template class LoadCycle<3>;
} // namespace xcrack
