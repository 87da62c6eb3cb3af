#include <deal.II/base/exceptions.h>
#include <softgrasp/mechanics/dilatation_state.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void DilatationState<dim>::start(const unsigned int n_active_cells)
  {
    cells.clear();
    cells.resize(n_active_cells);
    is_active   = true;
    is_recorded = false;
  }

  template <int dim> void DilatationState<dim>::clear()
  {
    std::vector<Cell>().swap(cells);
    is_active   = false;
    is_recorded = false;
  }

  template <int dim> bool DilatationState<dim>::active() const
  {
    return is_active;
  }

  template <int dim> bool DilatationState<dim>::recorded() const
  {
    return is_active && is_recorded;
  }

  template <int dim>
  void DilatationState<dim>::set_recorded(const bool complete)
  {
    is_recorded = is_active && complete;
  }

  template <int dim>
  const DilatationCoefficients *
  DilatationState<dim>::coefficients(const unsigned int index) const
  {
    if (!recorded())
      return nullptr;
    AssertIndexRange(index, cells.size());
    return &cells[index].current;
  }

  template <int dim>
  void DilatationState<dim>::store(const unsigned int            index,
                                   const DilatationCoefficients &c)
  {
    AssertIndexRange(index, cells.size());
    cells[index].current = c;
  }

  template <int dim>
  void DilatationState<dim>::store(const unsigned int             index,
                                   const DilatationLinearization &l)
  {
    AssertIndexRange(index, cells.size());
    cells[index].linearization = l;
  }

  template <int dim> void DilatationState<dim>::begin_update()
  {
    for (Cell &cell : cells)
      cell.start = cell.current;
  }

  template <int dim>
  void
  DilatationState<dim>::apply_update(const DoFHandler<dim>               &dofs,
                                     const TrilinosWrappers::MPI::Vector &du,
                                     const double                         alpha)
  {
    Vector<double> du_cell, increment;
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      Cell                          &data = cells[cell->active_cell_index()];
      const DilatationLinearization &l    = data.linearization;
      Assert(l.J_rate.n() == cell->get_fe().n_dofs_per_cell(),
             ExcMessage("No linearisation recorded for this cell."));
      du_cell.reinit(l.J_rate.n());
      cell->get_dof_values(du, du_cell);
      increment = l.J_offset;
      l.J_rate.vmult_add(increment, du_cell);
      data.current.J = data.start.J;
      data.current.J.add(alpha, increment);
      increment = l.p_offset;
      l.p_rate.vmult_add(increment, du_cell);
      data.current.p = data.start.p;
      data.current.p.add(alpha, increment);
    }
  }

  template class DilatationState<2>;
  template class DilatationState<3>;
} // namespace softgrasp
