#include <xcrack/linear_solver/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace LinearSolver
  {
    std::string
    to_string(const MatrixProperty property)
    {
      switch (property)
        {
          case MatrixProperty::spd:
            return "symmetric positive definite";
          case MatrixProperty::symmetric:
            return "symmetric indefinite";
          case MatrixProperty::general:
            return "unsymmetric";
        }
      return "";
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.declare_entry("Type",
                        "direct",
                        Patterns::Selection(List::pattern()),
                        "The solver of the linear systems:" +
                          List::documentation());
      // The iterative solvers share these.
      prm.declare_entry("Relative tolerance",
                        "1e-10",
                        Patterns::Double(0, 1),
                        "Iterative solvers: stop when |r| < tolerance |b|.");
      prm.declare_entry("Maximum iterations",
                        "2000",
                        Patterns::Integer(1),
                        "Iterative solvers: give up after this many "
                        "iterations.");
      prm.declare_entry(
        "Partition",
        "balanced",
        Patterns::Selection("balanced|assembly"),
        "Iterative solvers on several MPI ranks: which rows each rank "
        "solves. balanced: the matrix is moved so that every rank holds the "
        "same number of its entries (the cost of AMG and of a Krylov "
        "iteration); assembly: the rows each rank assembled, which "
        "Parallel/Partition = work makes uneven (the rank with the front has "
        "fewer rows). The direct solver ignores it.");
      List::declare_parameters(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      return create_plugin<dim, Interface<dim>>(prm.get("Type"),
                                                "Linear solver/Type",
                                                prm,
                                                simulator);
    }



    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace LinearSolver
} // namespace xcrack
