#ifndef xcrack_assembly_interface_h
#define xcrack_assembly_interface_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <xcrack/load_state.h>

#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The system of a load state is assembled as a sum of contributions, one
   * per term of the weak form (the bulk's elasticity, boundary tractions,
   * the body force, a pressure on the lips; contact on the lips, cohesion
   * later), as ASPECT assembles each equation from a list of assemblers.
   * Each contribution adds, cell by cell, to the linearised system at the
   * current iterate u_k:
   *
   *     A(u_k) u_{k+1} = b(u_k),
   *
   * the Newton step written for the next iterate itself rather than for
   * its increment (as deal.II's step-41 and step-42 write the active-set
   * and semi-smooth Newton steps of contact), so that inhomogeneous
   * Dirichlet data and hanging nodes are condensed alike in every step. A
   * linear term adds the same A and b whatever u_k: a scene of linear
   * terms only is solved by one step, and costs what a plain linear solve
   * costs. The residual of u_k is b(u_k) - A(u_k) u_k.
   */
  namespace Assembly
  {
    /// What a contribution sees of one cell.
    template <int dim>
    struct CellInput
    {
      typename DoFHandler<dim>::active_cell_iterator cell;
      /// Reinitialised on the cell with its X-FEM rule (cut and tip rules
      /// where the crack is), with the update flags the contributions asked
      /// for.
      const FEValues<dim> *fe_values = nullptr;
      /// The current iterate's values at the cell's DoFs; empty for the
      /// first step of a solve (the iterate is zero and linear terms need
      /// not read it).
      const Vector<double> *iterate = nullptr;
      const LoadState<dim> *state   = nullptr;
    };



    template <int dim>
    class Contribution
    {
    public:
      virtual ~Contribution() = default;

      /**
       * Called before each assembly of a system; @p first: the first of a
       * solve (the iterate is zero), where statuses from an earlier solve
       * no longer apply.
       */
      virtual void
      start_assembly(const bool /*first*/)
      {}

      /// What the contribution reads of the cell's FEValues.
      virtual UpdateFlags
      update_flags() const
      {
        return update_default;
      }

      /**
       * Add the cell's share of A(u_k) to @p matrix and of b(u_k) to
       * @p rhs (both sized to the cell's DoFs). Data that is not finite
       * where it is used is not thrown at once (every rank must reach the
       * collective check after the loop): its description goes to
       * @p culprit if that is still empty.
       */
      virtual void
      assemble(const CellInput<dim> &input,
               FullMatrix<double>   &matrix,
               Vector<double>       &rhs,
               std::string          &culprit) = 0;

      /// Whether A and b do not depend on the iterate.
      virtual bool
      is_linear() const
      {
        return true;
      }

      /// Whether its share of A is symmetric.
      virtual bool
      is_symmetric() const
      {
        return true;
      }

      /**
       * The statuses (a lip point open or closed, sticking or slipping) of
       * this rank's cells that the last assembly changed from those the
       * current iterate was solved with: their number, and where the first
       * is, for a message. A linear term has none.
       */
      virtual std::pair<unsigned int, std::string>
      changed_statuses() const
      {
        return {0, ""};
      }

      /**
       * @name Unknowns of its own
       *
       * A contribution may bring unknowns beyond the displacement's (the
       * Lagrange multipliers of contact on the lips): the system is then
       * [displacement DoFs, own unknowns], a saddle point. They are numbered
       * 0 .. n_own_unknowns() - 1 over all ranks; each rank owns the range
       * owned_own_unknowns() (the ranges of the ranks are disjoint and
       * cover them all). The simulator asks for them again after each
       * set-up of the space.
       */
      /// @{
      /// Whether it brings unknowns of its own (known before any space).
      virtual bool
      has_own_unknowns() const
      {
        return false;
      }

      /// Build the own unknowns on the current space (collective).
      virtual void
      setup_own_unknowns()
      {}

      virtual unsigned int
      n_own_unknowns() const
      {
        return 0;
      }

      /// [begin, end) of the own unknowns this rank owns.
      virtual std::pair<unsigned int, unsigned int>
      owned_own_unknowns() const
      {
        return {0, 0};
      }

      /// The own unknowns the locally owned @p cell couples to (their
      /// order is that of assemble_own()'s rows).
      virtual std::vector<unsigned int>
      own_unknowns_of(
        const typename DoFHandler<dim>::active_cell_iterator & /*cell*/) const
      {
        return {};
      }

      /**
       * Add the cell's share of the rows and columns of its own unknowns:
       * @p matrix and @p rhs have the cell's DoFs first (@p n_dofs, the
       * displacement block already assembled) and then its own unknowns
       * (own_unknowns_of()); only the entries of the own unknowns' rows and
       * columns are this function's.
       */
      virtual void
      assemble_own(const CellInput<dim> & /*input*/,
                   const unsigned int /*n_dofs*/,
                   FullMatrix<double> & /*matrix*/,
                   Vector<double> & /*rhs*/)
      {}

      /// After each solve: the values of all own unknowns (on every rank).
      virtual void
      set_own_values(const std::vector<double> & /*values*/)
      {}
      /// @}
    };
  } // namespace Assembly
} // namespace xcrack

#endif
