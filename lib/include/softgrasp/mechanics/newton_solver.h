#ifndef softgrasp_mechanics_newton_solver_h
#define softgrasp_mechanics_newton_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Newton-Raphson for the equilibrium of a SolidSystem at the current time
   * of its boundary conditions, with a backtracking line search on the
   * residual norm that also halves updates which would invert an element.
   *
   * Converged when the boundary values are reached and
   *   |r| <= max(relative tolerance * force scale, absolute tolerance),
   * where r is f_int - f_ext on the free dofs and the force scale is
   * max(|f_int|, |f_ext|) over all dofs (so reactions count).
   *
   * On failure the system holds the last iterate; the caller restores the
   * last converged state and cuts the step back.
   */
  template <int dim> class NewtonSolver
  {
  public:
    struct Result
    {
      bool                converged         = false;
      unsigned int        iterations        = 0;
      unsigned int        linear_iterations = 0;
      std::vector<double> residuals; ///< |r| per iteration (N)
      std::string         failure;   ///< why, if !converged
    };

    NewtonSolver(const NewtonParameters     &parameters,
                 dealii::ConditionalOStream &log);

    Result solve(SolidSystem<dim> &system) const;

  private:
    /// The iterations of solve().
    Result iterate(SolidSystem<dim> &system) const;
    /// Relative tolerance of the next iterative linear solve (inexact
    /// Newton) from the residual norms so far and the Newton tolerance (N).
    double forcing_term(const std::vector<double> &residuals,
                        const double               tolerance) const;
    /**
     * Moves the solution along @p du: the full step, or a step cut by the
     * line search (see the .cc); updates @p violation and @p state to the
     * new iterate and returns the step length alpha.
     */
    double line_search(SolidSystem<dim>                            &system,
                       const dealii::TrilinosWrappers::MPI::Vector &du,
                       const double                                 u_scale,
                       double                                      &violation,
                       typename SolidSystem<dim>::AssemblyResult &state) const;

    const NewtonParameters      parameters;
    dealii::ConditionalOStream &log;
  };
} // namespace softgrasp

#endif
