#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
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

  void LinearSolver::abandon_factorization()
  {
    (void)direct.release(); // deliberately not freed, see the header
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
    /// A solution with NaN or Inf entries is a breakdown, not a solution.
    LinearSolver::Result
    finite_or_breakdown(const TrilinosWrappers::MPI::Vector &x,
                        LinearSolver::Result                 result)
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

  LinearSolver::Result
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const bool                            symmetric,
                      const double                          relative_tolerance)
  {
    Result result;
    x = 0;
    if (chosen == LinearSolverType::direct)
      return solve_direct(A, x, b);

    // ML parameters (as deal.II's PreconditionAMG for elliptic problems),
    // with the rigid-body modes as pre-computed near null space.
    Teuchos::ParameterList ml;
    ML_Epetra::SetDefaults("SA", ml);
    ml.set("smoother: type", "Chebyshev");
    ml.set("smoother: sweeps", static_cast<int>(parameters.smoother_sweeps));
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
    TrilinosWrappers::PreconditionAMG preconditioner;
    preconditioner.initialize(A, ml);

    SolverControl control(
        parameters.max_iterations,
        std::max(relative_tolerance, parameters.relative_tolerance) *
            b.l2_norm(),
        false,
        false);
    try
    {
      if (symmetric)
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(A, x, b, preconditioner);
      }
      else
      {
        // Right preconditioning: the stopping test then sees the true
        // residual (N), as CG's does, not the preconditioned one (m).
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
            control,
            SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100,
                                                                       true));
        gmres.solve(A, x, b, preconditioner);
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
} // namespace softgrasp
