#ifndef softgrasp_solvers_implicit_stepper_h
#define softgrasp_solvers_implicit_stepper_h

#include <memory>
#include <softgrasp/contact/mortar_contact.h>
#include <softgrasp/mechanics/newton_solver.h>
#include <softgrasp/solvers/time_stepper.h>
#include <string>

namespace softgrasp
{
  /**
   * Implicit time stepping of a total-Lagrangian finite-strain solid:
   * load/time steps from the state's time to the end time, Newton-Raphson
   * with a line search in each step (NewtonSolver), automatic step
   * cut-back on non-convergence or element inversion, mortar contact by a
   * semi-smooth Newton method, a history row per step, fields and
   * checkpoints at their intervals, and progress with the time left.
   *
   * 'quasi-static' (QuasiStaticStepper): static equilibrium at every step,
   * inertia neglected. 'implicit dynamic' (ImplicitDynamicStepper): each
   * step also carries the inertia of the lumped mass by backward Euler
   * (v_{n+1} = (u_{n+1} - u_n)/dt, a_{n+1} = (v_{n+1} - v_n)/dt). A slow
   * load then follows the static path, and where that path has no
   * continuation (a frictional snap) a cut-back step makes M/dt^2 dominate
   * the released stiffness, so the step converges and the snap is passed
   * dynamically. The velocity is checkpointed; the history has the
   * kinetic energy.
   */
  template <int dim> class ImplicitStepper : public TimeStepper<dim>
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    /// @p dynamic: with the inertia of the lumped mass.
    explicit ImplicitStepper(const bool dynamic);

    bool needs_tangent() const override;
    bool has_inertia() const override;
    unsigned int
    n_checkpoint_fields(const SolverParameters &parameters) const override;
    std::unique_ptr<ContactSurface<dim>>
         make_contact(const SimulationAccess<dim> &run,
                      double                       shear_modulus) override;
    void run(const SimulationAccess<dim> &run) override;

  private:
    /// Inertia vectors, contact state, summary and the record of t = 0.
    void start(const SimulationAccess<dim> &run);
    /// The fresh run's state at t = 0 (equilibrium, or the initial
    /// conditions of implicit dynamics), recorded and written.
    void start_fresh(const SimulationAccess<dim> &run);
    /// One converged step of at most @p dt from @p u_start, cutting back
    /// (@p dt is halved each time); returns the new time and sets
    /// @p cut_backs. Throws a SolverFailure after the last cut-back.
    double take_step(const SimulationAccess<dim> &run,
                     const TimePhase             &phase,
                     const Vector                &u_start,
                     double                      &dt,
                     unsigned int                &cut_backs);
    /// Write the last converged state and throw the failure of a step.
    [[noreturn]] void fail(const SimulationAccess<dim> &run,
                           const std::string           &report,
                           const TimePhase             &phase,
                           double                       dt,
                           unsigned int                 cut_backs);
    /// Fields and checkpoint at their intervals, the progress line;
    /// returns true if the run ends here (stop criterion).
    bool finish_step(const SimulationAccess<dim> &run, const double dt);
    /// The Newton solves of the step at @p time, repeated while the
    /// contact's outer iterations have not settled; sets the last_*
    /// counters.
    typename NewtonSolver<dim>::Result
    solve_outer(const SimulationAccess<dim> &run, const double time);
    /// Finish a step whose lag has not settled by the contact's polish
    /// (friction against the current normal forces); true if it settled,
    /// then @p result is its last solve. Else the state is restored.
    bool polish(const SimulationAccess<dim>        &run,
                typename NewtonSolver<dim>::Result &result);
    /// Keep a step whose outer iterations did not settle, with a warning
    /// (@p settle_line: the contact's last report).
    void accept_unsettled(const SimulationAccess<dim> &run,
                          const double                 time,
                          const std::string           &settle_line);
    bool solve_step(const SimulationAccess<dim> &run,
                    const double                 time,
                    std::string                 &failure_report);
    /// Start the minimisation of the step at @p time from the last
    /// converged state extrapolated in time, where that lowers the
    /// step's potential ('Newton/Predictor').
    void predict(const SimulationAccess<dim> &run, const double time);
    /// Set the inertia term of a step of size @p dt from the state
    /// u_n = @p u_start with the velocity v_n.
    void set_inertia(const SimulationAccess<dim> &run,
                     const Vector                &u_start,
                     const double                 dt);
    /// After a converged step of size @p dt: v = (u - u_start)/dt.
    void   update_velocity(const SimulationAccess<dim> &run,
                           const Vector                &u_start,
                           const double                 dt);
    double kinetic_energy(const SimulationAccess<dim> &run) const;
    /// Implicit dynamics: the forces of the initial state u = 0 at t = 0,
    /// for its history row (no equilibrium is solved for).
    void evaluate_initial_state(const SimulationAccess<dim> &run);
    /// The checkpoint, with the velocity in implicit dynamics.
    void write_state(const SimulationAccess<dim> &run);
    void record_step(const SimulationAccess<dim> &run,
                     const double                 time,
                     const unsigned int           cut_backs);

    const bool                         dynamic;
    std::unique_ptr<NewtonSolver<dim>> newton;
    /// The polish's Newton solver: at most 30 iterations per solve.
    std::unique_ptr<NewtonSolver<dim>> polish_newton;
    ImplicitContact<dim>              *mortar = nullptr; ///< the run's
    unsigned int                       last_newton_iterations = 0;
    /// Newton solves of the last step (the contact's outer iterations).
    unsigned int last_outer_iterations = 0;
    /// Whether the last step was accepted with its outer iterations not
    /// settled, and how many steps of the run were.
    bool         last_unsettled  = false;
    unsigned int unsettled_steps = 0;
    /// Whether the last step was finished by the polish, how many steps of
    /// the run were and how many polish attempts failed.
    bool         last_polished  = false;
    unsigned int polished_steps = 0, failed_polishes = 0;
    /// Of the last step's Newton updates: those that raised the potential
    /// and those whose direction was not of descent (NewtonSolver::Result).
    unsigned int last_energy_increases = 0, last_non_descent = 0;
    unsigned int last_linear_iterations = 0;
    double       last_residual          = 0;
    double       previous_time          = 0;
    /// The converged state before the last step, u_{n-1} (m, owned), and
    /// that step's size (s; 0 before the first step of a run)
    Vector previous_solution;
    double previous_step = 0;
    /// Implicit dynamics: v_n (m/s, owned), the predictor u_n + dt v_n
    /// (ghosted) and the lumped mass (kg, owned and ghosted).
    Vector velocity, predictor, mass, ghosted_mass;
  };

  /// 'Time/Integrator = quasi-static': ImplicitStepper without inertia.
  template <int dim> class QuasiStaticStepper : public ImplicitStepper<dim>
  {
  public:
    QuasiStaticStepper();
  };

  /// 'Time/Integrator = implicit dynamic': ImplicitStepper with inertia.
  template <int dim> class ImplicitDynamicStepper : public ImplicitStepper<dim>
  {
  public:
    ImplicitDynamicStepper();
  };
} // namespace softgrasp

#endif
