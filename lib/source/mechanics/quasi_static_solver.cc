#include <cmath>
#include <deal.II/base/multithread_info.h>
#include <filesystem>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mechanics/quasi_static_solver.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  QuasiStaticSolver<dim>::QuasiStaticSolver(MPI_Comm                 comm,
                                            const SolverInputs<dim> &inputs)
      : MechanicsSolver<dim>(comm, inputs)
      , newton(this->solver_parameters.newton, this->verbose_out)
  {
    if (dynamic())
      this->n_restored_fields = 1; // the velocity
  }

  template <int dim> bool QuasiStaticSolver<dim>::dynamic() const
  {
    return this->solver_parameters.time.integrator ==
           TimeIntegrator::implicit_dynamic;
  }

  template <int dim>
  void
  QuasiStaticSolver<dim>::set_inertia(const TrilinosWrappers::MPI::Vector &u_n,
                                      const double                         dt)
  {
    if (!dynamic())
      return;
    TrilinosWrappers::MPI::Vector owned(u_n);
    owned.add(dt, velocity);
    predictor = owned;
    this->solid->set_inertia({&predictor, 1.0 / (dt * dt)});
    if (mortar)
      mortar->set_inertia(ghosted_mass, 1.0 / (dt * dt));
  }

  template <int dim>
  void QuasiStaticSolver<dim>::update_velocity(
      const TrilinosWrappers::MPI::Vector &u_n, const double dt)
  {
    if (!dynamic())
      return;
    velocity = this->solid->solution();
    velocity -= u_n;
    velocity /= dt;
  }

  template <int dim> double QuasiStaticSolver<dim>::kinetic_energy() const
  {
    double energy = 0;
    for (const auto i : mass.locally_owned_elements())
      energy += 0.5 * mass[i] * velocity[i] * velocity[i];
    return Utilities::MPI::sum(energy, this->comm);
  }

  template <int dim>
  std::unique_ptr<ContactSurface<dim>>
  QuasiStaticSolver<dim>::make_contact(const double shear_modulus)
  {
    auto contact = std::make_unique<MortarContact<dim>>(
        this->contact_parameters, this->bodies, shear_modulus, this->timers);
    contact->setup(*this->solid);
    this->solid->set_nodal_conditions(contact.get());
    mortar = contact.get();
    return contact;
  }

  template <int dim> void QuasiStaticSolver<dim>::run()
  {
    auto       &state             = this->state;
    auto       &solid             = this->solid;
    auto       &pcout             = this->pcout;
    const auto &time              = this->solver_parameters.time;
    const auto &solver_parameters = this->solver_parameters;
    mortar                        = nullptr;
    std::vector<std::string> trailing;
    if (!this->contact_parameters.slave_boundary_ids.empty())
      trailing = {
          "contact_active_nodes", "contact_slip_nodes", "active_set_changes"};
    std::vector<std::string> leading = {"step_size",
                                        "newton_iterations",
                                        "linear_iterations",
                                        "cut_backs",
                                        "wall_time"};
    if (dynamic())
      leading.push_back("kinetic_energy");
    this->prepare_run(leading, trailing);
    const bool resume = solver_parameters.checkpoint.resume;
    if (dynamic())
    {
      mass = solid->lumped_mass();
      ghosted_mass.reinit(solid->locally_owned_dofs(),
                          solid->locally_relevant_dofs(),
                          this->comm);
      ghosted_mass = mass;
      velocity.reinit(solid->locally_owned_dofs(), this->comm);
      predictor.reinit(solid->locally_owned_dofs(),
                       solid->locally_relevant_dofs(),
                       this->comm);
      if (resume)
        velocity = this->restored_fields[0];
    }
    previous_time = state.time;
    if (mortar)
    {
      solid->update_ghosts();
      mortar->accept_step(*solid, state.time);
    }
    this->print_summary(dynamic() ? "implicit dynamic" : "quasi-static");

    auto &progress = this->progress;
    progress.start(state.time, time.end_time);
    std::string report;
    if (!resume)
    {
      if (mortar)
      {
        const auto [inside, depth] = mortar->overlap_summary(
            mortar->node_overlaps(0.0, solid->ghosted_solution()));
        if (inside > 0)
          pcout << "Warning: " << inside
                << " contact node(s) start inside a rigid body (up to " << depth
                << " m); the first step pushes them out at once, which may "
                   "need cut-backs. Fix: start the rigid bodies outside the "
                   "tissue."
                << std::endl;
      }
      // Implicit dynamics starts from its initial conditions (u = v = 0),
      // which need not be in equilibrium (e.g. a body let go under
      // gravity); a quasi-static run starts in equilibrium.
      if (!dynamic() && !solve_step(0.0, report))
        throw SolverFailure("The initial state (t = 0) is not in equilibrium "
                            "and Newton failed on it: " +
                            report +
                            ". Fix: make the loads and prescribed "
                            "displacements zero at t = 0.");
      if (dynamic())
        evaluate_initial_state();
      record_step(0.0, 0, 0, 0);
      this->write_fields(0.0);
    }

    double     dt            = state.step_size;
    const auto previous_step = [&]() { return state.time; };
    while (previous_step() < time.end_time * (1 - 1e-12))
    {
      // a step stays within its phase ('Time/Phases'), at most its step
      const TimePhase               phase       = time.phase_at(state.time);
      unsigned int                  cut_backs   = 0;
      TrilinosWrappers::MPI::Vector u_converged = solid->solution();
      double                        t_new;
      dt = std::min(dt, phase.step);
      for (;;)
      {
        t_new = std::min(state.time + dt, phase.end);
        if (phase.end - t_new < 1e-9 * dt)
          t_new = phase.end;
        set_inertia(u_converged, t_new - state.time);
        if (solve_step(t_new, report))
          break;
        solid->solution() = u_converged;
        solid->update_ghosts();
        ++cut_backs;
        if (cut_backs > time.max_cut_backs || dt / 2 < phase.minimum)
        {
          this->boundary_conditions.set_time(state.time);
          this->write_fields(state.time);
          write_state();
          std::ostringstream message;
          message << report << "\nThe step was cut back " << cut_backs - 1
                  << " time(s) down to dt = " << dt << " s without success";
          if (cut_backs <= time.max_cut_backs)
            message << " (another cut-back would go below 'Time/Minimum "
                       "time step' = "
                    << phase.minimum << " s; a smaller one allows more)";
          message << ". The last converged state (step " << state.step
                  << ", t = " << state.time << " s) was written to '"
                  << solver_parameters.output.directory
                  << "' (VTU and checkpoint). Fix: reduce 'Time/Time step', "
                     "check the loads and boundary conditions, or use the "
                     "'mixed u-p-J' formulation for nearly incompressible "
                     "materials.";
          if (mortar && !dynamic() &&
              this->contact_parameters.friction_coefficient > 0)
            message << " With friction, a step that fails at every size "
                       "while contact nodes flip between stick and slip is "
                       "a frictional snap: the quasi-static path has no "
                       "continuation there (doc/contact.md). Fix: 'Time/"
                       "Integrator = implicit dynamic', whose inertia "
                       "carries the snap.";
          throw SolverFailure(message.str());
        }
        dt /= 2;
        pcout << report << "\n  -> cutting back to dt = " << dt << " s"
              << std::endl;
      }
      update_velocity(u_converged, t_new - state.time);
      state.time = t_new;
      ++state.step;
      record_step(
          t_new, last_newton_iterations, last_linear_iterations, cut_backs);

      const unsigned int vtu = solver_parameters.output.vtu_interval;
      this->stopped          = this->stop_criterion && this->stop_criterion();
      const bool last =
          this->stopped || state.time >= time.end_time * (1 - 1e-12);
      if ((vtu > 0 && state.step % vtu == 0) || last)
        this->write_fields(state.time);
      const unsigned int every = solver_parameters.checkpoint.interval;
      // A run stopped by its criterion can be continued (or branched from).
      if ((every > 0 && state.step % every == 0) || this->stopped)
        write_state();

      pcout << "Step " << std::setw(4) << state.step
            << "  t = " << std::setw(10) << state.time << " s (" << std::setw(3)
            << std::lround(100 * state.time / time.end_time)
            << "%)  dt = " << dt << " s  Newton " << last_newton_iterations
            << "  linear " << last_linear_iterations << "  |r| "
            << std::scientific << std::setprecision(2) << last_residual
            << std::defaultfloat << std::setprecision(6) << "  wall "
            << ProgressReporter::format_duration(progress.elapsed()) << "  ETA "
            << ProgressReporter::format_duration(progress.eta(state.time))
            << std::endl;
      const TimePhase next = time.phase_at(state.time);
      if (next.end != phase.end)
        dt = next.step; // a new phase starts with its own step
      else if (cut_backs == 0)
        dt = std::min(2 * dt, phase.step);
      state.step_size = dt;
      if (this->stopped)
      {
        pcout << "Stop criterion met at t = " << state.time << " s."
              << std::endl;
        break;
      }
    }
    this->timers.print_wall_time_statistics(this->comm);
  }

  template <int dim>
  bool QuasiStaticSolver<dim>::solve_step(const double time,
                                          std::string &report)
  {
    this->boundary_conditions.set_time(time);
    if (mortar)
      mortar->set_time(time);
    const auto result      = newton.solve(*this->solid);
    last_newton_iterations = result.iterations;
    last_linear_iterations = result.linear_iterations;
    last_residual = result.residuals.empty() ? 0 : result.residuals.back();
    if (result.converged)
      return true;
    std::ostringstream message;
    message << "Step " << this->state.step + 1 << " (t = " << time
            << " s, from t = " << this->state.time
            << " s) failed: " << result.failure << ". Residual history (N):";
    for (const double r : result.residuals)
      message << " " << std::scientific << std::setprecision(3) << r;
    report = message.str();
    return false;
  }

  template <int dim>
  void QuasiStaticSolver<dim>::record_step(const double       time,
                                           const unsigned int newton_iterations,
                                           const unsigned int linear_iterations,
                                           const unsigned int cut_backs)
  {
    std::vector<double> leading = {this->state.step == 0 ? 0.0
                                                         : time - previous_time,
                                   double(newton_iterations),
                                   double(linear_iterations),
                                   double(cut_backs),
                                   this->progress.elapsed()};
    if (dynamic())
      leading.push_back(kinetic_energy());
    previous_time = time;
    std::vector<double> trailing;
    if (mortar)
      trailing = {double(mortar->n_active()),
                  double(mortar->n_slip()),
                  double(mortar->changes_in_step())};
    this->record(time, leading, trailing);
    if (mortar)
      mortar->accept_step(*this->solid, time);
  }

  template <int dim> void QuasiStaticSolver<dim>::evaluate_initial_state()
  {
    this->boundary_conditions.set_time(0.0);
    if (mortar)
      mortar->set_time(0.0);
    const double violation = this->solid->update_constraints();
    if (violation > 0)
      throw SolverFailure(
          "Implicit dynamics starts from u = 0, but the prescribed "
          "displacements at t = 0 differ from zero (by up to " +
          std::to_string(violation) +
          " m). Fix: make them zero at t = 0 and ramp them up.");
    const auto state = this->solid->assemble(false);
    if (!state.ok || !std::isfinite(state.residual_norm))
      throw SolverFailure("The initial state (t = 0) cannot be evaluated: " +
                          state.failed_cell);
  }

  template <int dim> void QuasiStaticSolver<dim>::write_state()
  {
    if (!dynamic())
    {
      this->write_checkpoint();
      return;
    }
    TrilinosWrappers::MPI::Vector ghosted(this->solid->locally_owned_dofs(),
                                          this->solid->locally_relevant_dofs(),
                                          this->comm);
    ghosted = velocity;
    this->write_checkpoint({&ghosted});
  }

  template class QuasiStaticSolver<2>;
  template class QuasiStaticSolver<3>;
} // namespace softgrasp
