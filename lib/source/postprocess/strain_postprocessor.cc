#include <softgrasp/base/plane_strain.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/postprocess/strain_postprocessor.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  StrainPostprocessor<dim>::StrainPostprocessor(
      const unsigned int first_component)
      : first_component(first_component)
  {
  }

  template <int dim>
  void StrainPostprocessor<dim>::evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        F[i] += inputs.solution_gradients[q][first_component + i];
      const PrincipalStrains p =
          PrincipalStrains::compute(PlaneStrain::to_3d(F));
      Vector<double> &out = computed_quantities[q];
      out[0]              = p.strains[0];
      out[1]              = p.strains[1];
      out[2]              = p.strains[2];
      out[3]              = p.J;
      for (unsigned int i = 0; i < dim; ++i)
        out[4 + i] = p.directions[0][i];
    }
  }

  template <int dim>
  std::vector<std::string> StrainPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names = {"e_max", "e_mid", "e_min", "J"};
    for (unsigned int i = 0; i < dim; ++i)
      names.emplace_back("n_max");
    return names;
  }

  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StrainPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(4, DataComponentInterpretation::component_is_scalar);
    for (unsigned int i = 0; i < dim; ++i)
      interpretation.push_back(
          DataComponentInterpretation::component_is_part_of_vector);
    return interpretation;
  }

  template <int dim>
  UpdateFlags StrainPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients;
  }

  template class StrainPostprocessor<2>;
  template class StrainPostprocessor<3>;
} // namespace softgrasp
