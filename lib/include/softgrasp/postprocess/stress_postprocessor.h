#ifndef softgrasp_postprocess_stress_postprocessor_h
#define softgrasp_postprocess_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>
#include <softgrasp/materials/material_library.h>

namespace softgrasp
{
  /**
   * DataPostprocessor for DataOut: Cauchy stress sigma (Pa, a dim x dim
   * tensor; in 2D the in-plane part of the plane-strain state), von Mises
   * stress (Pa) and pressure p = -tr(sigma)/3 (Pa), computed by the material
   * of each cell's material id from F = I + Grad u. The displacement
   * occupies components [first_component, first_component + dim). Fibre
   * directions are evaluated at the output points, which must be reference
   * positions (no displacement in the mapping given to DataOut).
   */
  template <int dim>
  class StressPostprocessor : public dealii::DataPostprocessor<dim>
  {
  public:
    StressPostprocessor(const MaterialLibrary &materials,
                        const unsigned int     first_component = 0);

    void evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<dealii::Vector<double>>                &computed_quantities)
        const override;

    std::vector<std::string> get_names() const override;

    std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    dealii::UpdateFlags get_needed_update_flags() const override;

  private:
    const MaterialLibrary &materials;
    const unsigned int     first_component;
  };
} // namespace softgrasp

#endif
