#ifndef softgrasp_explicit_central_difference_h
#define softgrasp_explicit_central_difference_h

#include <deal.II/base/index_set.h>
#include <functional>
#include <softgrasp/explicit/internal_force_operator.h>
#include <vector>

namespace softgrasp
{
  /**
   * Central-difference (explicit) time integration of
   *   M a = f_ext - f_int(u) - beta K v + f_c - alpha M v
   * with the diagonal mass M of compute_lumped_mass():
   *   v^{n+1/2} = v^{n-1/2} + h a^n,   u^{n+1} = u^n + dt v^{n+1/2},
   * h = (dt_{n-1} + dt_n)/2, started by v^{1/2} = v^0 + dt/2 a^0. Dofs in
   * the fixed set move as prescribed (their acceleration is not computed;
   * the internal force there is the reaction). alpha (1/s) is optional
   * mass-proportional damping, beta (s) optional stiffness-proportional
   * damping; K v is the rate of the internal forces over the step,
   * (f_int(u^{n+1}) - f_int(u^n))/dt_n, applied with a^{n+1} as the mass
   * damping is (both lag half a step; the stable step of a mode of
   * frequency omega is then 2/omega (sqrt(1 + xi^2) - xi), with
   * xi = beta omega/2). Contact forces f_c enter as kinematic
   * corrections of the predicted u^{n+1} (constrain, forward-increment
   * Lagrange multipliers): a correction du of a free dof is the force
   * M du / (dt h) at t^n.
   *
   * Energy bookkeeping per step (J; J/m in 2D), with the discrete identity
   * of the scheme: the kinetic energy K = 1/2 v.M.v at the last half step
   * changes by the power of the forces at t^n, F^n . (v^{n-1/2} +
   * v^{n+1/2})/2, times h. The internal (strain) energy is reported at the
   * same half step, U = (U^n + U^{n+1})/2; the work of the external forces,
   * of the supports (the reactions f_int - f_ext at fixed dofs) and of
   * contact, and the energy dissipated by damping, are accumulated in the
   * same way. The balance error is
   *   |K + U - K0 - U0 - W_ext - W_supports - W_contact + D|
   * over the largest of these terms. Contact work is negative: frictional
   * sliding and the (perfectly plastic) arrest of nodes hitting a body
   * dissipate.
   */
  template <int dim> class CentralDifference
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    struct Energies
    {
      double kinetic = 0, internal = 0, external_work = 0, support_work = 0,
             contact_work = 0, damping = 0;
      double balance_error = 0; ///< relative, see the class documentation
      /// The signed relative imbalance where it is positive: energy the
      /// integration created (an unstable step); 0 where energy was lost.
      double created = 0;
    };

    /// Why step() refused a step.
    enum class StepResult
    {
      ok,
      not_finite, ///< NaN or infinite displacement/acceleration
      inverted,   ///< det F <= 0 at a quadrature point
      unbalanced  ///< energy balance error above the limit
    };

    /// @p mass from compute_lumped_mass(); @p fixed: locally owned dofs
    /// whose displacement is prescribed by prescribe() (may be empty).
    CentralDifference(const InternalForceOperator<dim> &force,
                      const VectorType                 &mass,
                      const dealii::IndexSet           &fixed,
                      const double                      mass_damping      = 0,
                      const double                      stiffness_damping = 0);

    /// Stiffness-proportional damping beta (s) from the next step on.
    void set_stiffness_damping(const double beta);

    /// Sets the displacement of the fixed dofs at time t (default: zero).
    std::function<void(const double t, VectorType &u)> prescribe;
    /// Adds external forces (N) at time t to f (default: none).
    std::function<void(const double t, const VectorType &u, VectorType &f)>
        external_forces;
    /**
     * Corrects the predicted displacement u^{n+1} for kinematic
     * constraints (contact): called with t^{n+1}, dt, h, u^n and u^{n+1};
     * may change free dofs only (default: none).
     */
    std::function<void(const double      t,
                       const double      dt,
                       const double      h,
                       const VectorType &u_old,
                       VectorType       &u)>
        constrain;

    /**
     * The locally owned dofs (global indices) that constrain() may change
     * (contact: the slave nodes' dofs). With them, a step copies and
     * compares only these dofs around constrain() instead of whole
     * vectors; without (the default), every dof is compared.
     */
    void set_constrained_dofs(
        const std::vector<dealii::types::global_dof_index> &dofs);

    /**
     * Refuse steps that create energy beyond @p limit (Energies::created:
     * an unstable integration gains energy; the impact losses of nodes
     * arrested by a rigid body are dissipation and are not refused), from
     * the 50th step and from time @p active_from (s) on: before, the
     * energies are too small for a relative measure, while an unstable
     * step grows exponentially and is caught by the non-finite and
     * inversion checks, which act from the first step. A step is refused
     * only once the created energy has stayed above the limit and kept
     * growing for balance_patience steps in a row: an instability grows
     * step after step, while the jump of the relative measure at a rigid
     * body's first touch (all energies near zero) decays at once.
     */
    void set_balance_limit(const double limit, const double active_from = 0);

    /// Start at time @p t0 from displacement @p u0 and velocity @p v0.
    void
    initialize(const double t0, const VectorType &u0, const VectorType &v0);

    /**
     * The critical time step 2 / omega_max of the current state, omega_max^2
     * the largest eigenvalue of M^{-1} K (K the tangent stiffness), from a
     * power iteration on finite differences of f_int, warm-started from the
     * previous call's eigenvector.
     */
    double critical_time_step(const unsigned int iterations = 40);

    /// Advance by @p dt (s). A step that is not ok is undone (the state
    /// before it is kept).
    StepResult step(const double dt);

    /// The scalars a restart needs (time, last step, energies).
    std::vector<double> state_scalars() const;
    /**
     * Continue from a saved state: displacement @p u, half-step velocity
     * @p v_half (velocity_half_step()), state_scalars() and, with
     * stiffness damping, the @p damping_force of the saved step.
     */
    void restore(const VectorType          &u,
                 const VectorType          &v_half,
                 const std::vector<double> &scalars,
                 const VectorType          *damping_force = nullptr);
    /// The power iteration's current estimate of the highest mode (saved
    /// with a checkpoint so that a restart continues identically).
    const VectorType &highest_mode() const;
    void              set_highest_mode(const VectorType &mode);

    double            time() const;
    const VectorType &displacement() const;
    /// Velocity at the current step, v^{n-1/2} + dt/2 a^n (m/s; the
    /// contact forces of the coming step are not in it).
    const VectorType &velocity() const;
    /// Velocity at the last half step v^{n-1/2} (m/s).
    const VectorType &velocity_half_step() const;
    /// The stiffness damping force beta K v at the current step (N; zero
    /// without stiffness damping).
    const VectorType &damping_force() const;
    /// Internal and external forces at the current step (N).
    const VectorType &internal_forces() const;
    const VectorType &external_forces_now() const;
    /// Contact forces on the tissue of the last step (N; at t^{n-1}).
    const VectorType &contact_forces() const;
    Energies          energies() const;
    double            min_J() const;

  private:
    /// a = M^-1 (f_ext - f_int(u) - f_damping) - alpha v at time t; with
    /// @p rate_dt > 0 (the step just taken) f_damping is first updated to
    /// beta (f_int(u) - f_int(u_prev)) / rate_dt.
    void acceleration(const double      t,
                      const VectorType &u,
                      const VectorType &v,
                      const double      rate_dt = 0);
    /// Keep u^n and v^{n-1/2}, then v^{n+1/2} = v^{n-1/2} + h a^n and
    /// u^{n+1} = u^n + dt v^{n+1/2}, in one pass over the vectors.
    void predict(const double dt, const double h);
    /// 1/2 v.M.v over all ranks (J; J/m in 2D).
    double kinetic_energy(const VectorType &velocity) const;
    /// Apply constrain() to u; turn its corrections into f_c and v.
    void apply_constraints(const double dt, const double h);
    /// Whether the created energy has exceeded the balance limit and grown
    /// for balance_patience steps in a row (counts this step).
    bool energy_keeps_growing();
    /// Energies after a step of velocity step h; false if not finite.
    bool update_energies(const double h);
    void undo_step(const double internal_old,
                   const double J_old,
                   const double previous_time);

    const InternalForceOperator<dim> &force;
    const VectorType                 &mass;
    dealii::IndexSet                  fixed;
    double                            alpha;
    double                            beta; ///< stiffness damping, s
    double                            balance_limit = 0; ///< 0: none
    double balance_from = 0; ///< s, time from which the limit acts
    /// Steps in a row that a growing created energy must stay above the
    /// limit before the last one is refused.
    static constexpr unsigned int balance_patience = 10;
    unsigned int  steps_over_limit = 0; ///< consecutive such steps so far
    double        created_before   = 0; ///< e.created of the last step
    unsigned long steps_taken      = 0;
    double        t = 0, last_dt = 0;
    VectorType    u, v_half, v, a, f, f_ext, f_contact, u_trial, eigenvector;
    mutable VectorType v_now; ///< velocity() at the current step
    /// The state before the current step (kept for the rollback and the
    /// work over the step; swapped, not reallocated, each step).
    VectorType u_prev, v_half_prev, a_prev, f_prev, f_ext_prev;
    /// The stiffness damping force beta K v at t^{n+1} and at t^n.
    VectorType f_damping, f_damping_prev;
    /// Per locally owned dof (local order): 1 if free, 0 if fixed.
    std::vector<unsigned char> is_free;
    /// Local indices of the free dofs constrain() may change (empty: all)
    /// and their predicted values before constrain().
    std::vector<unsigned int> constrained;
    std::vector<double>       constrained_trial;
    bool                      started = false;
    Energies                  e, e0;
    double                    smallest_J = 1, internal_energy = 0;
    double                    internal_start = 0; ///< U^n of the step
  };
} // namespace softgrasp

#endif
