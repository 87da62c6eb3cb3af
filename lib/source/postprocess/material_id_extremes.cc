#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <limits>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/postprocess/material_id_extremes.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <utility>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  template <typename VectorType>
  void MaterialIdExtremes<dim>::compute(const DoFHandler<dim> &dof_handler,
                                        const VectorType      &solution,
                                        const MaterialLibrary &materials,
                                        const Quadrature<dim> &quadrature,
                                        const unsigned int     first_component)
  {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto       ids = materials.material_ids();
    // per id: maxima of (e_max, -e_min, -J_min, J_max, von_mises), count
    std::vector<double>       maxima(5 * ids.size(), -inf);
    std::vector<unsigned int> counts(ids.size(), 0);

    FEValues<dim>                              fe_values(dof_handler.get_fe(),
                            quadrature,
                            update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector           displacement(first_component);
    std::vector<Tensor<2, dim>>                grad_u(quadrature.size());
    std::map<types::material_id, unsigned int> index;
    for (unsigned int k = 0; k < ids.size(); ++k)
      index[ids[k]] = k;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(solution, grad_u);
        const Material    &material = materials.get(cell->material_id());
        const unsigned int k        = index.at(cell->material_id());
        for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const Tensor<2, 3> F = PlaneStrain::to_3d(
              Tensor<2, dim>(unit_symmetric_tensor<dim>()) + grad_u[q]);
          const PrincipalStrains p  = PrincipalStrains::compute(F);
          const double           vm = von_mises_stress(material.cauchy_stress(
              F,
              material.structural_directions(
                  PlaneStrain::to_3d(fe_values.quadrature_point(q)))));
          const double local[5]     = {p.e_max(), -p.e_min(), -p.J, p.J, vm};
          for (unsigned int m = 0; m < 5; ++m)
            maxima[5 * k + m] = std::max(maxima[5 * k + m], local[m]);
          ++counts[k];
        }
      }

    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    {
      std::vector<double>       global_maxima(maxima.size());
      std::vector<unsigned int> global_counts(counts.size());
      Utilities::MPI::max(make_array_view(std::as_const(maxima)),
                          comm,
                          make_array_view(global_maxima));
      Utilities::MPI::sum(make_array_view(std::as_const(counts)),
                          comm,
                          make_array_view(global_counts));
      maxima = std::move(global_maxima);
      counts = std::move(global_counts);
    }
    values.clear();
    for (unsigned int k = 0; k < ids.size(); ++k)
      if (counts[k] > 0)
      {
        Extremes &e     = values[ids[k]];
        e.e_max         = maxima[5 * k];
        e.e_min         = -maxima[5 * k + 1];
        e.J_min         = -maxima[5 * k + 2];
        e.J_max         = maxima[5 * k + 3];
        e.von_mises_max = maxima[5 * k + 4];
        e.n_points      = counts[k];
      }
  }

  template <int dim>
  const std::map<types::material_id, typename MaterialIdExtremes<dim>::Extremes>
      &MaterialIdExtremes<dim>::extremes() const
  {
    return values;
  }

  template <int dim>
  TableHandler
  MaterialIdExtremes<dim>::table(const MaterialLibrary &materials) const
  {
    TableHandler table;
    for (const auto &[id, e] : values)
    {
      table.add_value("material_id", static_cast<unsigned int>(id));
      table.add_value("name", materials.get(id).name());
      table.add_value("e_max", e.e_max);
      table.add_value("e_min", e.e_min);
      table.add_value("E_GL_max", green_lagrange_strain(e.e_max));
      table.add_value("E_GL_min", green_lagrange_strain(e.e_min));
      table.add_value("log_strain_max", logarithmic_strain(e.e_max));
      table.add_value("log_strain_min", logarithmic_strain(e.e_min));
      table.add_value("J_min", e.J_min);
      table.add_value("J_max", e.J_max);
      table.add_value("von_Mises_max_Pa", e.von_mises_max);
    }
    for (const char *column : {"e_max",
                               "e_min",
                               "E_GL_max",
                               "E_GL_min",
                               "log_strain_max",
                               "log_strain_min",
                               "J_min",
                               "J_max",
                               "von_Mises_max_Pa"})
    {
      table.set_scientific(column, true);
      table.set_precision(column, 4);
    }
    return table;
  }

  template class MaterialIdExtremes<2>;
  template class MaterialIdExtremes<3>;

#define SOFTGRASP_INSTANTIATE(dim, VectorType)                                 \
  template void MaterialIdExtremes<dim>::compute<VectorType>(                  \
      const DoFHandler<dim> &,                                                 \
      const VectorType &,                                                      \
      const MaterialLibrary &,                                                 \
      const Quadrature<dim> &,                                                 \
      const unsigned int);
  SOFTGRASP_INSTANTIATE(2, Vector<double>)
  SOFTGRASP_INSTANTIATE(3, Vector<double>)
  SOFTGRASP_INSTANTIATE(2, LinearAlgebra::distributed::Vector<double>)
  SOFTGRASP_INSTANTIATE(3, LinearAlgebra::distributed::Vector<double>)
  SOFTGRASP_INSTANTIATE(2, TrilinosWrappers::MPI::Vector)
  SOFTGRASP_INSTANTIATE(3, TrilinosWrappers::MPI::Vector)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
