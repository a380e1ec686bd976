#ifndef xcrack_growth_law_interface_h
#define xcrack_growth_law_interface_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/plugins.h>

#include <memory>
#include <string>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * How fast a front point advances (`subsection Propagation/Growth law`,
   * `Model name`): the crack growth rate da/dN as a function of the
   * equivalent stress intensity range Delta K, its maximum K_max and the
   * load ratio R = K_min / K_max of the load cycle. Propagation picks the
   * cycle increment so that the fastest point of all fronts advances
   * `Maximum advance`, and integrates the cycles between two steps.
   */
  namespace GrowthLaw
  {
    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      /**
       * da/dN (length per cycle, in the units of the mesh and of K) at a
       * point with @p delta_k, @p k_max under load ratio @p load_ratio:
       * zero at or below a threshold, infinite where the law predicts
       * fracture within the cycle.
       */
      virtual double
      rate(const double delta_k,
           const double k_max,
           const double load_ratio) const = 0;

      /**
       * Why rate() gave a value that is not finite for these arguments,
       * for the message that ends the run (it names the point and its K's).
       */
      virtual std::string
      why_no_rate(const double delta_k,
                  const double k_max,
                  const double load_ratio) const;

      /**
       * Whether rate() is a rate per load cycle. A quasi-static law returns
       * relative speeds instead: the front advances in their proportion and
       * no cycles are counted; its K's are given relative to the step's
       * largest K_eq (1 at the most loaded point), so that a steep law does
       * not underflow at every point.
       */
      virtual bool
      counts_cycles() const
      {
        return true;
      }
    };



    /**
     * The constants the power laws share: the coefficient C, the exponent
     * m and the threshold Delta K_th, declared in the law's own subsection
     * and checked there (C > 0, m > 0), with messages that name the law.
     */
    struct PowerLawConstants
    {
      /// Declare C (default @p default_c, in @p c_units), m and Threshold in
      /// the current subsection.
      static void
      declare_parameters(ParameterHandler  &prm,
                         const std::string &default_c,
                         const std::string &c_units);

      /// Read them in the current subsection, the one of the law @p law.
      void
      parse_parameters(ParameterHandler &prm, const std::string &law);

      double c = 1e-11, m = 3, threshold = 0;
    };



    /// Declare `Model name` and every law's entries (in the current
    /// subsection).
    void
    declare_parameters(ParameterHandler &prm);

    /// The law `Model name` selects (in the current subsection).
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace GrowthLaw
} // namespace xcrack

#endif
