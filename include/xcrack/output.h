#ifndef xcrack_output_h
#define xcrack_output_h

#include <deal.II/numerics/data_postprocessor.h>

#include <xcrack/material.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * Stress tensor and von Mises stress computed from the displacement
   * gradient at the output points, so that the VTU files show the fields an
   * engineer looks at first.
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    explicit StressPostprocessor(const Material &material);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Material &material;
  };
} // namespace xcrack

#endif
