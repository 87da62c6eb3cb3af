#ifndef softgrasp_mechanics_nodal_conditions_h
#define softgrasp_mechanics_nodal_conditions_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
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
   * this kind. SolidSystem calls evaluate() after each residual assembly;
   * before assembling the tangent it asks for the node constraints of the
   * current state (add_constraints()), which it merges with the
   * hanging-node and Dirichlet constraints, then transforms every cell's
   * rows and adds the node-local terms, both condensed through those
   * constraints.
   *
   * The constraints carry the node equations that do not couple to K: where
   * A_j = 0 (e.g. a sticking contact node) all of du_j is prescribed, and
   * where A_j has a left null vector z (z^T A_j = 0, e.g. the normal of a
   * sliding contact node) the equation z^T B_j du_j = -z^T Phi_j becomes one
   * linear constraint on du_j. What remains of the node's rows is tested
   * only with directions in the constraint's null space, so the condensed
   * system is symmetric wherever the remaining rows are (symmetric()).
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

    /// Add the node constraints of the current state (after evaluate()) to
    /// @p constraints (not closed; its index set is the locally relevant
    /// dofs): identical lines on every rank that sees a node.
    virtual void
    add_constraints(dealii::AffineConstraints<double> &constraints) const = 0;

    /// Add B_j to the tangent and -(Phi_j - A_j f_j) to the right-hand side
    /// at locally owned nodes, condensed through @p constraints (those the
    /// cells' contributions went through). Collective (compresses both).
    virtual void
    add_node_terms(const dealii::AffineConstraints<double> &constraints,
                   dealii::TrilinosWrappers::SparseMatrix  &tangent,
                   dealii::TrilinosWrappers::MPI::Vector   &rhs) const = 0;

    /// Whether the condensed tangent is symmetric where the tangent of the
    /// solid is (no sliding node with friction at the current state).
    virtual bool symmetric() const = 0;

    /**
     * Whether the conditions add the gradient of a potential (energy()) to
     * the solid's residual and its (positive semi-definite) Hessian to the
     * tangent, without transforming rows or adding constraints. Newton then
     * searches its line on the total potential (NewtonSolver).
     */
    virtual bool is_potential() const
    {
      return false;
    }

    /**
     * Whether Newton should backtrack along its direction until the
     * residual norm falls (Armijo on |r|) rather than take full steps, for
     * conditions that are neither a potential nor semi-smooth (friction
     * against the current normal force).
     */
    virtual bool backtrack_on_residual() const
    {
      return false;
    }

    /**
     * Potential conditions: from the next tangent on, add the projection
     * of each node's Hessian onto the positive semi-definite matrices
     * (@p on) or the Hessian itself (!@p on). Newton asks for the
     * projection when the exact tangent gave no descent direction.
     */
    virtual void project_to_positive(const bool on)
    {
      (void)on;
    }

    /// The conditions' potential at the last evaluate() (J; J/m in 2D),
    /// summed over processes; 0 unless is_potential(). Collective.
    virtual double energy() const
    {
      return 0;
    }

    /// One line for the Newton log (e.g. active-set sizes and changes).
    virtual std::string iteration_report() const = 0;

    /// The state of the node that owns @p dof, if this rank governs it
    /// (e.g. "contact node, slip on body/geom, gap ..."); "" otherwise.
    virtual std::string
    describe_node(const dealii::types::global_dof_index dof) const
    {
      (void)dof;
      return "";
    }
  };
} // namespace softgrasp

#endif
