#ifndef xcrack_fracture_integral_derivatives_h
#define xcrack_fracture_integral_derivatives_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The derivatives d b_jm / dU of the interaction integral's integrals b_jm
   * (test function j of the smoothing basis, mode m) with respect to the
   * displacement DoFs: the loads of the K error estimate's dual problems
   * (KDerivatives). Each b_jm sums grad u : A_jm over the points of the
   * crown, so its derivative gets grad phi_i : A_jm at every shape function
   * i of the point's cell.
   *
   * The A's of a point are summed over the integrand's terms first (add()),
   * then contracted with each shape gradient once (flush_point()): the
   * gradients of FE_Enriched's shape functions are slow to read, and one
   * point contributes to several terms and test functions.
   */
  template <int dim>
  class IntegralDerivatives
  {
  public:
    /// Zero derivatives for @p n_tests test functions and @p n_modes modes,
    /// as vectors of the DoFs @p owned.
    IntegralDerivatives(const IndexSet    &owned,
                        const MPI_Comm     comm,
                        const unsigned int n_tests,
                        const unsigned int n_modes);

    /// Start the cell @p cell, on which the test functions @p active_tests
    /// do not vanish.
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const std::vector<unsigned int>                      &active_tests);

    /// Add A (weights included) to the point's tensor of test function
    /// @p j and mode @p m.
    void
    add(const unsigned int j, const unsigned int m, const Tensor<2, dim> &A)
    {
      point_loads[j * n_modes + m] += A;
    }

    /// Contract the point's tensors with the shape gradients at point @p q
    /// of @p values (the cell's), and start the next point.
    void
    flush_point(const FEValues<dim> &values, const unsigned int q);

    /// Add the cell's derivatives so far to the global ones through
    /// @p constraints (condensed), and start afresh on the same cell.
    void
    flush_cell(const AffineConstraints<double> &constraints);

    /// The global derivative of b_jm times @p scale (collective: the first
    /// call compresses).
    TrilinosWrappers::MPI::Vector
    scaled(const unsigned int j, const unsigned int m, const double scale);

  private:
    const unsigned int                         n_modes;
    std::vector<TrilinosWrappers::MPI::Vector> global;
    bool                                       compressed = false;
    std::vector<Vector<double>>                cell_loads;
    std::vector<Tensor<2, dim>>                point_loads;
    std::vector<types::global_dof_index>       dof_indices;
    /// Per shape function of the cell: its one non-zero component, or
    /// invalid_unsigned_int for a non-primitive one.
    std::vector<unsigned int> components;
    std::vector<unsigned int> active_tests;
  };
} // namespace xcrack

#endif
