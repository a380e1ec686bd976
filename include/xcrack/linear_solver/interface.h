#ifndef xcrack_linear_solver_interface_h
#define xcrack_linear_solver_interface_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/plugins.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * The solver of the linear systems of a run (`subsection Linear solver`,
   * `Type`): the elasticity system, each Newton step's system when the
   * lips are in contact, and the dual problems of K's error estimate.
   *
   * A system says what kind of matrix it has (MatrixProperty): elasticity
   * alone is symmetric positive definite; Lagrange multipliers make it a
   * symmetric saddle point (indefinite); Coulomb friction makes the tangent
   * unsymmetric. A solver states which kinds it accepts (accepts()), so that
   * an impossible combination stops the run before any work, and is told
   * the kind of each system it solves, so that it factorises or iterates
   * accordingly (MUMPS's LDL^T of one triangle for the symmetric kinds, LU
   * for the unsymmetric one; CG only for the definite kind).
   *
   * The factorisation (or preconditioner) of the last solve() is kept until
   * release() or the next solve(), so that further right-hand sides with the
   * same matrix cost a substitution (or a preconditioned Krylov run) only.
   */
  namespace LinearSolver
  {
    /// What a system's matrix is.
    enum class MatrixProperty
    {
      /// Symmetric positive definite (elasticity, penalty contact).
      spd,
      /// Symmetric, indefinite (a saddle point: Lagrange multipliers).
      symmetric,
      /// Unsymmetric (the tangent of Coulomb friction).
      general
    };

    /// "symmetric positive definite", ... for messages.
    std::string
    to_string(const MatrixProperty property);



    /// A system to solve: its matrix, what kind it is, and (for AMG) the
    /// near-null space of the displacement, computed when a solver asks.
    struct System
    {
      const TrilinosWrappers::SparseMatrix &matrix;
      MatrixProperty                        property = MatrixProperty::spd;
      /// The rigid translations, one per component, on the locally owned
      /// DoFs, in the order of the owned index set (AMG's coarse spaces).
      std::function<std::vector<std::vector<bool>>()> constant_modes;
    };



    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      /// Whether this solver can solve systems of kind @p property.
      virtual bool
      accepts(const MatrixProperty property) const = 0;

      /// Whether it can solve a saddle point (Lagrange multipliers: rows
      /// with a zero diagonal block, which AMG cannot smooth).
      virtual bool
      accepts_saddle_point() const
      {
        return false;
      }

      /**
       * Solve @p system x = @p rhs (x: locally owned entries, its values the
       * initial guess of an iterative solver). Returns the iterations (1 for
       * a direct solver). Throws std::runtime_error with the reason when it
       * fails. Keeps what solve_again() needs.
       */
      virtual unsigned int
      solve(const System                        &system,
            TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &rhs) = 0;

      /**
       * Solve the matrix of the last solve() (which must still exist,
       * unchanged) for another right-hand side @p rhs, reusing its
       * factorisation or preconditioner. Returns the iterations.
       */
      virtual unsigned int
      solve_again(TrilinosWrappers::MPI::Vector       &x,
                  const TrilinosWrappers::MPI::Vector &rhs) = 0;

      /// Free what solve() kept (a direct solver's factor is the largest
      /// object of a solve).
      virtual void
      release() = 0;

      /// The Krylov method whose iterations solve() returns ("CG",
      /// "GMRES"), or empty for a direct solver (one solve).
      virtual std::string
      iterative_method() const = 0;
    };



    /// Declare `Type`, the entries the iterative solvers share and every
    /// solver's own (in the current subsection).
    void
    declare_parameters(ParameterHandler &prm);

    /// The solver `Type` selects (in the current subsection).
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace LinearSolver
} // namespace xcrack

#endif
