#ifndef xcrack_direction_criterion_interface_h
#define xcrack_direction_criterion_interface_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/plugins.h>

#include <memory>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * Where a front point goes (`subsection Propagation/Direction
   * criterion`, `Model name`): the kink angle of a mixed-mode crack tip
   * and the equivalent mode-I stress intensity factor the criterion
   * assigns to it, from K_I and K_II at that point (2D tips and every point
   * of a 3D front alike, in its plane (e1, e2)). Mode III does not turn
   * the front (no twist); Propagation decides whether K_III adds to the
   * equivalent K.
   */
  namespace DirectionCriterion
  {
    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      /**
       * The kink angle (radians, from e1 towards e2: K_II > 0 gives a
       * negative angle, doc/benchmarks.md Case 10) of a tip with @p k_I >= 0
       * and @p k_II.
       */
      virtual double
      kink_angle(const double k_I, const double k_II) const = 0;

      /// The criterion's equivalent mode-I K of that tip (= k_I without
      /// k_II).
      virtual double
      equivalent_k(const double k_I, const double k_II) const = 0;
    };



    /// Declare `Model name` and every criterion's entries (in the current
    /// subsection).
    void
    declare_parameters(ParameterHandler &prm);

    /// The criterion `Model name` selects (in the current subsection).
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace DirectionCriterion
} // namespace xcrack

#endif
