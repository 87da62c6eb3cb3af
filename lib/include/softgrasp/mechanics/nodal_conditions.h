#ifndef softgrasp_mechanics_nodal_conditions_h
#define softgrasp_mechanics_nodal_conditions_h

#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <string>
#include <vector>

namespace softgrasp
{
  template <int dim> class SolidSystem;

  /**
   * Conditions that replace the equilibrium equations of some nodes by
   * other (nonlinear) equations Phi_j = 0, linearised as
   *   A_j (K du)_j + B_j du_j = -Phi_j,
   * i.e. a combination A_j of the node's rows of the tangent K plus a
   * node-local matrix B_j. Mortar contact with condensed multipliers is of
   * this kind. SolidSystem calls evaluate() after each residual assembly,
   * transforms every cell's rows while assembling the tangent, and then
   * adds the node-local terms.
   */
  template <int dim> class NodalConditions
  {
  public:
    virtual ~NodalConditions() = default;

    /// Decide the state of every node at the current solution of @p system
    /// (its internal and external forces have just been assembled).
    virtual void evaluate(const SolidSystem<dim> &system) = 0;

    /// Overwrite the residual (f_ext - f_int) rows of the governed nodes by
    /// -Phi. Collective.
    virtual void apply_to_residual(
        dealii::TrilinosWrappers::MPI::Vector &residual) const = 0;

    /// Replace the rows of the governed nodes in a cell's matrix and
    /// right-hand side (indices are the cell's global dof indices).
    virtual void transform_cell_rows(
        const std::vector<dealii::types::global_dof_index> &dof_indices,
        dealii::FullMatrix<double>                         &matrix,
        dealii::Vector<double>                             &rhs) const = 0;

    /// Add B_j to the tangent and -(Phi_j - A_j f_j) to the right-hand side
    /// at locally owned nodes. Collective (compresses both).
    virtual void
    add_node_terms(dealii::TrilinosWrappers::SparseMatrix &tangent,
                   dealii::TrilinosWrappers::MPI::Vector  &rhs) const = 0;

    /// One line for the Newton log (e.g. active-set sizes and changes).
    virtual std::string iteration_report() const = 0;
  };
} // namespace softgrasp

#endif
