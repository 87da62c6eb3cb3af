#include <cmath>
#include <iomanip>
#include <limits>
#include <softgrasp/mechanics/newton_solver.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  NewtonSolver<dim>::NewtonSolver(const NewtonParameters &parameters,
                                  ConditionalOStream     &log)
      : parameters(parameters)
      , log(log)
  {
  }

  template <int dim>
  typename NewtonSolver<dim>::Result
  NewtonSolver<dim>::solve(SolidSystem<dim> &system) const
  {
    /// Ends the solve's element unknowns also when an error unwinds.
    struct Scope
    {
      SolidSystem<dim> &system;
      explicit Scope(SolidSystem<dim> &s)
          : system(s)
      {
        system.begin_newton_solve();
      }
      ~Scope()
      {
        system.end_newton_solve();
      }
    };
    Result result;
    {
      const Scope scope(system);
      result = iterate(system);
    }
    // Collective on every rank, in the normal flow of the run: MUMPS'
    // symbolic factorisation lives for one load step.
    system.release_factorization();
    return result;
  }

  namespace
  {
    /// Why the iterate @p state cannot go on ("" if it can).
    template <typename AssemblyResult>
    std::string failure_of(const AssemblyResult &state)
    {
      std::ostringstream why;
      if (!state.ok)
        why << "an element inverted (J = " << state.failed_J << ") in "
            << state.failed_cell;
      else if (!std::isfinite(state.residual_norm))
        why << "the residual is NaN or Inf (a material or load evaluation "
               "failed)";
      return why.str();
    }

    /// Why the linear solve @p linear failed ("" if it converged).
    std::string failure_of(const LinearSolver::Result &linear)
    {
      std::ostringstream why;
      if (linear.converged)
        return "";
      if (!linear.breakdown.empty())
        why << linear.breakdown;
      else
        why << "the linear solver did not converge in " << linear.iterations
            << " iterations (residual " << linear.residual << ")";
      return why.str();
    }
  } // namespace

  template <int dim>
  double NewtonSolver<dim>::line_search(
      SolidSystem<dim>                          &system,
      const TrilinosWrappers::MPI::Vector       &du,
      const double                               u_scale,
      double                                    &violation,
      typename SolidSystem<dim>::AssemblyResult &state) const
  {
    // Line search on the energy slope s(alpha) = du . r(u + alpha du)
    // (r = f_ext - f_int): the full step is taken when |s(1)| <= 0.8
    // |s(0)|, otherwise alpha moves to the secant root of s; updates that
    // invert an element are halved. Skipped while boundary values are
    // being imposed (then r(u) is not the gradient along du) and with
    // nodal conditions such as contact (then r is not an energy gradient;
    // the semi-smooth Newton method takes full steps).
    system.begin_update();
    const double s0    = system.residual_dot(du);
    const bool   jump  = violation > 1e-12 * u_scale;
    const double r0    = state.residual_norm;
    double       alpha = 1.0;
    // conditions that are neither a potential nor semi-smooth (friction
    // against the current normal force) backtrack until |r| falls (Armijo
    // on |r|), by halvings down to 2^-20
    const bool backtrack = system.backtrack_on_residual() && !jump;
    for (unsigned int ls = 0;; ++ls)
    {
      system.apply_update(du, alpha);
      violation = system.update_constraints();
      state     = system.assemble(false);
      const unsigned int max_steps =
          backtrack ? 20 : parameters.max_line_search_steps;
      if (!state.ok)
      {
        if (ls >= max_steps)
          break;
        alpha *= 0.5;
        continue;
      }
      if (backtrack)
      {
        if (state.residual_norm <= (1 - 1e-4 * alpha) * r0 || ls >= max_steps)
          break;
        alpha *= 0.5;
        continue;
      }
      if (jump || !parameters.line_search || s0 <= 0 ||
          system.has_nodal_conditions() ||
          ls >= parameters.max_line_search_steps)
        break;
      const double s = system.residual_dot(du);
      if (std::abs(s) <= 0.8 * std::abs(s0))
        break;
      const double root = (s0 - s) > 0 ? alpha * s0 / (s0 - s) : 0.5 * alpha;
      const double next = std::min(1.0, std::max(0.1 * alpha, root));
      if (std::abs(next - alpha) < 1e-3)
        break;
      alpha = next;
    }
    return alpha;
  }

  template <int dim>
  double NewtonSolver<dim>::potential_line_search(
      SolidSystem<dim>                          &system,
      const TrilinosWrappers::MPI::Vector       &du,
      double                                    &violation,
      typename SolidSystem<dim>::AssemblyResult &state,
      Result                                    &result) const
  {
    const bool jump =
        violation > 1e-12 * std::max(system.solution().linfty_norm(), 1e-300);
    system.begin_update();
    const double E0 = state.energy;
    // s0 = -dE/dalpha at alpha = 0 (the residual is -grad E)
    const double s0 = system.residual_dot(du);
    // the energy's round-off: sums of terms of the size of E0 and of the
    // work along the full step; at rest (E0 = 0) the work of the absolute
    // force tolerance over the round-off length
    const double floor = parameters.absolute_tolerance *
                         parameters.increment_tolerance * system.length_scale();
    const double       noise = 1e-11 * (std::abs(E0) + std::abs(s0)) + floor;
    const unsigned int max_steps =
        std::max(parameters.max_line_search_steps, 20u);
    double alpha = 1.0;
    // a bracket of the minimiser along du: the slope s = du . r is
    // positive (E falling) at lo and negative (E rising) at hi
    double lo = 0, s_lo = s0, hi = -1, s_hi = 0;
    for (unsigned int ls = 0;; ++ls)
    {
      system.apply_update(du, alpha);
      violation = system.update_constraints();
      state     = system.assemble(false);
      if (!state.ok || !std::isfinite(state.energy))
      {
        if (ls >= max_steps)
          break;
        alpha = hi < 0 ? 0.5 * alpha : 0.5 * (lo + alpha);
        continue;
      }
      // with boundary values still being imposed, E is not minimised along
      // du; without descent the full step stands; so it does where the
      // decrease Newton predicts (s0 / 2) is below the round-off of E,
      // which no comparison of energies can resolve
      const double change = state.energy - E0;
      const bool   trivial =
          jump || !(s0 > 0) || s0 <= 1e-12 * std::abs(E0) + floor;
      const bool   decrease = change <= -1e-4 * alpha * s0 + noise;
      const double s        = trivial ? 0 : system.residual_dot(du);
      // Armijo; within a bracket of the minimiser also near it (|s| <=
      // 0.5 s0): where a sliding node's friction has no curvature along
      // du, the first step that lowers E may be of the size of a slip
      // length and lose most of the decrease the line offers
      const bool near = alpha == 1 || hi < 0 || std::abs(s) <= 0.5 * s0;
      if (trivial || (decrease && near))
        break;
      if (ls >= max_steps)
      {
        if (!decrease)
          ++result.energy_increases;
        break;
      }
      if (s < 0)
        hi = alpha, s_hi = s;
      else if (decrease)
        lo = alpha, s_lo = s;
      if (hi < 0 || (s >= 0 && !decrease))
      {
        // no bracket (or E rose with a falling slope: not convex along
        // du): the minimiser of the quadratic through E0, the slope -s0
        // and E(alpha)
        const double fit =
            0.5 * alpha * alpha * s0 / std::max(change + alpha * s0, 1e-300);
        alpha = std::min(0.5 * alpha, std::max(0.1 * alpha, fit));
        hi    = -1;
        lo = 0, s_lo = s0;
        continue;
      }
      // the secant root of the slope within the bracket, kept off its ends
      const double root = lo + (hi - lo) * s_lo / (s_lo - s_hi);
      alpha             = std::min(hi - 0.05 * (hi - lo),
                       std::max(lo + 0.05 * (hi - lo), root));
    }
    return alpha;
  }

  template <int dim>
  typename NewtonSolver<dim>::Descent NewtonSolver<dim>::make_descent(
      SolidSystem<dim>                          &system,
      TrilinosWrappers::MPI::Vector             &du,
      const double                               tolerance,
      typename SolidSystem<dim>::AssemblyResult &state,
      Result                                    &result) const
  {
    // no descent: the node Hessians' negative part (the rigid surfaces'
    // curvature) outweighs the tissue; solve again with their positive
    // semi-definite projection
    log << ", no descent: node Hessians projected";
    system.project_nodal_hessians(true);
    const auto           projected = system.assemble(true);
    LinearSolver::Result linear;
    if (projected.ok)
      linear = system.solve(du, forcing_term(result.residuals, tolerance));
    system.project_nodal_hessians(false);
    if (!projected.ok)
    {
      state = projected;
      log << std::endl;
      return Descent::reassemble;
    }
    result.linear_iterations += linear.iterations;
    result.failure = failure_of(linear);
    if (!result.failure.empty())
    {
      log << std::endl;
      return Descent::failed;
    }
    if (!(system.residual_dot(du) > 0))
    {
      // still no descent (the tissue's own tangent is indefinite): the
      // reversed direction descends, and the line search on the potential
      // keeps the step from raising it
      ++result.non_descent;
      du *= -1.0;
      log << ", reversed";
    }
    return Descent::ready;
  }

  template <int dim>
  typename NewtonSolver<dim>::Descent
  NewtonSolver<dim>::direction(SolidSystem<dim>              &system,
                               TrilinosWrappers::MPI::Vector &du,
                               const double                   tolerance,
                               const bool                     descend,
                               const bool                     confirm,
                               typename SolidSystem<dim>::AssemblyResult &state,
                               Result &result) const
  {
    const auto tangent_state = system.assemble(true);
    if (!tangent_state.ok)
    {
      state = tangent_state;
      return Descent::reassemble; // reported at the top of the loop
    }
    // a direction that only confirms convergence by its decrement need
    // not be accurate (an iterative solve to 0.1 of the residual)
    const auto linear = system.solve(
        du, confirm ? 0.1 : forcing_term(result.residuals, tolerance));
    result.linear_iterations += linear.iterations;
    log << ", " << linear.iterations << " linear its";
    result.failure = failure_of(linear);
    if (!result.failure.empty())
    {
      log << std::endl;
      return Descent::failed;
    }
    // (a direction that only confirms convergence converges if it does
    // not descend: its decrement is not positive)
    if (descend && !confirm && !(system.residual_dot(du) > 0))
      return make_descent(system, du, tolerance, state, result);
    return Descent::ready;
  }

  template <int dim>
  void NewtonSolver<dim>::log_iterate(
      const SolidSystem<dim>                          &system,
      const unsigned int                               it,
      const typename SolidSystem<dim>::AssemblyResult &state,
      const double                                     tolerance,
      const double                                     violation,
      const bool                                       potential) const
  {
    log << "    Newton " << std::setw(2) << it << ": |r| = " << std::scientific
        << std::setprecision(3) << state.residual_norm;
    if (potential)
      log << " (largest " << state.residual_max << ", tolerance " << tolerance
          << ")";
    else
      log << " (tolerance " << tolerance << ")";
    log << ", |g - u| = " << violation << std::defaultfloat;
    if (system.has_nodal_conditions())
      log << ", " << system.nodal_conditions_report();
  }

  template <int dim>
  typename NewtonSolver<dim>::Result
  NewtonSolver<dim>::iterate(SolidSystem<dim> &system) const
  {
    Result                        result;
    auto                         &u         = system.solution();
    double                        violation = system.update_constraints();
    auto                          state     = system.assemble(false);
    TrilinosWrappers::MPI::Vector du;
    double                        last_increment = 0; // max |alpha du| (m)
    // a potential's minimisation: line search on it, converged on the
    // largest residual entry and the Newton decrement du . r (J) of the
    // last full step or, failing that, of a direction at the iterate
    const bool potential = system.has_nodal_conditions() &&
                           system.has_potential() && parameters.line_search;
    const double E_start        = state.energy;
    double       last_decrement = std::numeric_limits<double>::infinity();

    for (unsigned int it = 0;; ++it)
    {
      if (state.ok)
        result.residuals.push_back(state.residual_norm);
      result.failure = failure_of(state);
      if (!result.failure.empty())
        return result;
      const double tolerance =
          std::max(parameters.relative_tolerance * state.force_scale,
                   parameters.absolute_tolerance);
      const double decrement_tolerance =
          parameters.relative_tolerance *
          (std::abs(state.energy) + std::abs(E_start - state.energy));
      const bool imposed =
          violation <= 1e-12 * std::max(u.linfty_norm(), 1e-300);
      log_iterate(system, it, state, tolerance, violation, potential);
      const bool increment_small =
          it > 0 && last_increment <=
                        parameters.increment_tolerance * system.length_scale();
      const bool small = potential ? state.residual_max <= tolerance &&
                                         last_decrement <= decrement_tolerance
                                   : state.residual_norm <= tolerance;
      if (imposed && (small || increment_small))
        return converged(it, small, result);
      // with a potential, a small residual after a damped step (or none)
      // is confirmed by the decrement at the iterate
      const bool confirm =
          potential && imposed && state.residual_max <= tolerance;
      if (it == parameters.max_iterations && !confirm)
        return fail_at_limit(system, it, result);
      const Descent descent = direction(
          system, du, tolerance, potential && imposed, confirm, state, result);
      if (descent == Descent::reassemble)
        continue;
      if (descent == Descent::failed)
        return result;
      if (potential)
      {
        last_decrement = system.residual_dot(du);
        log << ", decrement " << std::scientific << std::setprecision(3)
            << last_decrement << std::defaultfloat;
        if (confirm && last_decrement <= decrement_tolerance)
          return converged(it, true, result);
        if (it == parameters.max_iterations)
          return fail_at_limit(system, it, result);
      }
      const double alpha =
          potential
              ? potential_line_search(system, du, violation, state, result)
              : line_search(system,
                            du,
                            std::max(u.linfty_norm(), 1e-300),
                            violation,
                            state);
      last_increment = alpha * du.linfty_norm();
      if (alpha < 1)
      {
        log << ", line search alpha = " << alpha;
        last_decrement = std::numeric_limits<double>::infinity();
      }
      log << std::endl;
      result.iterations = it + 1;
    }
  }

  template <int dim>
  typename NewtonSolver<dim>::Result NewtonSolver<dim>::converged(
      const unsigned int iterations, const bool small, Result &result) const
  {
    log << (small ? "  converged" : "  converged (update at round-off)")
        << std::endl;
    result.converged  = true;
    result.iterations = iterations;
    return result;
  }

  template <int dim>
  typename NewtonSolver<dim>::Result
  NewtonSolver<dim>::fail_at_limit(const SolidSystem<dim> &system,
                                   const unsigned int      iterations,
                                   Result                 &result) const
  {
    log << std::endl;
    result.iterations = iterations;
    result.failure    = "no convergence in " + std::to_string(iterations) +
                     " Newton iterations (" +
                     system.describe_largest_residual() +
                     "); 'Newton/Maximum iterations' allows more";
    return result;
  }

  template <int dim>
  double NewtonSolver<dim>::forcing_term(const std::vector<double> &residuals,
                                         const double tolerance) const
  {
    // Eisenstat and Walker (1996), choice 2 (gamma = 0.9, alpha = 2), at
    // most 1e-4: loose while Newton is far from the solution, tight where
    // it converges fast; never tighter than reaching a tenth of the Newton
    // tolerance needs. The linear solver's own tolerance is the floor.
    if (!parameters.inexact_linear_solves)
      return 0;
    const double eta_max = 1e-4;
    const double r       = residuals.back();
    double       eta     = eta_max;
    if (residuals.size() > 1)
    {
      const double ratio = r / residuals[residuals.size() - 2];
      eta                = std::min(eta_max, 0.9 * ratio * ratio);
    }
    if (r > 0)
      eta = std::max(eta, std::min(eta_max, 0.1 * tolerance / r));
    return eta;
  }

  template class NewtonSolver<2>;
  template class NewtonSolver<3>;
} // namespace softgrasp
