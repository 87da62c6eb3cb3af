// SolidSystem's side of the nodal conditions (contact): what Newton asks
// of them through the system, and where the largest residual sits.
#include <algorithm>
#include <deal.II/base/mpi.h>
#include <softgrasp/mechanics/solid_system.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void SolidSystem<dim>::set_nodal_conditions(NodalConditions<dim> *conditions)
  {
    nodal_conditions = conditions;
  }

  template <int dim> bool SolidSystem<dim>::has_nodal_conditions() const
  {
    return nodal_conditions != nullptr;
  }

  template <int dim>
  void SolidSystem<dim>::project_nodal_hessians(const bool on)
  {
    if (nodal_conditions != nullptr)
      nodal_conditions->project_to_positive(on);
  }

  template <int dim> bool SolidSystem<dim>::has_potential() const
  {
    return !boundary_conditions.has_follower_loads() &&
           (nodal_conditions == nullptr || nodal_conditions->is_potential());
  }

  template <int dim> bool SolidSystem<dim>::backtrack_on_residual() const
  {
    return nodal_conditions != nullptr &&
           nodal_conditions->backtrack_on_residual();
  }

  template <int dim>
  std::string SolidSystem<dim>::nodal_conditions_report() const
  {
    return nodal_conditions ? nodal_conditions->iteration_report() : "";
  }

  template <int dim>
  std::string SolidSystem<dim>::describe_largest_residual() const
  {
    // The largest owned entry of this rank, then the largest of all ranks.
    double                  local_max = -1;
    types::global_dof_index local_dof = 0;
    for (const auto i : owned)
      if (std::abs(residual[i]) > local_max)
      {
        local_max = std::abs(residual[i]);
        local_dof = i;
      }
    const auto peak = Utilities::MPI::min_max_avg(local_max, communicator());
    const types::global_dof_index dof =
        Utilities::MPI::broadcast(communicator(), local_dof, peak.max_index);

    // Its node: the owner finds the support point on one of its cells.
    std::ostringstream where;
    if (Utilities::MPI::this_mpi_process(communicator()) == peak.max_index)
    {
      std::vector<types::global_dof_index> indices(fe().n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(indices);
        const auto it = std::find(indices.begin(), indices.end(), dof);
        if (it == indices.end())
          continue;
        const unsigned int i = it - indices.begin();
        const Point<dim>   x = reference_mapping.transform_unit_to_real_cell(
            cell, fe().unit_support_point(i));
        const char axis[] = {'x', 'y', 'z'};
        where << "the largest residual, " << peak.max << " N, is in the "
              << axis[fe().system_to_component_index(i).first]
              << " equation of the node at (" << x << ") m (reference)";
        const std::string node = nodal_conditions != nullptr
                                     ? nodal_conditions->describe_node(dof)
                                     : std::string();
        if (!node.empty())
          where << ": " << node;
        break;
      }
    }
    return Utilities::MPI::broadcast(
        communicator(), where.str(), peak.max_index);
  }

#define SOFTGRASP_INSTANTIATE(dim)                                             \
  template void SolidSystem<dim>::set_nodal_conditions(                        \
      NodalConditions<dim> *);                                                 \
  template bool        SolidSystem<dim>::has_nodal_conditions() const;         \
  template void        SolidSystem<dim>::project_nodal_hessians(const bool);   \
  template bool        SolidSystem<dim>::has_potential() const;                \
  template bool        SolidSystem<dim>::backtrack_on_residual() const;        \
  template std::string SolidSystem<dim>::nodal_conditions_report() const;      \
  template std::string SolidSystem<dim>::describe_largest_residual() const;
  SOFTGRASP_INSTANTIATE(2)
  SOFTGRASP_INSTANTIATE(3)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
