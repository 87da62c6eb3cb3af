#include <cmath>
#include <iomanip>
#include <softgrasp/solvers/implicit_stepper.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  ImplicitStepper<dim>::ImplicitStepper(const bool dynamic)
      : dynamic(dynamic)
  {
  }

  template <int dim> bool ImplicitStepper<dim>::needs_tangent() const
  {
    return true;
  }

  template <int dim> bool ImplicitStepper<dim>::has_inertia() const
  {
    return dynamic;
  }

  template <int dim>
  unsigned int
  ImplicitStepper<dim>::n_checkpoint_fields(const SolverParameters &) const
  {
    return dynamic ? 1 : 0; // the velocity
  }

  template <int dim>
  std::unique_ptr<ContactSurface<dim>>
  ImplicitStepper<dim>::make_contact(const SimulationAccess<dim> &run,
                                     const double                 shear_modulus)
  {
    auto contact =
        create_implicit_contact<dim>(run.contact_parameters().for_implicit(),
                                     run.rigid_bodies(),
                                     shear_modulus,
                                     run.timers());
    contact->setup(run.solid());
    run.solid().set_nodal_conditions(contact.get());
    mortar = contact.get();
    return contact;
  }

  template <int dim>
  void ImplicitStepper<dim>::set_inertia(const SimulationAccess<dim> &run,
                                         const Vector                &u_n,
                                         const double                 dt)
  {
    if (!dynamic)
      return;
    Vector owned(u_n);
    owned.add(dt, velocity);
    predictor = owned;
    run.solid().set_inertia({&predictor, 1.0 / (dt * dt)});
    if (mortar)
      mortar->set_inertia(ghosted_mass, 1.0 / (dt * dt));
  }

  template <int dim>
  void ImplicitStepper<dim>::update_velocity(const SimulationAccess<dim> &run,
                                             const Vector                &u_n,
                                             const double                 dt)
  {
    if (!dynamic)
      return;
    velocity = run.solid().solution();
    velocity -= u_n;
    velocity /= dt;
  }

  template <int dim>
  double
  ImplicitStepper<dim>::kinetic_energy(const SimulationAccess<dim> &run) const
  {
    double energy = 0;
    for (const auto i : mass.locally_owned_elements())
      energy += 0.5 * mass[i] * velocity[i] * velocity[i];
    return Utilities::MPI::sum(energy, run.communicator());
  }

  template <int dim>
  void ImplicitStepper<dim>::run(const SimulationAccess<dim> &run)
  {
    if (!run.has_contact())
      mortar = nullptr;
    // a minimisation (the incremental potential) may ask for more
    // iterations than a semi-smooth solve needs
    NewtonParameters newton_parameters = run.parameters().newton;
    if (mortar)
      newton_parameters.max_iterations = std::max(
          newton_parameters.max_iterations, mortar->max_newton_iterations());
    newton = std::make_unique<NewtonSolver<dim>>(newton_parameters,
                                                 run.verbose_out());
    // the polish converges fast where it converges (2 to 20 iterations on
    // the drags); where its backtracking stalls more iterations are lost
    NewtonParameters polish_parameters = newton_parameters;
    polish_parameters.max_iterations =
        std::min(newton_parameters.max_iterations, 30u);
    polish_newton = std::make_unique<NewtonSolver<dim>>(polish_parameters,
                                                        run.verbose_out());
    start(run);
    const auto &time  = run.parameters().time;
    RunState   &state = run.state();
    double      dt    = state.step_size;
    while (state.time < time.end_time * (1 - 1e-12))
    {
      // a step stays within its phase ('Time/Phases'), at most its step
      const TimePhase phase       = time.phase_at(state.time);
      unsigned int    cut_backs   = 0;
      const Vector    u_converged = run.solid().solution();
      dt                          = std::min(dt, phase.step);
      const double t_new = take_step(run, phase, u_converged, dt, cut_backs);
      update_velocity(run, u_converged, t_new - state.time);
      previous_solution = u_converged;
      previous_step     = t_new - state.time;
      state.time        = t_new;
      ++state.step;
      record_step(run, t_new, cut_backs);
      const bool      stop = finish_step(run, dt);
      const TimePhase next = time.phase_at(state.time);
      if (next.end != phase.end)
        dt = next.step; // a new phase starts with its own step
      else if (cut_backs == 0)
        dt = std::min(2 * dt, phase.step);
      state.step_size = dt;
      if (stop)
      {
        run.out() << "Stop criterion met at t = " << state.time << " s."
                  << std::endl;
        break;
      }
    }
    if (polished_steps + failed_polishes > 0)
      run.out() << polished_steps << " step(s) finished by the polish "
                << "(friction against the current normal forces; history "
                << "column 'polished'), " << failed_polishes
                << " polish attempt(s) failed." << std::endl;
    if (unsettled_steps > 0)
      run.out() << unsettled_steps << " step(s) accepted with the contact's "
                << "outer iterations not settled (history columns "
                << "'unsettled', 'coulomb_excess')." << std::endl;
  }

  template <int dim>
  void ImplicitStepper<dim>::start(const SimulationAccess<dim> &run)
  {
    auto &solid = run.solid();
    if (dynamic)
    {
      const MPI_Comm comm = run.communicator();
      mass                = solid.lumped_mass();
      ghosted_mass.reinit(
          solid.locally_owned_dofs(), solid.locally_relevant_dofs(), comm);
      ghosted_mass = mass;
      velocity.reinit(solid.locally_owned_dofs(), comm);
      predictor.reinit(
          solid.locally_owned_dofs(), solid.locally_relevant_dofs(), comm);
      if (run.resumed())
        velocity = run.restored_fields()[0];
    }
    previous_time = run.state().time;
    if (mortar)
    {
      solid.update_ghosts();
      mortar->accept_step(solid, run.state().time);
    }
    run.print_summary(dynamic ? "implicit dynamic" : "quasi-static");
    run.progress().start(run.state().time, run.parameters().time.end_time);
    if (!run.resumed())
      start_fresh(run);
  }

  template <int dim>
  void ImplicitStepper<dim>::start_fresh(const SimulationAccess<dim> &run)
  {
    if (mortar)
    {
      const auto [inside, depth] = mortar->overlap_summary(
          mortar->node_overlaps(0.0, run.solid().ghosted_solution()));
      if (inside > 0)
        run.out() << "Warning: " << inside
                  << " contact node(s) start inside a rigid body (up to "
                  << depth
                  << " m); the first step pushes them out at once, which may "
                     "need cut-backs. Fix: start the rigid bodies outside the "
                     "tissue."
                  << std::endl;
    }
    // Implicit dynamics starts from its initial conditions (u = v = 0),
    // which need not be in equilibrium (e.g. a body let go under
    // gravity); a quasi-static run starts in equilibrium.
    std::string report;
    if (!dynamic && !solve_step(run, 0.0, report))
      throw SolverFailure("The initial state (t = 0) is not in equilibrium "
                          "and Newton failed on it: " +
                          report +
                          ". Fix: make the loads and prescribed "
                          "displacements zero at t = 0.");
    if (dynamic)
      evaluate_initial_state(run);
    record_step(run, 0.0, 0);
    run.write_fields(0.0);
  }

  template <int dim>
  double ImplicitStepper<dim>::take_step(const SimulationAccess<dim> &run,
                                         const TimePhase             &phase,
                                         const Vector                &u_start,
                                         double                      &dt,
                                         unsigned int                &cut_backs)
  {
    const double t_old = run.state().time;
    std::string  report;
    for (;;)
    {
      double t_new = std::min(t_old + dt, phase.end);
      if (phase.end - t_new < 1e-9 * dt)
        t_new = phase.end;
      set_inertia(run, u_start, t_new - t_old);
      if (solve_step(run, t_new, report))
        return t_new;
      run.solid().solution() = u_start;
      run.solid().update_ghosts();
      ++cut_backs;
      if (cut_backs > run.parameters().time.max_cut_backs ||
          dt / 2 < phase.minimum)
        fail(run, report, phase, dt, cut_backs);
      dt /= 2;
      run.out() << report << "\n  -> cutting back to dt = " << dt << " s"
                << std::endl;
    }
  }

  template <int dim>
  void ImplicitStepper<dim>::fail(const SimulationAccess<dim> &run,
                                  const std::string           &report,
                                  const TimePhase             &phase,
                                  const double                 dt,
                                  const unsigned int           cut_backs)
  {
    const RunState &state = run.state();
    run.boundary_conditions().set_time(state.time);
    run.write_fields(state.time);
    write_state(run);
    std::ostringstream message;
    message << report << "\nThe step was cut back " << cut_backs - 1
            << " time(s) down to dt = " << dt << " s without success";
    if (cut_backs <= run.parameters().time.max_cut_backs)
      message << " (another cut-back would go below 'Time/Minimum "
                 "time step' = "
              << phase.minimum << " s; a smaller one allows more)";
    message << ". The last converged state (step " << state.step
            << ", t = " << state.time << " s) was written to '"
            << run.parameters().output.directory
            << "' (VTU and checkpoint). Fix: reduce 'Time/Time step', "
               "check the loads and boundary conditions, or use the "
               "'mixed u-p-J' formulation for nearly incompressible "
               "materials.";
    if (mortar && !dynamic && run.contact_parameters().friction_coefficient > 0)
      message << " With friction, a step that fails at every size "
                 "while contact nodes flip between stick and slip is "
                 "a frictional snap: the quasi-static path has no "
                 "continuation there (doc/contact.md). Fix: 'Time/"
                 "Integrator = implicit dynamic', whose inertia "
                 "carries the snap.";
    throw SolverFailure(message.str());
  }

  template <int dim>
  bool ImplicitStepper<dim>::finish_step(const SimulationAccess<dim> &run,
                                         const double                 dt)
  {
    const auto     &parameters = run.parameters();
    const RunState &state      = run.state();
    const bool      stopped    = run.stop_requested();
    const bool      last =
        stopped || state.time >= parameters.time.end_time * (1 - 1e-12);
    const unsigned int vtu = parameters.output.vtu_interval;
    if ((vtu > 0 && state.step % vtu == 0) || last)
      run.write_fields(state.time);
    const unsigned int every = parameters.checkpoint.interval;
    // A run stopped by its criterion can be continued (or branched from).
    if ((every > 0 && state.step % every == 0) || stopped)
      write_state(run);
    const auto &progress = run.progress();
    run.out() << "Step " << std::setw(4) << state.step
              << "  t = " << std::setw(10) << state.time << " s ("
              << std::setw(3)
              << std::lround(100 * state.time / parameters.time.end_time)
              << "%)  dt = " << dt << " s  Newton " << last_newton_iterations
              << "  linear " << last_linear_iterations << "  |r| "
              << std::scientific << std::setprecision(2) << last_residual
              << std::defaultfloat << std::setprecision(6) << "  wall "
              << ProgressReporter::format_duration(progress.elapsed())
              << "  ETA "
              << ProgressReporter::format_duration(progress.eta(state.time))
              << std::endl;
    return stopped;
  }

  template <int dim>
  typename NewtonSolver<dim>::Result
  ImplicitStepper<dim>::solve_outer(const SimulationAccess<dim> &run,
                                    const double                 time)
  {
    // An enforcement that holds something fixed within a Newton solve (the
    // lagged friction of the incremental potential) repeats the solve until
    // that has settled: the outer iterations.
    const unsigned int max_outer = mortar ? mortar->max_outer_iterations() : 1;
    typename NewtonSolver<dim>::Result result;
    last_newton_iterations = last_linear_iterations = 0;
    last_energy_increases = last_non_descent = 0;
    last_unsettled = last_polished = false;
    for (last_outer_iterations = 1;; ++last_outer_iterations)
    {
      result = newton->solve(run.solid());
      last_energy_increases += result.energy_increases;
      last_non_descent += result.non_descent;
      last_newton_iterations += result.iterations;
      last_linear_iterations += result.linear_iterations;
      if (!result.converged || mortar == nullptr)
        break;
      std::string line;
      const bool  settled = mortar->settle(run.solid(), line);
      if (!line.empty())
        run.verbose_out() << "    outer " << last_outer_iterations << ": "
                          << line << std::endl;
      if (settled)
        break;
      const unsigned int every = mortar->polish_after();
      if (every > 0 && last_outer_iterations % every == 0 &&
          polish(run, result))
        break;
      if (last_outer_iterations < max_outer)
        continue;
      if (mortar->accept_unsettled())
        accept_unsettled(run, time, line);
      else
      {
        result.converged = false;
        result.failure   = "the contact's outer iterations did not settle in " +
                         std::to_string(max_outer) + " (" + line +
                         "; 'Contact/Maximum outer iterations', 'Contact/"
                         "Settle tolerance')";
      }
      break;
    }
    return result;
  }

  template <int dim>
  bool ImplicitStepper<dim>::polish(const SimulationAccess<dim>        &run,
                                    typename NewtonSolver<dim>::Result &result)
  {
    // Where the lagged normal forces 2-cycle or contract slowly (a patch
    // passing from stick to slip), Newton's method with friction against
    // the current normal forces holds Coulomb's law exactly; the
    // multipliers are still updated between its solves. From the last
    // lagged iterate; on failure the lagged iterations go on from there.
    if (!mortar->begin_polish())
      return false;
    const Vector u_lagged = run.solid().solution();
    std::string  line;
    bool         settled = false;
    unsigned int solves  = 0;
    while (!settled && solves < mortar->max_outer_iterations())
    {
      const auto attempt = polish_newton->solve(run.solid());
      ++solves;
      last_newton_iterations += attempt.iterations;
      last_linear_iterations += attempt.linear_iterations;
      if (!attempt.converged)
      {
        line = attempt.failure;
        break;
      }
      settled = mortar->settle(run.solid(), line);
      if (settled)
        result = attempt;
    }
    mortar->end_polish(settled);
    run.verbose_out() << "    polish after outer iteration "
                      << last_outer_iterations << ": "
                      << (settled ? "settled" : "failed") << " in " << solves
                      << " solve(s) (" << line << ")" << std::endl;
    if (settled)
    {
      last_polished = true;
      ++polished_steps;
      return true;
    }
    ++failed_polishes;
    run.solid().solution() = u_lagged;
    run.solid().update_ghosts();
    return false;
  }

  template <int dim>
  void ImplicitStepper<dim>::accept_unsettled(const SimulationAccess<dim> &run,
                                              const double                 time,
                                              const std::string &settle_line)
  {
    // an equilibrium of the lagged problem, Coulomb's law not yet against
    // the current normal forces: kept, with its excess
    ++unsettled_steps;
    last_unsettled = true;
    run.out() << "Warning: step " << run.state().step + 1 << " (t = " << time
              << " s): the contact's outer iterations did not settle in "
              << last_outer_iterations << " (" << settle_line
              << "); the step is accepted with a Coulomb excess of "
              << mortar->coulomb_excess()
              << " of mu times the largest normal force. Fix: a smaller "
                 "'Time/Time step', or 'Contact/Unsettled steps = cut back'."
              << std::endl;
  }

  template <int dim>
  bool ImplicitStepper<dim>::solve_step(const SimulationAccess<dim> &run,
                                        const double                 time,
                                        std::string                 &report)
  {
    run.boundary_conditions().set_time(time);
    if (mortar)
    {
      mortar->set_time(time);
      mortar->begin_step(time - run.state().time);
    }
    predict(run, time);
    const auto result = solve_outer(run, time);
    last_residual     = result.residuals.empty() ? 0 : result.residuals.back();
    if (result.converged)
      return true;
    std::ostringstream message;
    message << "Step " << run.state().step + 1 << " (t = " << time
            << " s, from t = " << run.state().time
            << " s) failed in outer iteration " << last_outer_iterations
            << " after " << last_newton_iterations
            << " Newton iterations: " << result.failure
            << ". Residual history (N):";
    for (const double r : result.residuals)
      message << " " << std::scientific << std::setprecision(3) << r;
    report = message.str();
    return false;
  }

  template <int dim>
  void ImplicitStepper<dim>::predict(const SimulationAccess<dim> &run,
                                     const double                 time)
  {
    // A minimisation may start anywhere its potential is finite: moved on
    // linearly in time, a drag's sticking nodes travel with the rigid
    // body from the start instead of being walked there by the line
    // search in steps of the slip length. Kept only if it lowers the
    // potential (not across a reversal of the load, say).
    const double step = time - run.state().time;
    if (!run.parameters().newton.extrapolate || mortar == nullptr ||
        !mortar->is_potential() || !(previous_step > 0) || !(step > 0))
      return;
    auto      &solid = run.solid();
    const auto start = solid.assemble(false);
    if (!start.ok || !std::isfinite(start.energy))
      return;
    const Vector u_start = solid.solution();
    Vector       change(u_start);
    change -= previous_solution;
    solid.solution().add(step / previous_step, change);
    solid.update_ghosts();
    const auto moved = solid.assemble(false);
    const bool lower =
        moved.ok && std::isfinite(moved.energy) && moved.energy < start.energy;
    run.verbose_out() << "    predictor: potential " << start.energy << " -> "
                      << moved.energy
                      << (lower ? " (kept)" : " (not lower: discarded)")
                      << std::endl;
    if (lower)
      return;
    solid.solution() = u_start;
    solid.update_ghosts();
  }

  template <int dim>
  void ImplicitStepper<dim>::record_step(const SimulationAccess<dim> &run,
                                         const double                 time,
                                         const unsigned int           cut_backs)
  {
    const bool    first   = run.state().step == 0;
    HistoryValues leading = {
        {"step_size", first ? 0.0 : time - previous_time},
        {"newton_iterations", double(first ? 0 : last_newton_iterations)},
        {"linear_iterations", double(first ? 0 : last_linear_iterations)},
        {"cut_backs", double(cut_backs)},
        {"wall_time", run.progress().elapsed()}};
    if (dynamic)
    {
      // the state's energies (the last assembly is of the converged
      // state): with a dead load kinetic + internal + load potential is
      // the mechanical energy, which backward Euler dissipates at first
      // order in the step
      const auto &energies = run.solid().last_assembly();
      leading.emplace_back("kinetic_energy", kinetic_energy(run));
      leading.emplace_back("internal_energy", energies.strain_energy);
      leading.emplace_back("load_potential", energies.load_potential);
    }
    previous_time = time;
    HistoryValues trailing;
    if (mortar)
      trailing = {{"contact_active_nodes", double(mortar->n_active())},
                  {"contact_slip_nodes", double(mortar->n_slip())},
                  {"active_set_changes", double(mortar->changes_in_step())}};
    if (mortar && mortar->max_outer_iterations() > 1)
    {
      // the minimisation's own checks: updates along which the potential
      // rose, directions that were not of descent
      trailing.emplace_back("outer_iterations",
                            double(first ? 0 : last_outer_iterations));
      trailing.emplace_back("energy_increases",
                            double(first ? 0 : last_energy_increases));
      trailing.emplace_back("non_descent_directions",
                            double(first ? 0 : last_non_descent));
      trailing.emplace_back("coulomb_excess", mortar->coulomb_excess());
      trailing.emplace_back("unsettled", double(!first && last_unsettled));
      trailing.emplace_back("polished", double(!first && last_polished));
    }
    run.record(time, leading, trailing);
    if (mortar)
      mortar->accept_step(run.solid(), time);
  }

  template <int dim>
  void
  ImplicitStepper<dim>::evaluate_initial_state(const SimulationAccess<dim> &run)
  {
    run.boundary_conditions().set_time(0.0);
    if (mortar)
      mortar->set_time(0.0);
    const double violation = run.solid().update_constraints();
    if (violation > 0)
      throw SolverFailure(
          "Implicit dynamics starts from u = 0, but the prescribed "
          "displacements at t = 0 differ from zero (by up to " +
          std::to_string(violation) +
          " m). Fix: make them zero at t = 0 and ramp them up.");
    const auto state = run.solid().assemble(false);
    if (!state.ok || !std::isfinite(state.residual_norm))
      throw SolverFailure("The initial state (t = 0) cannot be evaluated: " +
                          state.failed_cell);
  }

  template <int dim>
  void ImplicitStepper<dim>::write_state(const SimulationAccess<dim> &run)
  {
    if (!dynamic)
    {
      run.write_checkpoint();
      return;
    }
    const auto &solid = run.solid();
    Vector      ghosted(solid.locally_owned_dofs(),
                   solid.locally_relevant_dofs(),
                   run.communicator());
    ghosted = velocity;
    run.write_checkpoint({&ghosted});
  }

  template <int dim>
  QuasiStaticStepper<dim>::QuasiStaticStepper()
      : ImplicitStepper<dim>(false)
  {
  }

  template <int dim>
  ImplicitDynamicStepper<dim>::ImplicitDynamicStepper()
      : ImplicitStepper<dim>(true)
  {
  }

  template class ImplicitStepper<2>;
  template class ImplicitStepper<3>;
  template class QuasiStaticStepper<2>;
  template class QuasiStaticStepper<3>;
  template class ImplicitDynamicStepper<2>;
  template class ImplicitDynamicStepper<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_TIME_STEPPER(
    softgrasp::QuasiStaticStepper,
    quasi_static,
    "quasi-static",
    "static equilibrium at every load step by Newton's method (inertia "
    "neglected; the 'Newton' and 'Linear solver' subsections apply)")

SOFTGRASP_REGISTER_TIME_STEPPER(
    softgrasp::ImplicitDynamicStepper,
    implicit_dynamic,
    "implicit dynamic",
    "Newton's method as 'quasi-static', with the inertia of the lumped mass, "
    "backward Euler in time (first order, damps the fast motion of a snap, "
    "so that a slow load follows the static path where one exists and passes "
    "through a snap where none does; t is physical time and the history "
    "reports the kinetic energy)")
