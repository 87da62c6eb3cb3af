#ifndef softgrasp_postprocess_strain_postprocessor_h
#define softgrasp_postprocess_strain_postprocessor_h

#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_postprocessor.h>

namespace softgrasp
{
  /**
   * DataPostprocessor for DataOut: the principal strains of the paper
   * (see PrincipalStrains) from the displacement field, which occupies
   * components [first_component, first_component + dim) of the solution.
   * Outputs: e_max, e_mid, e_min (1), J (1), the reference direction
   * n_max of the largest principal stretch (a vector), and the largest and
   * smallest principal strains in two other measures of the same
   * stretches: Green-Lagrange E_GL = (lambda^2 - 1)/2 and logarithmic
   * ln(lambda) (1). In 2D the state is plane strain, so one principal
   * stretch is the out-of-plane 1.
   */
  template <int dim>
  class StrainPostprocessor : public dealii::DataPostprocessor<dim>
  {
  public:
    explicit StrainPostprocessor(const unsigned int first_component = 0);

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
    const unsigned int first_component;
  };

  template <int dim> class SolidSystem;

  /**
   * Per locally owned cell (by active cell index), the largest e_max and
   * the smallest e_min over its quadrature points (QGauss(degree + 1),
   * where the stresses are evaluated) at the system's current
   * displacement: the peaks that nodal values, averaged between cells,
   * smooth out. @p e_max and @p e_min have one entry per active cell.
   */
  template <int dim>
  void cell_strain_extremes(const SolidSystem<dim> &system,
                            dealii::Vector<float>  &e_max,
                            dealii::Vector<float>  &e_min);
} // namespace softgrasp

#endif
