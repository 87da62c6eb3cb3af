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
   * of its boundary conditions, with a line search on the energy slope
   * that also halves updates which would invert an element.
   *
   * Converged when the boundary values are reached and
   *   |r| <= max(relative tolerance * force scale, absolute tolerance),
   * where r is f_int - f_ext on the free dofs and the force scale is
   * max(|f_int|, |f_ext|) over all dofs (so reactions count).
   *
   * When the step minimises a potential E (nodal conditions that are one,
   * SolidSystem::has_potential(); 'Contact/Enforcement = incremental
   * potential') the line search is on E (potential_line_search()) and the
   * solve is converged when the largest residual entry is within that
   * tolerance and the Newton decrement du . r = du^T K du (twice the
   * decrease of E that Newton predicts) at most the relative tolerance
   * times |E| + |E_start - E| (E_start: at the start of the solve); the
   * log shows both. The decrement is that of the last step if it was a
   * full one; otherwise a direction is solved at the iterate (loosely,
   * only to confirm) and taken if its decrement is not small.
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
      /// With a potential (SolidSystem::has_potential() and nodal
      /// conditions): the accepted updates along which the potential did
      /// not decrease (beyond round-off), and the Newton directions that
      /// did not descend even with the node Hessians projected to positive
      /// semi-definite (they are reversed, then line-searched).
      unsigned int energy_increases = 0;
      unsigned int non_descent      = 0;
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

    /// What make_descent() left: a direction for the line search, a
    /// tangent that could not be assembled (iterate again from the state),
    /// or a failed linear solve (Result::failure says why).
    enum class Descent
    {
      ready,
      reassemble,
      failed
    };

    /**
     * The Newton direction @p du at the last assembled state: the tangent
     * assembled and solved (to the forcing term of @p tolerance, N); with
     * @p descend, a direction that does not descend on the potential is
     * made one (make_descent()); with @p confirm, a loose solve that only
     * confirms convergence by the decrement.
     */
    Descent direction(SolidSystem<dim>                          &system,
                      dealii::TrilinosWrappers::MPI::Vector     &du,
                      const double                               tolerance,
                      const bool                                 descend,
                      const bool                                 confirm,
                      typename SolidSystem<dim>::AssemblyResult &state,
                      Result                                    &result) const;

    /// The line of iterate @p it in the Newton log (without its end).
    void log_iterate(const SolidSystem<dim>                          &system,
                     const unsigned int                               it,
                     const typename SolidSystem<dim>::AssemblyResult &state,
                     const double                                     tolerance,
                     const double                                     violation,
                     const bool potential) const;

    /// @p result converged after @p iterations (@p small: by the
    /// tolerances, otherwise by an update at round-off).
    Result converged(const unsigned int iterations,
                     const bool         small,
                     Result            &result) const;

    /// @p result after 'Newton/Maximum iterations' without convergence,
    /// naming the largest residual.
    Result fail_at_limit(const SolidSystem<dim> &system,
                         const unsigned int      iterations,
                         Result                 &result) const;

    /**
     * A Newton direction @p du that does not descend on the potential:
     * solved again with the nodal conditions' Hessians projected to
     * positive semi-definite and, if that does not descend either,
     * reversed (counted in Result::non_descent). @p tolerance is Newton's.
     */
    Descent make_descent(SolidSystem<dim>                          &system,
                         dealii::TrilinosWrappers::MPI::Vector     &du,
                         const double                               tolerance,
                         typename SolidSystem<dim>::AssemblyResult &state,
                         Result &result) const;

    /**
     * The line search of a potential's minimisation: backtracking from the
     * full step until the potential E decreases by at least 1e-4 alpha
     * times its slope (Armijo), the step cut by a safeguarded quadratic
     * fit; updates that invert an element are halved. The full step stands
     * where the predicted decrease is below 1e-12 |E| plus the work of
     * 'Absolute tolerance' over 'Increment tolerance' times the domain
     * size (round-off). Updates @p
     * violation and @p state (whose energy is E at the start) and counts the
     * accepted updates that did not decrease E in @p result.
     */
    double
    potential_line_search(SolidSystem<dim>                            &system,
                          const dealii::TrilinosWrappers::MPI::Vector &du,
                          double                                    &violation,
                          typename SolidSystem<dim>::AssemblyResult &state,
                          Result &result) const;

    const NewtonParameters      parameters;
    dealii::ConditionalOStream &log;
  };
} // namespace softgrasp

#endif
