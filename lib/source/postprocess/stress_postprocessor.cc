#include <deal.II/dofs/dof_handler.h>
#include <limits>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/postprocess/stress_postprocessor.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
      const MaterialLibrary &materials, const unsigned int first_component)
      : materials(materials)
      , first_component(first_component)
  {
  }

  template <int dim>
  void StressPostprocessor<dim>::evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>>                &computed_quantities) const
  {
    const auto      cell     = inputs.template get_cell<dim>();
    const Material &material = materials.get(cell->material_id());
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        F[i] += inputs.solution_gradients[q][first_component + i];
      Vector<double>       &out = computed_quantities[q];
      SymmetricTensor<2, 3> sigma;
      try
      {
        sigma = material.cauchy_stress(
            PlaneStrain::to_3d(F),
            material.structural_directions(
                PlaneStrain::to_3d(inputs.evaluation_points[q])));
      }
      catch (const InvertedMaterialState &)
      {
        // An output point (not a quadrature point) of a strongly distorted
        // higher-order element can have J <= 0; its stress is undefined.
        out = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          out[i * dim + j] = sigma[i][j];
      out[dim * dim]     = von_mises_stress(sigma);
      out[dim * dim + 1] = -trace(sigma) / 3.0;
    }
  }

  template <int dim>
  std::vector<std::string> StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names(dim * dim, "cauchy_stress");
    names.emplace_back("von_mises_stress");
    names.emplace_back("pressure");
    return names;
  }

  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
            dim * dim,
            DataComponentInterpretation::component_is_part_of_tensor);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }

  template <int dim>
  UpdateFlags StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }

  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
} // namespace softgrasp
