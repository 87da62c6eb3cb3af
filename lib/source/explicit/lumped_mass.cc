#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <softgrasp/explicit/lumped_mass.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void compute_lumped_mass(const Mapping<dim>              &mapping,
                           const DoFHandler<dim>           &dofs,
                           const AffineConstraints<double> &constraints,
                           const MaterialLibrary           &materials,
                           LinearAlgebra::distributed::Vector<double> &mass,
                           const std::vector<double> &density_factor)
  {
    const auto              &fe = dofs.get_fe();
    const QGaussLobatto<dim> nodal(fe.degree + 1);
    FEValues<dim>            fe_values(
        mapping, fe, nodal, update_values | update_JxW_values);
    Vector<double>                       local(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    mass = 0;
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      const double rho =
          materials.get(cell->material_id()).density() *
          (density_factor.empty() ? 1.0
                                  : density_factor[cell->active_cell_index()]);
      local = 0;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int component = fe.system_to_component_index(i).first;
        for (unsigned int q = 0; q < nodal.size(); ++q)
        {
          const double N = fe_values.shape_value_component(i, q, component);
          local(i) += rho * N * N * fe_values.JxW(q); // diagonal entries
        }
      }
      cell->get_dof_indices(indices);
      constraints.distribute_local_to_global(local, indices, mass);
    }
    mass.compress(VectorOperation::add);
  }

  template void
  compute_lumped_mass<2>(const Mapping<2> &,
                         const DoFHandler<2> &,
                         const AffineConstraints<double> &,
                         const MaterialLibrary &,
                         LinearAlgebra::distributed::Vector<double> &,
                         const std::vector<double> &);
  template void
  compute_lumped_mass<3>(const Mapping<3> &,
                         const DoFHandler<3> &,
                         const AffineConstraints<double> &,
                         const MaterialLibrary &,
                         LinearAlgebra::distributed::Vector<double> &,
                         const std::vector<double> &);
} // namespace softgrasp
