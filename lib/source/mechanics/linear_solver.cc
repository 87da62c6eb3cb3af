#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <limits>
#include <ml_MultiLevelPreconditioner.h>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/mechanics/linear_solver.h>

namespace softgrasp
{
  using namespace dealii;

  LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
      : parameters(parameters)
      , chosen(parameters.resolve(0))
  {
  }

  /// The linear problem MUMPS factorised last, and the solver that holds
  /// its symbolic factorisation (for the matrix object @p matrix).
  struct LinearSolver::DirectState
  {
    Epetra_LinearProblem               problem;
    std::unique_ptr<Amesos_BaseSolver> solver;
    const Epetra_CrsMatrix            *matrix = nullptr;
  };

  LinearSolver::~LinearSolver()
  {
    abandon_factorization(); // never a collective call in a destructor
  }

  void LinearSolver::forget_factorization()
  {
    direct.reset();
  }

  void LinearSolver::forget_matrix()
  {
    direct.reset();
    amg.reset();
    amg_matrix = nullptr;
    amg_stale  = true;
  }

  void LinearSolver::abandon_factorization()
  {
    (void)direct.release(); // deliberately not freed, see the header
    amg.reset();            // not collective
    amg_matrix = nullptr;
  }

  void LinearSolver::set_problem_size(const types::global_dof_index n_dofs)
  {
    chosen = parameters.resolve(n_dofs);
  }

  LinearSolverType LinearSolver::type() const
  {
    return chosen;
  }

  void LinearSolver::set_rigid_body_modes(
      const std::vector<TrilinosWrappers::MPI::Vector> &rigid_body_modes)
  {
    modes = rigid_body_modes;
    null_space.reset();
  }

  namespace
  {
    /**
     * SolverControl that also fails when the best residual so far has not
     * fallen by 10 % over the last 200 iterations: a Krylov solve on an
     * indefinite tangent (e.g. at a poor Newton iterate) can stagnate for
     * thousands of iterations, and the load step is better cut back at
     * once.
     */
    class StagnationControl : public SolverControl
    {
    public:
      StagnationControl(const unsigned int max_steps, const double tolerance)
          : SolverControl(max_steps, tolerance, false, false)
      {
      }
      State check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        if (state != iterate)
          return state;
        if (value < 0.9 * best)
        {
          best      = value;
          best_step = step;
        }
        if (step > best_step + window)
        {
          lcheck = failure;
          return failure;
        }
        return iterate;
      }

    private:
      static constexpr unsigned int window = 200;
      double                        best   = std::numeric_limits<double>::max();
      unsigned int                  best_step = 0;
    };

    /// A solution with NaN or Inf entries is a breakdown, not a solution.
    template <typename VectorType>
    LinearSolver::Result finite_or_breakdown(const VectorType    &x,
                                             LinearSolver::Result result)
    {
      if (result.converged && !std::isfinite(x.l2_norm()))
      {
        result.converged = false;
        result.breakdown = "the linear solver returned NaN or Inf values";
      }
      return result;
    }
  } // namespace

  LinearSolver::Result
  LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b)
  {
    // MUMPS (multifrontal, nested-dissection ordering) scales far better
    // than KLU on 3D meshes; Debian's Trilinos is built with it.
    Result result;
    result.iterations              = 1;
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    if (!parameters.reuse_symbolic_factorization ||
        (direct && direct->matrix != &matrix))
      direct.reset();
    int status = 0;
    if (!direct)
    {
      direct = std::make_unique<DirectState>();
      direct->problem.SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix));
      direct->matrix = &matrix;
      Amesos factory;
      direct->solver.reset(factory.Create("Amesos_Mumps", direct->problem));
      AssertThrow(direct->solver != nullptr,
                  ExcMessage("Trilinos was built without Amesos_Mumps."));
      status = direct->solver->SymbolicFactorization();
    }
    direct->problem.SetLHS(&x.trilinos_vector());
    direct->problem.SetRHS(
        const_cast<Epetra_MultiVector *>(&b.trilinos_vector()));
    if (status == 0)
      status = direct->solver->NumericFactorization();
    if (status == 0)
      status = direct->solver->Solve();
    // x and b belong to the caller: keep no pointers to them.
    direct->problem.SetLHS(static_cast<Epetra_MultiVector *>(nullptr));
    direct->problem.SetRHS(static_cast<Epetra_MultiVector *>(nullptr));
    if (status != 0)
    {
      // A singular or otherwise failed factorisation (MUMPS reports it on
      // every rank): the Newton step fails and the load step is cut back.
      direct.reset();
      result.breakdown = "the direct solver (MUMPS) failed with Amesos "
                         "error " +
                         std::to_string(status) +
                         " (singular or badly scaled matrix)";
      return result;
    }
    result.converged = true;
    return finite_or_breakdown(x, result);
  }

  void LinearSolver::initialize_amg(
      const TrilinosWrappers::SparseMatrix &A,
      const bool                            symmetric,
      TrilinosWrappers::PreconditionAMG    &preconditioner)
  {
    // ML parameters (as deal.II's PreconditionAMG for elliptic problems),
    // with the rigid-body modes as pre-computed near null space and the
    // smoother of the Krylov method (symmetric for CG).
    Teuchos::ParameterList ml;
    ML_Epetra::SetDefaults("SA", ml);
    const AmgSmoother smoother = parameters.smoother_for(symmetric);
    ml.set("smoother: type", LinearSolverParameters::smoother_name(smoother));
    ml.set("smoother: sweeps",
           static_cast<int>(parameters.smoother_sweeps_for(smoother)));
    ml.set("aggregation: type", "Uncoupled");
    ml.set("aggregation: threshold", parameters.aggregation_threshold);
    ml.set("coarse: type", "Amesos-KLU");
    ml.set("coarse: max size", 2000);
    ml.set("ML output", 0);
    if (!modes.empty())
    {
      const Epetra_Map &map = A.trilinos_matrix().DomainMap();
      null_space = std::make_unique<Epetra_MultiVector>(map, modes.size());
      for (unsigned int m = 0; m < modes.size(); ++m)
        for (int i = 0; i < map.NumMyElements(); ++i)
          (*null_space)[m][i] = modes[m][map.GID(i)];
      ml.set("null space: type", "pre-computed");
      ml.set("null space: dimension", null_space->NumVectors());
      ml.set("null space: vectors", null_space->Values());
    }
    preconditioner.initialize(A, ml);
  }

  template <typename Attempt>
  LinearSolver::Result
  LinearSolver::with_amg(const TrilinosWrappers::SparseMatrix &A,
                         const bool                            symmetric,
                         const Attempt                        &attempt)
  {
    if (!parameters.reuse_amg) // a new AMG, freed after the solve
    {
      TrilinosWrappers::PreconditionAMG preconditioner;
      initialize_amg(A, symmetric, preconditioner);
      return attempt(preconditioner);
    }
    // A kept AMG refers to its matrix object: a different object, or a
    // solve that needs another smoother, needs a new one.
    if (amg_matrix != static_cast<const void *>(&A.trilinos_matrix()) ||
        parameters.smoother_for(symmetric) != amg_smoother)
      amg_stale = true;
    // Times are maxima over the ranks, so that every rank decides alike.
    const MPI_Comm comm = A.get_mpi_communicator();
    for (unsigned int pass = 0;; ++pass)
    {
      const bool fresh = amg_stale || !amg;
      if (fresh)
      {
        Timer setup;
        amg.reset(); // before the new one is built: one hierarchy in memory
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        initialize_amg(A, symmetric, *amg);
        amg_matrix        = &A.trilinos_matrix();
        amg_smoother      = parameters.smoother_for(symmetric);
        amg_stale         = false;
        amg_setup_seconds = Utilities::MPI::max(setup.wall_time(), comm);
      }
      Timer        solve;
      const Result result  = attempt(*amg);
      const double seconds = Utilities::MPI::max(solve.wall_time(), comm);
      if (!result.converged)
        amg_stale = true;
      else if (fresh)
      {
        amg_first_iterations  = result.iterations;
        amg_iteration_seconds = seconds / std::max(result.iterations, 1u);
      }
      else if ((double(result.iterations) - amg_first_iterations) *
                   amg_iteration_seconds >
               amg_setup_seconds)
        amg_stale = true; // its extra iterations cost more than a new one
      if (result.converged || fresh || pass > 0)
        return result;
    }
  }

  template <typename Operator, typename Preconditioner, typename VectorType>
  LinearSolver::Result
  LinearSolver::iterate(const Operator       &op,
                        const Preconditioner &preconditioner,
                        VectorType           &x,
                        const VectorType     &b,
                        const bool            symmetric,
                        const double          tolerance) const
  {
    Result            result;
    StagnationControl control(parameters.max_iterations, tolerance);
    try
    {
      if (symmetric)
      {
        SolverCG<VectorType> cg(control);
        cg.solve(op, x, b, preconditioner);
      }
      else
      {
        // Right preconditioning: the stopping test then sees the true
        // residual (N), as CG's does, not the preconditioned one (m).
        SolverGMRES<VectorType> gmres(
            control,
            typename SolverGMRES<VectorType>::AdditionalData(100, true));
        gmres.solve(op, x, b, preconditioner);
      }
      result.converged = true;
    }
    catch (const SolverControl::NoConvergence &)
    {
      result.converged = false;
    }
    catch (const std::exception &e)
    {
      // e.g. a breakdown of CG on an indefinite matrix
      result.converged = false;
      result.breakdown = "the iterative solver broke down: " + error_message(e);
    }
    result.iterations = control.last_step();
    result.residual   = control.last_value();
    return finite_or_breakdown(x, result);
  }

  LinearSolver::Result
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const bool                            symmetric,
                      const double                          relative_tolerance)
  {
    x = 0;
    if (chosen == LinearSolverType::direct)
      return solve_direct(A, x, b);
    const double tolerance =
        std::max(relative_tolerance, parameters.relative_tolerance) *
        b.l2_norm();
    return with_amg(A,
                    symmetric,
                    [&](const TrilinosWrappers::PreconditionAMG &amg)
                    {
                      x = 0;
                      return iterate(A, amg, x, b, symmetric, tolerance);
                    });
  }

  namespace
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;
    using Block       = VolumetricOperator::PressureBlock;

    /// The saddle point operator [A G^T; Sigma G  -Sigma C]
    /// (VolumetricOperator).
    class SaddlePointOperator
    {
    public:
      SaddlePointOperator(const TrilinosWrappers::SparseMatrix &A,
                          const VolumetricOperator             &V)
          : A(A)
          , V(V)
      {
      }
      void vmult(BlockVector &dst, const BlockVector &src) const
      {
        scratch.reinit(src, true);
        A.vmult(dst.block(0), src.block(0));
        V.gradient(scratch.block(0), src.block(1));
        dst.block(0) += scratch.block(0);
        V.divergence(scratch.block(1), src.block(0));
        V.multiply(dst.block(1), scratch.block(1), Block::scaled_stiffness);
        V.multiply(scratch.block(1), src.block(1), Block::scaled_compliance);
        dst.block(1) -= scratch.block(1);
      }

    private:
      const TrilinosWrappers::SparseMatrix &A;
      const VolumetricOperator             &V;
      mutable BlockVector                   scratch;
    };

    /// The block triangular preconditioner [A G^T; 0 -Sigma S]^-1 with one
    /// AMG cycle for A^-1 and the element-wise S^-1.
    class BlockTriangularPreconditioner
    {
    public:
      BlockTriangularPreconditioner(
          const TrilinosWrappers::PreconditionAMG &amg,
          const VolumetricOperator                &V)
          : amg(amg)
          , V(V)
      {
      }
      void vmult(BlockVector &dst, const BlockVector &src) const
      {
        u.reinit(src.block(0), true);
        V.multiply(dst.block(1), src.block(1), Block::preconditioner);
        dst.block(1) *= -1;
        V.gradient(u, dst.block(1));
        u.sadd(-1, 1, src.block(0));
        amg.vmult(dst.block(0), u);
      }

    private:
      const TrilinosWrappers::PreconditionAMG &amg;
      const VolumetricOperator                &V;
      mutable TrilinosWrappers::MPI::Vector    u;
    };

    /// |b - (A + G^T D G) x|, the residual of the condensed system (N).
    double condensed_residual(const TrilinosWrappers::SparseMatrix &A,
                              const VolumetricOperator             &V,
                              const TrilinosWrappers::MPI::Vector  &x,
                              const TrilinosWrappers::MPI::Vector  &b,
                              const IndexSet &pressure_dofs)
    {
      TrilinosWrappers::MPI::Vector r(b), Ax(b),
          p(pressure_dofs, b.get_mpi_communicator()), Dp(p);
      A.vmult(Ax, x);
      r -= Ax;
      V.divergence(p, x);
      V.multiply(Dp, p, Block::stiffness);
      V.gradient(Ax, Dp);
      r -= Ax;
      return r.l2_norm();
    }
  } // namespace

  LinearSolver::Result
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                      const VolumetricOperator             &volumetric,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const bool /*symmetric*/,
                      const double relative_tolerance)
  {
    AssertThrow(chosen == LinearSolverType::iterative,
                ExcMessage("The saddle point solve is for the iterative "
                           "solver only."));
    const MPI_Comm comm = b.get_mpi_communicator();
    BlockVector    X(std::vector<IndexSet>{b.locally_owned_elements(),
                                           volumetric.pressure_dofs()},
                  comm);
    BlockVector    B(X);
    B.block(0) = b;
    const SaddlePointOperator op(A, volumetric);

    // The condensed residual is what Newton needs; the saddle point
    // residual bounds it only up to kappa/mu in the pressure rows, so the
    // solve is tightened until the condensed residual is small enough.
    const double target =
        std::max(relative_tolerance, parameters.relative_tolerance) *
        b.l2_norm();
    const auto attempt = [&](const TrilinosWrappers::PreconditionAMG &amg)
    {
      const BlockTriangularPreconditioner preconditioner(amg, volumetric);
      X                = 0;
      double tolerance = target;
      Result result;
      for (unsigned int round = 0; round < 4; ++round)
      {
        const Result pass = iterate(op, preconditioner, X, B, false, tolerance);
        result.iterations += pass.iterations;
        result.breakdown = pass.breakdown;
        x                = X.block(0);
        result.residual =
            condensed_residual(A, volumetric, x, b, volumetric.pressure_dofs());
        result.converged = pass.converged && result.residual <= target;
        if (result.converged || !pass.converged)
          break;
        tolerance *= 0.5 * target / result.residual;
      }
      return finite_or_breakdown(x, result);
    };
    return with_amg(A, false, attempt); // GMRES
  }
} // namespace softgrasp
