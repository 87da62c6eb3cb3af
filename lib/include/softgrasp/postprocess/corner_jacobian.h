#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

namespace softgrasp
{
  /**
   * The smallest Jacobian determinant J = det F of the displacement field
   * at the vertices of the cells, and the reference position of that
   * vertex (m). A folding element turns a corner inside out (J <= 0 there)
   * while J stays positive at all of its quadrature points, so the solver's
   * own check does not see it: on a coarse mesh a deep sliding contact can
   * fold the surface cells next to it, and the forces after that are an
   * artefact of the mesh (doc/contact.md, "Agreement with CalculiX").
   */
  template <int dim> struct CornerJacobian
  {
    double             J = 1;
    dealii::Point<dim> position;
    /// True if some vertex has turned inside out.
    bool folded() const
    {
      return !(J > 0);
    }
  };

  /// CornerJacobian of the displacement @p ghosted_u (the first dim
  /// components of the element of @p dof_handler) over the locally owned
  /// cells of all ranks. Collective.
  template <int dim>
  CornerJacobian<dim> smallest_corner_jacobian(
      const dealii::Mapping<dim>                  &mapping,
      const dealii::DoFHandler<dim>               &dof_handler,
      const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
      MPI_Comm                                     comm);
} // namespace softgrasp
