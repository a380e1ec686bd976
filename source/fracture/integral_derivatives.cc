#include <deal.II/fe/fe_values_extractors.h>

#include <xcrack/fracture/integral_derivatives.h>

namespace xcrack
{
  template <int dim>
  IntegralDerivatives<dim>::IntegralDerivatives(const IndexSet    &owned,
                                                const MPI_Comm     comm,
                                                const unsigned int n_tests,
                                                const unsigned int n_modes)
    : n_modes(n_modes)
    , global(n_tests * n_modes, TrilinosWrappers::MPI::Vector(owned, comm))
    , point_loads(n_tests * n_modes)
  {}



  template <int dim>
  void
  IntegralDerivatives<dim>::reinit(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const std::vector<unsigned int>                      &active_tests)
  {
    const FiniteElement<dim> &fe     = cell->get_fe();
    const unsigned int        n_dofs = fe.n_dofs_per_cell();
    cell_loads.assign(global.size(), Vector<double>(n_dofs));
    dof_indices.resize(n_dofs);
    cell->get_dof_indices(dof_indices);
    this->active_tests = active_tests;
    // The component of each primitive shape function (all of X-FEM's
    // vector elements: FESystem of a scalar FE_Enriched), else none.
    components.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      components[i] = fe.is_primitive(i) ?
                        fe.system_to_component_index(i).first :
                        numbers::invalid_unsigned_int;
  }



  template <int dim>
  void
  IntegralDerivatives<dim>::flush_point(const FEValues<dim> &values,
                                        const unsigned int   q)
  {
    const FEValuesExtractors::Vector displacement(0);
    for (unsigned int i = 0; i < dof_indices.size(); ++i)
      if (const unsigned int c = components[i];
          c != numbers::invalid_unsigned_int)
        {
          // grad phi_i = e_c (x) grad N_i: only row c of each A counts.
          const Tensor<1, dim> &g = values.shape_grad(i, q);
          for (const unsigned int j : active_tests)
            for (unsigned int m = 0; m < n_modes; ++m)
              cell_loads[j * n_modes + m][i] +=
                g * point_loads[j * n_modes + m][c];
        }
      else
        {
          const Tensor<2, dim> g = values[displacement].gradient(i, q);
          for (const unsigned int j : active_tests)
            for (unsigned int m = 0; m < n_modes; ++m)
              cell_loads[j * n_modes + m][i] +=
                scalar_product(g, point_loads[j * n_modes + m]);
        }
    for (const unsigned int j : active_tests)
      for (unsigned int m = 0; m < n_modes; ++m)
        point_loads[j * n_modes + m] = Tensor<2, dim>();
  }



  template <int dim>
  void
  IntegralDerivatives<dim>::flush_cell(
    const AffineConstraints<double> &constraints)
  {
    for (unsigned int i = 0; i < cell_loads.size(); ++i)
      {
        constraints.distribute_local_to_global(cell_loads[i],
                                               dof_indices,
                                               global[i]);
        cell_loads[i] = 0;
      }
  }



  template <int dim>
  TrilinosWrappers::MPI::Vector
  IntegralDerivatives<dim>::scaled(const unsigned int j,
                                   const unsigned int m,
                                   const double       scale)
  {
    if (!compressed)
      for (auto &d : global)
        d.compress(VectorOperation::add);
    compressed = true;
    TrilinosWrappers::MPI::Vector result(global[j * n_modes + m]);
    result *= scale;
    return result;
  }



  template class IntegralDerivatives<2>;
  template class IntegralDerivatives<3>;
} // namespace xcrack
