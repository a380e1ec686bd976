#ifndef xcrack_linear_solver_direct_h
#define xcrack_linear_solver_direct_h

#include <xcrack/linear_solver/interface.h>

#include <memory>
#include <string>

class Amesos_Mumps;
class Epetra_LinearProblem;

namespace xcrack
{
  namespace LinearSolver
  {
    /**
     * `direct`: MUMPS through Trilinos Amesos, distributed over the MPI
     * ranks. Robust for the badly conditioned matrices of enriched spaces,
     * the reference for every other choice, and the one solver that takes
     * every kind of system: LDL^T of one triangle for the symmetric ones
     * (half the time and memory of LU), LU for the unsymmetric one.
     * `Direct solver ordering` picks the fill-reducing ordering.
     */
    template <int dim>
    class Direct : public Interface<dim>
    {
    public:
      Direct();
      ~Direct() override;

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      bool
      accepts(const MatrixProperty property) const override;

      bool
      accepts_saddle_point() const override
      {
        return true;
      }

      unsigned int
      solve(const System                        &system,
            TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &rhs) override;

      unsigned int
      solve_again(TrilinosWrappers::MPI::Vector       &x,
                  const TrilinosWrappers::MPI::Vector &rhs) override;

      void
      release() override;

      std::string
      iterative_method() const override;

    private:
      /// "metis", "auto" or "pord".
      std::string ordering = "metis";

      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_Mumps>         factorization;
    };
  } // namespace LinearSolver
} // namespace xcrack

#endif
