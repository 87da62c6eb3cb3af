#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <softgrasp/postprocess/corner_jacobian.h>

#include <cmath>
#include <limits>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  CornerJacobian<dim>
  smallest_corner_jacobian(const Mapping<dim>                  &mapping,
                           const DoFHandler<dim>               &dof_handler,
                           const TrilinosWrappers::MPI::Vector &ghosted_u,
                           MPI_Comm                             comm)
  {
    // the trapezoidal rule's points are the cell's vertices
    FEValues<dim>                    corners(mapping,
                          dof_handler.get_fe(),
                          QTrapezoid<dim>(),
                          update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(corners.n_quadrature_points);
    CornerJacobian<dim>              local;
    local.J = std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        corners.reinit(cell);
        corners[displacement].get_function_gradients(ghosted_u, grad_u);
        for (unsigned int q = 0; q < grad_u.size(); ++q)
        {
          const double J =
              determinant(unit_symmetric_tensor<dim>() + grad_u[q]);
          if (J < local.J || !std::isfinite(J))
          {
            local.J        = std::isfinite(J) ? J : -1;
            local.position = corners.quadrature_point(q);
          }
        }
      }
    CornerJacobian<dim> global;
    global.J = Utilities::MPI::min(local.J, comm);
    // the vertex of the lowest rank that holds the smallest value
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const unsigned int owner = Utilities::MPI::min(
        local.J == global.J ? rank : Utilities::MPI::n_mpi_processes(comm),
        comm);
    global.position = Utilities::MPI::broadcast(comm, local.position, owner);
    return global;
  }

  template CornerJacobian<2>
  smallest_corner_jacobian(const Mapping<2> &,
                           const DoFHandler<2> &,
                           const TrilinosWrappers::MPI::Vector &,
                           MPI_Comm);
  template CornerJacobian<3>
  smallest_corner_jacobian(const Mapping<3> &,
                           const DoFHandler<3> &,
                           const TrilinosWrappers::MPI::Vector &,
                           MPI_Comm);
} // namespace softgrasp
