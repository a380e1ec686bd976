#ifndef xcrack_contact_interface_h
#define xcrack_contact_interface_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/cell_id.h>

#include <xcrack/assembly/interface.h>
#include <xcrack/plugins.h>

#include <map>
#include <memory>
#include <string>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * Crack lips that touch (`subsection Contact`, `Formulation`): under
   * compression, bending that reverses or a negative load ratio the lips of
   * a real crack close and press on each other, where without contact the
   * enriched displacement lets them pass through each other. A formulation
   * is a contribution to the system (Assembly::Contribution) on the lips,
   * nonlinear (which points are closed depends on the solution: the
   * Newton loop of NonlinearSolver finds them), and keeps the statuses
   * and the tractions of its lip points between the assemblies of a solve.
   *
   * Unilateral contact in small sliding: at a point of the lips (lsn = 0,
   * lst < 0) the gap is g = n . [[u]], n the normal to the lsn > 0 lip,
   * [[u]] the jump of the displacement across the crack (the lips coincide
   * before the load: the initial gap is zero); the lips must not
   * interpenetrate, g >= 0, and press on each other only where they touch:
   * p >= 0, p g = 0. With Coulomb friction (`Friction coefficient` mu > 0)
   * closed lips also resist their slip s = P_T [[u]] (P_T the projection on
   * the crack's tangent plane): they stick while the tangential traction
   * |t_T| < mu p, and slip against it with |t_T| = mu p. Each load state is
   * reached from the unloaded body along a proportional path, in one
   * increment: the slip is measured from the lips' position before the load
   * (exact for proportional monotonic loading, as in the closed-form
   * benchmarks; a load history within the cycle is not followed).
   */
  namespace Contact
  {
    template <int dim>
    class Interface : public Plugins::InterfaceBase,
                      public Assembly::Contribution<dim>
    {
    public:
      /**
       * The traction the lsn < 0 lip exerts on the lsn > 0 one at lip point
       * @p q of the cell @p cell (force per area: p n for a contact pressure
       * p), as of the last assembly; zero where the lips are open. The K
       * extraction's lip term and the output read it.
       */
      virtual Tensor<1, dim>
      lip_traction(const CellId &cell, const unsigned int q) const = 0;

      /// What the last assembly found on the lips of one cell, as means
      /// over them weighted by their length (area).
      struct LipState
      {
        /// The contact pressure, and the gap the formulation holds (the
        /// mean of the cell's, or of its points').
        double pressure = 0, gap = 0;
        /// The traction on the lsn > 0 lip (p n plus friction's).
        Tensor<1, dim> traction;
        /// The fractions of the cell's lips that are closed, and slip.
        double closed = 0, slipping = 0;
      };

      /// The state of the lips of the locally owned @p cell (zeros where it
      /// has none), for the crack's VTU.
      virtual LipState
      lip_state(const CellId &cell) const = 0;

      /**
       * The fraction of the lips within @p radius of @p x (a front point)
       * that the last assembly found closed, over all ranks (collective; 0
       * if no lip is that near).
       */
      virtual double
      closed_fraction(const Point<dim> &x, const double radius) const = 0;

      /**
       * What the last assembly found, over all ranks (collective), for
       * statistics.csv: `contact_closed`, the fraction of the lips' length
       * (area) that is closed, with friction `contact_slipping`, the
       * fraction of the closed lips that slip, and `contact_pressure_min`,
       * `contact_pressure_max`, the smallest and largest contact pressure
       * where they are (a uniform pressure that these show spread out
       * oscillates: the pressure space is not stable there), and
       * `contact_gap_min`, the most negative gap held where closed (the
       * interpenetration; 0 if none).
       */
      virtual std::map<std::string, double>
      statistics() const = 0;

      bool
      is_linear() const override
      {
        return false;
      }

      /// Friction's tangent at a slipping point is not symmetric.
      bool
      is_symmetric() const override
      {
        return friction == 0;
      }

      /// Coulomb's mu on the lips (0: frictionless); set by create().
      double friction = 0;
    };



    /// Declare `Formulation` and every formulation's entries (in the current
    /// subsection).
    void
    declare_parameters(ParameterHandler &prm);

    /// The formulation `Formulation` selects (in the current subsection);
    /// null for `none`.
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace Contact
} // namespace xcrack

#endif
