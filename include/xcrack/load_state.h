#ifndef xcrack_load_state_h
#define xcrack_load_state_h

#include <deal.II/base/function.h>

#include <deal.II/lac/vector.h>

#include <xcrack/boundary_conditions.h>

#include <memory>
#include <string>

namespace xcrack
{
  /**
   * One instant of a load cycle: the loads of a load set (the prescribed
   * displacements, tractions, body force and lip pressure of `Boundary
   * conditions`, or of another set such as `Propagation/Minimum loads`),
   * scaled by a factor. A fatigue step solves the maximum and, where it
   * cannot be had by linearity, the minimum of the cycle; the supports
   * (which boundaries and components are held, pinned points) are the same
   * in every state. Thermal loads, rotating loads and load spectra will be
   * more states of the same kind.
   */
  template <int dim>
  struct LoadState
  {
    /// For messages and files: "maximum", "minimum".
    std::string name = "maximum";
    /// The loads; never null once a state is in use.
    const BoundaryConditions<dim> *loads = nullptr;
    /// The loads are those of the set times this.
    double factor = 1;
  };



  /// @p function times a factor: a load of a LoadState where it is used
  /// as a Function (Dirichlet data, the lip term of the K extraction).
  template <int dim>
  class ScaledFunction : public Function<dim>
  {
  public:
    ScaledFunction(const Function<dim> &function, const double factor)
      : Function<dim>(function.n_components)
      , function(function)
      , factor(factor)
    {}

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override
    {
      return factor * function.value(p, component);
    }

    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override
    {
      function.vector_value(p, values);
      values *= factor;
    }

  private:
    const Function<dim> &function;
    const double         factor;
  };



  /**
   * @p function of @p state scaled by its factor, or @p function itself
   * (null: null) where the factor is 1.
   */
  template <int dim>
  std::shared_ptr<const Function<dim>>
  scaled(const Function<dim> *function, const LoadState<dim> &state)
  {
    if (!function)
      return nullptr;
    if (state.factor == 1)
      return std::shared_ptr<const Function<dim>>(function,
                                                  [](const Function<dim> *) {});
    return std::make_shared<ScaledFunction<dim>>(*function, state.factor);
  }
} // namespace xcrack

#endif
