#ifndef softgrasp_explicit_lumped_mass_h
#define softgrasp_explicit_lumped_mass_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <softgrasp/materials/material_library.h>
#include <vector>

namespace softgrasp
{
  /**
   * The diagonal (lumped) mass of a displacement field FESystem(FE_Q(p),
   * dim), p = 1 or 2 (kg per dof; kg/m in 2D): the mass matrix integrated
   * with the Gauss-Lobatto quadrature whose points are the element's nodes
   * (nodal quadrature), which makes each element mass diagonal with entries
   * rho_0 w_q |J_q| > 0 for every element type offered (for Q1 this is
   * row-sum lumping; for Q2 it avoids the zero or negative corner masses of
   * other lumpings). Each dof of a node carries the node's mass; hanging
   * nodes pass their mass on to the nodes they are constrained to.
   * The total per displacement component is the body's mass exactly.
   * @p mass must be initialised with the matrix-free partitioner.
   * @p density_factor, if not empty, multiplies the density of each cell
   * (by active cell index): the mass scaling of the explicit solver.
   */
  template <int dim>
  void
  compute_lumped_mass(const dealii::Mapping<dim>              &mapping,
                      const dealii::DoFHandler<dim>           &dofs,
                      const dealii::AffineConstraints<double> &constraints,
                      const MaterialLibrary                   &materials,
                      dealii::LinearAlgebra::distributed::Vector<double> &mass,
                      const std::vector<double> &density_factor = {});
} // namespace softgrasp

#endif
