#ifndef softgrasp_mechanics_linear_solver_h
#define softgrasp_mechanics_linear_solver_h

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
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
   * The volumetric coupling of a mixed (u-p-J) tangent with element-local
   * pressure modes p. The condensed tangent K = A + G^T D G (D = C^-1)
   * is the Schur complement of the saddle point system
   *   [A  G^T] [du]   [b]
   *   [G  -C ] [ p] = [0],
   * whose entries stay bounded as the bulk modulus grows (C ~ M/kappa -> 0)
   * while K's do not. The iterative solver therefore solves the saddle
   * point system with the block triangular preconditioner
   *   [A  G^T]^-1      AMG on A, and S = C + G A^-1 G^T approximated
   *   [0  -S ]         element by element by C + M/mu,
   * whose iterations are independent of the bulk modulus and the mesh
   * (Elman, Silvester and Wathen, Finite Elements and Fast Iterative
   * Solvers, ch. 4). Pressure vectors hold n_p entries per locally owned
   * cell (pressure_dofs()); displacement vectors are the condensed ones of
   * the tangent (constraints applied as in A).
   */
  class VolumetricOperator
  {
  public:
    /// The element-block-diagonal pressure operators. The pressure rows of
    /// the saddle point system are scaled by Sigma = h^2 D (h^3 the element
    /// volume), which gives their residual the unit N and bounds the
    /// condensed residual by the saddle point one.
    enum class PressureBlock
    {
      stiffness,         ///< D (Pa/m^3)
      scaled_stiffness,  ///< Sigma = h^2 D (Pa/m)
      scaled_compliance, ///< Sigma C = h^2 I (m^2)
      preconditioner     ///< (Sigma (C + M/mu))^-1 (1/m^2)
    };

    virtual ~VolumetricOperator() = default;
    /// The pressure unknowns owned by this process (contiguous).
    virtual const dealii::IndexSet &pressure_dofs() const = 0;
    /// p = G u (m^3 per m of u).
    virtual void
    divergence(dealii::TrilinosWrappers::MPI::Vector       &p,
               const dealii::TrilinosWrappers::MPI::Vector &u) const = 0;
    /// u = G^T p, condensed (N per Pa of p).
    virtual void
    gradient(dealii::TrilinosWrappers::MPI::Vector       &u,
             const dealii::TrilinosWrappers::MPI::Vector &p) const = 0;
    /// dst = X src for the pressure block X.
    virtual void multiply(dealii::TrilinosWrappers::MPI::Vector       &dst,
                          const dealii::TrilinosWrappers::MPI::Vector &src,
                          const PressureBlock block) const = 0;
  };

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

    /// Drop the direct solver's symbolic factorisation (redone at the
    /// next solve); the kept AMG stays.
    void forget_factorization();

    /// The matrix object is about to be replaced (new sparsity pattern):
    /// drop everything that refers to the old one (factorisation, AMG).
    void forget_matrix();

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

    /// Solve (A + G^T D G) x = b iteratively through the saddle point
    /// system of @p volumetric, with its block preconditioner.
    Result solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                 const VolumetricOperator                     &volumetric,
                 dealii::TrilinosWrappers::MPI::Vector        &x,
                 const dealii::TrilinosWrappers::MPI::Vector  &b,
                 const bool                                    symmetric,
                 const double relative_tolerance = 0);

  private:
    /// Set @p preconditioner up as ML AMG of @p A with the near null space,
    /// with a smoother fit for CG if @p symmetric, else for GMRES.
    void
    initialize_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
                   const bool                                    symmetric,
                   dealii::TrilinosWrappers::PreconditionAMG &preconditioner);

    /// Run @p attempt (a solve, from x = 0) with the AMG of @p A: the kept
    /// one while it serves ('Reuse AMG'), else a new one; a failure with a
    /// kept AMG is repeated once with a new one. @p symmetric: the attempt
    /// runs CG.
    template <typename Attempt>
    Result with_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
                    const bool                                    symmetric,
                    const Attempt                                &attempt);

    /// CG or GMRES on @p op with @p preconditioner, stopping at residual
    /// norm @p tolerance.
    template <typename Operator, typename Preconditioner, typename VectorType>
    Result iterate(const Operator       &op,
                   const Preconditioner &preconditioner,
                   VectorType           &x,
                   const VectorType     &b,
                   const bool            symmetric,
                   const double          tolerance) const;

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
    /// The AMG kept from earlier solves, the matrix it was built for (it
    /// holds a pointer to it), the iterations and the time per iteration
    /// (s) of its first solve, the time it took to build (s), and whether
    /// the next solve needs a new one.
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    const void  *amg_matrix            = nullptr;
    AmgSmoother  amg_smoother          = AmgSmoother::chebyshev;
    unsigned int amg_first_iterations  = 0;
    double       amg_iteration_seconds = 0;
    double       amg_setup_seconds     = 0;
    bool         amg_stale             = true;
  };
} // namespace softgrasp

#endif
