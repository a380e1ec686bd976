#include <xcrack/output.h>

namespace xcrack
{
  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(const Material &material)
    : material(material)
  {}



  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        Tensor<2, dim> grad;
        for (unsigned int d = 0; d < dim; ++d)
          grad[d] = inputs.solution_gradients[q][d];
        const SymmetricTensor<2, dim> stress =
          material.stress(symmetrize(grad));
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            computed_quantities[q][i * dim + j] = stress[i][j];
        computed_quantities[q][dim * dim] = material.von_mises(stress);
      }
  }



  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names(dim * dim, "stress");
    names.emplace_back("von_mises");
    return names;
  }



  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim * dim,
                     DataComponentInterpretation::component_is_part_of_tensor);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }



  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients;
  }



  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
} // namespace xcrack
