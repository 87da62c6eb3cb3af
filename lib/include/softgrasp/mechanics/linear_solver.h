#ifndef softgrasp_mechanics_linear_solver_h
#define softgrasp_mechanics_linear_solver_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <softgrasp/mechanics/solver_parameters.h>
#include <string>
#include <vector>

class Epetra_MultiVector;

namespace softgrasp
{
  /**
   * The linear solve of one Newton step on Trilinos matrices: sparse direct
   * (Amesos MUMPS), or CG/GMRES preconditioned by Trilinos ML smoothed
   * aggregation AMG whose near null space is the rigid-body modes of the
   * body (3 in 2D, 6 in 3D), which keeps the iteration count of elasticity
   * nearly independent of the mesh size.
   */
  class LinearSolver
  {
  public:
    struct Result
    {
      bool         converged  = false;
      unsigned int iterations = 0;
      double       residual   = 0; ///< final Krylov residual norm
      /// why it failed, if it broke down (empty if it merely ran out of
      /// iterations)
      std::string breakdown;
    };

    explicit LinearSolver(const LinearSolverParameters &parameters);
    ~LinearSolver();

    /// Resolve 'automatic' for a system of @p n_dofs unknowns (global).
    void set_problem_size(const dealii::types::global_dof_index n_dofs);
    /// The solver in use: direct or iterative.
    LinearSolverType type() const;

    /**
     * Set the near null space: each vector a rigid-body mode, with the
     * parallel layout of the matrix. Without it, ML uses the constant
     * modes of each of the @p n_components components.
     */
    void set_rigid_body_modes(
        const std::vector<dealii::TrilinosWrappers::MPI::Vector> &modes);

    /// The sparsity pattern of the matrices to come differs from the last
    /// one's: the direct solver's symbolic factorisation is redone.
    void forget_factorization();

    /// Drop the direct solver's state without freeing it (MUMPS' cleanup
    /// is collective): for a destructor that may run on one rank only
    /// while an error unwinds; the memory goes with the process.
    void abandon_factorization();

    /// Solve A x = b; @p symmetric selects CG over GMRES. An iterative
    /// solve stops at max(@p relative_tolerance, 'Relative tolerance')
    /// times |b|.
    Result solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                 dealii::TrilinosWrappers::MPI::Vector        &x,
                 const dealii::TrilinosWrappers::MPI::Vector  &b,
                 const bool                                    symmetric,
                 const double relative_tolerance = 0);

  private:
    /// MUMPS through Amesos, keeping its symbolic factorisation.
    Result solve_direct(const dealii::TrilinosWrappers::SparseMatrix &A,
                        dealii::TrilinosWrappers::MPI::Vector        &x,
                        const dealii::TrilinosWrappers::MPI::Vector  &b);

    struct DirectState; ///< the Amesos problem and solver
    LinearSolverParameters                             parameters;
    LinearSolverType                                   chosen;
    std::unique_ptr<DirectState>                       direct;
    std::vector<dealii::TrilinosWrappers::MPI::Vector> modes;
    std::unique_ptr<Epetra_MultiVector>                null_space;
  };
} // namespace softgrasp

#endif
