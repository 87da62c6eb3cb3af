#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/mechanics/solid_system.h>
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
      // the same principal stretches as Green-Lagrange and logarithmic
      // strains
      const double l_max = p.stretches[0], l_min = p.stretches[2];
      out[4 + dim]     = green_lagrange_strain(l_max - 1);
      out[4 + dim + 1] = green_lagrange_strain(l_min - 1);
      out[4 + dim + 2] = logarithmic_strain(l_max - 1);
      out[4 + dim + 3] = logarithmic_strain(l_min - 1);
    }
  }

  template <int dim>
  std::vector<std::string> StrainPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names = {"e_max", "e_mid", "e_min", "J"};
    for (unsigned int i = 0; i < dim; ++i)
      names.emplace_back("n_max");
    for (const char *name :
         {"E_GL_max", "E_GL_min", "log_strain_max", "log_strain_min"})
      names.emplace_back(name);
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
    for (unsigned int i = 0; i < 4; ++i)
      interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }

  template <int dim>
  UpdateFlags StrainPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients;
  }

  template <int dim>
  void cell_strain_extremes(const SolidSystem<dim> &system,
                            Vector<float>          &e_max,
                            Vector<float>          &e_min)
  {
    const QGauss<dim> quadrature(system.fe().degree + 1);
    FEValues<dim>     values(
        system.mapping(), system.fe(), quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      gradients(quadrature.size());
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(system.ghosted_solution(),
                                                    gradients);
        double largest = -1e300, smallest = 1e300;
        for (const auto &grad_u : gradients)
        {
          Tensor<2, dim> F = unit_symmetric_tensor<dim>();
          F += grad_u;
          const PrincipalStrains p =
              PrincipalStrains::compute(PlaneStrain::to_3d(F));
          largest  = std::max(largest, p.e_max());
          smallest = std::min(smallest, p.e_min());
        }
        e_max[cell->active_cell_index()] = largest;
        e_min[cell->active_cell_index()] = smallest;
      }
  }

  template void cell_strain_extremes(const SolidSystem<2> &,
                                     Vector<float> &,
                                     Vector<float> &);
  template void cell_strain_extremes(const SolidSystem<3> &,
                                     Vector<float> &,
                                     Vector<float> &);

  template class StrainPostprocessor<2>;
  template class StrainPostprocessor<3>;
} // namespace softgrasp
