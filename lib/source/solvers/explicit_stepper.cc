#include <array>
#include <cmath>
#include <deal.II/dofs/dof_tools.h>
#include <iomanip>
#include <limits>
#include <softgrasp/base/input_error.h>
#include <softgrasp/explicit/lumped_mass.h>
#include <softgrasp/solvers/explicit_stepper.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim> bool ExplicitStepper<dim>::needs_tangent() const
  {
    return false;
  }

  template <int dim> bool ExplicitStepper<dim>::has_inertia() const
  {
    return true;
  }

  template <int dim>
  unsigned int ExplicitStepper<dim>::n_checkpoint_fields(
      const SolverParameters &parameters) const
  {
    // half-step velocity, highest mode and, with stiffness damping, the
    // damping force of the last step
    return parameters.explicit_dynamics.stiffness_damping > 0 ? 3 : 2;
  }

  template <int dim>
  void
  ExplicitStepper<dim>::check_inputs(const SimulationAccess<dim> &run) const
  {
    const auto &bcs = run.boundary_conditions();
    if (!bcs.tractions.empty() || !bcs.pressures.empty() || bcs.has_gravity())
      throw InputError(
          "The explicit solver ('Time/Integrator = explicit dynamic') takes "
          "prescribed displacements and contact with rigid bodies; "
          "tractions, pressures and gravity are not offered by it yet. Fix: "
          "use 'Time/Integrator = quasi-static', or apply the load through a "
          "prescribed displacement or a rigid body.");
  }

  template <int dim>
  std::unique_ptr<ContactSurface<dim>>
  ExplicitStepper<dim>::make_contact(const SimulationAccess<dim> &run,
                                     const double                 shear_modulus)
  {
    sim.emplace(run);
    auto contact = std::make_unique<ExplicitContact<dim>>(
        run.contact_parameters().for_explicit(),
        run.rigid_bodies(),
        run.timers(),
        shear_modulus);
    contact->set_reference_step(sim->parameters().time.step_size);
    contact->setup(run.solid());
    explicit_contact = contact.get();
    return contact;
  }

  template <int dim> void ExplicitStepper<dim>::setup_integrator()
  {
    const auto &dofs = sim->solid().dof_handler();
    hanging.clear();
    hanging.reinit(sim->solid().locally_relevant_dofs());
    DoFTools::make_hanging_node_constraints(dofs, hanging);
    hanging.close();
    const auto &element = sim->parameters().discretization;
    using Operator      = InternalForceOperator<dim>;
    using Kernel        = typename Operator::Kernel;
    using Dilatation    = typename Operator::Dilatation;
    const Dilatation dilatation =
        element.formulation == Formulation::displacement
            ? Dilatation::pointwise
            : (element.pressure_degree() == 0 ? Dilatation::element_constant
                                              : Dilatation::element_linear);
    force = std::make_unique<Operator>(
        sim->solid().mapping(),
        dofs,
        hanging,
        sim->materials(),
        dilatation,
        sim->parameters().explicit_dynamics.vectorized_force_kernel
            ? Kernel::vectorized
            : Kernel::reference);
    force->initialize_dof_vector(mass);
    compute_lumped_mass(
        sim->solid().mapping(), dofs, hanging, sim->materials(), mass);
    physical_mass = mass.l1_norm() / dim;
    added_mass    = 0;
    setup_prescribed();
    const auto &constraints = sim->solid().constraint_set();
    fixed                   = IndexSet(dofs.n_dofs());
    for (const auto i : sim->solid().locally_owned_dofs())
      if (constraints.is_constrained(i))
        fixed.add_index(i);
    fixed.compress();
    integrator = std::make_unique<CentralDifference<dim>>(
        *force, mass, fixed, sim->parameters().explicit_dynamics.mass_damping);
    // The balance limit acts after the first 2 % of the run.
    integrator->set_balance_limit(
        sim->parameters().explicit_dynamics.energy_balance_limit,
        0.02 * sim->parameters().time.end_time);
    integrator->prescribe = [this](const double t, VectorType &u)
    { prescribe(t, u); };
    if (explicit_contact)
    {
      integrator->constrain = [this](const double      t,
                                     const double      dt,
                                     const double      h,
                                     const VectorType &u_old,
                                     VectorType       &u)
      { explicit_contact->enforce(t, dt, h, mass, u_old, u); };
      // contact moves the slave nodes only
      std::vector<types::global_dof_index> slave_dofs;
      for (const auto &node : explicit_contact->nodes())
        slave_dofs.insert(slave_dofs.end(), node.dofs.begin(), node.dofs.end());
      integrator->set_constrained_dofs(slave_dofs);
    }
    const double target =
        sim->parameters().explicit_dynamics.mass_scaling_time_step;
    if (target > 0)
      scale_mass(target);
  }

  template <int dim> double ExplicitStepper<dim>::step_fraction() const
  {
    // central differences with damping lagged half a step: the highest
    // mode is stable up to 2/omega (sqrt(1 + xi^2) - xi), xi = beta omega/2
    const auto  &ep = sim->parameters().explicit_dynamics;
    const double xi = ep.stiffness_damping;
    return ep.safety_factor * (std::sqrt(1 + xi * xi) - xi);
  }

  template <int dim> void ExplicitStepper<dim>::set_time_step(const double dt)
  {
    // beta = xi x the critical step the time step stands for, so that a
    // restart (which knows the time step) damps exactly as before
    time_step = dt;
    integrator->set_stiffness_damping(
        sim->parameters().explicit_dynamics.stiffness_damping * dt /
        step_fraction());
  }

  template <int dim>
  void ExplicitStepper<dim>::scale_mass(const double target_step)
  {
    // Element estimates dt_e = k h_e / c_e (h_e the smallest vertex
    // distance, c_e the dilatational wave speed), calibrated by k so that
    // the smallest equals the critical step of the unscaled mesh (power
    // iteration). Elements below the target get their density scaled by
    // (target / dt_e)^2; the scaled mesh's critical step is then measured
    // again by the caller.
    const double        critical = integrator->critical_time_step(40);
    const auto         &tria     = sim->triangulation();
    std::vector<double> estimate(tria.n_active_cells(), 0.0);
    double              smallest = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const double c =
            sim->materials().get(cell->material_id()).reference_wave_speed();
        estimate[cell->active_cell_index()] =
            cell->minimum_vertex_distance() / c;
        smallest = std::min(smallest, estimate[cell->active_cell_index()]);
      }
    smallest              = Utilities::MPI::min(smallest, sim->communicator());
    const double        k = critical / smallest;
    std::vector<double> factor(tria.n_active_cells(), 1.0);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const double dt_e = k * estimate[cell->active_cell_index()];
        if (dt_e < target_step)
          factor[cell->active_cell_index()] = std::pow(target_step / dt_e, 2);
      }
    compute_lumped_mass(sim->solid().mapping(),
                        sim->solid().dof_handler(),
                        hanging,
                        sim->materials(),
                        mass,
                        factor);
    added_mass = 100 * (mass.l1_norm() / dim - physical_mass) / physical_mass;
  }

  template <int dim> void ExplicitStepper<dim>::setup_prescribed()
  {
    const auto &dofs  = sim->solid().dof_handler();
    const auto &owned = sim->solid().locally_owned_dofs();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(sim->solid().mapping(), dofs, points);
    prescribed.clear();
    std::set<types::global_dof_index> claimed;
    for (const auto &d : sim->boundary_conditions().dirichlet)
      for (unsigned int c = 0; c < dim; ++c)
      {
        if (!d.components[c])
          continue;
        std::vector<bool> mask(dim, false);
        mask[c]                = true;
        const IndexSet on_face = DoFTools::extract_boundary_dofs(
            dofs, ComponentMask(mask), {d.boundary_id});
        for (const auto i : on_face)
          if (owned.is_element(i) && !hanging.is_constrained(i) &&
              claimed.insert(i).second)
            prescribed.push_back({i, c, points.at(i), d.displacement.get()});
      }
  }

  template <int dim>
  void ExplicitStepper<dim>::prescribe(const double time, VectorType &u)
  {
    sim->boundary_conditions().set_time(time);
    for (const auto &p : prescribed)
      u(p.index) = p.function->value(p.point, p.component);
    if (hanging.n_constraints() > 0)
      hanging.distribute(u);
  }

  template <int dim> void ExplicitStepper<dim>::update_system()
  {
    const VectorType &u        = integrator->displacement();
    auto             &solution = sim->solid().solution();
    for (const auto i : sim->solid().locally_owned_dofs())
      solution[i] = u(i);
    solution.compress(VectorOperation::insert);
    sim->solid().update_ghosts();
    // The reactions f_int - f_ext at the supports: the integrator's own
    // (matrix-free) forces of this state.
    const VectorType &f_int = integrator->internal_forces();
    const VectorType &f_ext = integrator->external_forces_now();
    sim->solid().set_forces(
        [&](const types::global_dof_index i) { return f_int(i); },
        [&](const types::global_dof_index i) { return f_ext(i); });
  }

  template <int dim> void ExplicitStepper<dim>::record_state(const double time)
  {
    update_system();
    const auto    e        = integrator->energies();
    HistoryValues trailing = {{"kinetic_energy", e.kinetic},
                              {"internal_energy", e.internal},
                              {"external_work", e.external_work},
                              {"support_work", e.support_work},
                              {"contact_work", e.contact_work},
                              {"damping_energy", e.damping},
                              {"energy_balance_error", e.balance_error},
                              {"min_J", integrator->min_J()},
                              {"added_mass_percent", added_mass}};
    if (explicit_contact)
    {
      trailing.emplace_back("contact_active_nodes",
                            explicit_contact->n_active());
      trailing.emplace_back("contact_slip_nodes", explicit_contact->n_slip());
      trailing.emplace_back("max_penetration", worst_penetration);
    }
    sim->record(time,
                {{"time_step", time_step},
                 {"time_steps", double(steps)},
                 {"wall_time", sim->progress().elapsed()}},
                trailing);
    worst_penetration = 0;
  }

  template <int dim> void ExplicitStepper<dim>::save_checkpoint()
  {
    // Ghosted Trilinos copies of the half-step velocity, the highest mode
    // (the power iteration's warm start) and the damping force.
    std::array<TrilinosWrappers::MPI::Vector, 3> fields;
    const std::array<const VectorType *, 3>      sources = {
             {&integrator->velocity_half_step(),
              &integrator->highest_mode(),
              &integrator->damping_force()}};
    for (unsigned int k = 0; k < n_checkpoint_fields(sim->parameters()); ++k)
    {
      TrilinosWrappers::MPI::Vector owned(sim->solid().locally_owned_dofs(),
                                          sim->communicator());
      for (const auto i : sim->solid().locally_owned_dofs())
        owned[i] = (*sources[k])(i);
      owned.compress(VectorOperation::insert);
      fields[k].reinit(sim->solid().locally_owned_dofs(),
                       sim->solid().locally_relevant_dofs(),
                       sim->communicator());
      fields[k] = owned;
    }
    sim->state().integrator_state = integrator->state_scalars();
    sim->state().integrator_state.insert(sim->state().integrator_state.end(),
                                         {double(steps), time_step});
    std::vector<const TrilinosWrappers::MPI::Vector *> written;
    for (unsigned int k = 0; k < n_checkpoint_fields(sim->parameters()); ++k)
      written.push_back(&fields[k]);
    sim->write_checkpoint(written);
  }

  template <int dim>
  void ExplicitStepper<dim>::write_last_good_state(const double time)
  {
    ++sim->state().step;
    sim->state().time = time;
    record_state(time);
    sim->write_fields(time);
    save_checkpoint();
  }

  template <int dim>
  void ExplicitStepper<dim>::fail(const std::string &cause,
                                  const std::string &fix)
  {
    const double t = integrator->time();
    write_last_good_state(t);
    std::ostringstream message;
    message << "Explicit step " << steps + 1 << " (from t = " << t
            << " s, dt = " << time_step << " s) was refused: " << cause
            << ". The last good state (t = " << t << " s) was written to '"
            << sim->parameters().output.directory
            << "' (VTU and checkpoint). Fix: " << fix;
    throw SolverFailure(message.str());
  }

  template <int dim>
  void ExplicitStepper<dim>::print_progress(const double time,
                                            const double dt) const
  {
    const auto   e   = integrator->energies();
    const double end = sim->parameters().time.end_time;
    sim->out() << "Record " << std::setw(4) << sim->state().step
               << "  t = " << std::setw(10) << time << " s (" << std::setw(3)
               << std::lround(100 * time / end) << "%)  steps " << steps
               << "  dt = " << std::setprecision(3) << dt
               << " s  E_kin = " << e.kinetic << " J  balance "
               << 100 * e.balance_error << "%";
    if (explicit_contact)
      sim->out() << "  contact " << explicit_contact->n_active() << " ("
                 << explicit_contact->n_slip() << " slip)";
    sim->out() << std::setprecision(6) << "  wall "
               << ProgressReporter::format_duration(sim->progress().elapsed())
               << "  ETA "
               << ProgressReporter::format_duration(sim->progress().eta(time))
               << std::endl;
  }

  template <int dim>
  void ExplicitStepper<dim>::run(const SimulationAccess<dim> &run)
  {
    sim.emplace(run);
    if (!run.has_contact())
      explicit_contact = nullptr;
    setup_integrator();
    run.print_summary("explicit dynamic");
    VectorType u, v;
    force->initialize_dof_vector(u);
    force->initialize_dof_vector(v);
    run.progress().start(run.state().time, run.parameters().time.end_time);
    start(u, v);
    choose_time_step();
    const auto &time  = run.parameters().time;
    RunState   &state = run.state();
    while (state.time < time.end_time * (1 - 1e-12))
    {
      // the next recorded time: on the grid of the phase's interval
      const TimePhase phase = time.phase_at(state.time);
      const double    begin = time.phase_begin(state.time);
      const double    k = std::floor((state.time - begin) / phase.step + 0.5);
      const double t_record = std::min(phase.end, begin + (k + 1) * phase.step);
      advance_to(t_record);
      if (finish_record(t_record))
      {
        run.out() << "Stop criterion met at t = " << t_record << " s."
                  << std::endl;
        break;
      }
    }
  }

  template <int dim>
  void ExplicitStepper<dim>::start(VectorType &u, VectorType &v)
  {
    for (const auto i : sim->solid().locally_owned_dofs())
      u(i) = sim->solid().solution()[i];
    if (sim->resumed())
    {
      restore(u, v);
      return;
    }
    steps = 0;
    if (explicit_contact)
    {
      const auto [inside, overlap] =
          explicit_contact->relax_initial_overlap(0.0, u, 100);
      if (inside > 0)
        sim->out() << "Initial overlap: " << inside
                   << " contact node(s) start inside a rigid body (up to "
                   << overlap
                   << " m); they are pushed out over the first 100 steps."
                   << std::endl;
    }
    integrator->initialize(0.0, u, v);
    record_state(0.0);
    sim->write_fields(0.0);
  }

  template <int dim>
  void ExplicitStepper<dim>::restore(VectorType &u, VectorType &v)
  {
    VectorType mode, damping;
    force->initialize_dof_vector(mode);
    force->initialize_dof_vector(damping);
    const auto &fields = sim->restored_fields();
    const bool  damped = fields.size() > 2;
    for (const auto i : sim->solid().locally_owned_dofs())
    {
      v(i)    = fields[0][i];
      mode(i) = fields[1][i];
      if (damped)
        damping(i) = fields[2][i];
    }
    auto scalars = sim->state().integrator_state;
    if (scalars.size() < 2)
      throw InputError("The checkpoint has no explicit integrator state. "
                       "Fix: resume with the 'Time/Integrator' of the run "
                       "that wrote it.");
    time_step = scalars.back();
    scalars.pop_back();
    steps = static_cast<unsigned long>(scalars.back());
    scalars.pop_back();
    integrator->restore(u, v, scalars, damped ? &damping : nullptr);
    integrator->set_highest_mode(mode);
  }

  template <int dim> void ExplicitStepper<dim>::choose_time_step()
  {
    const auto &ep   = sim->parameters().explicit_dynamics;
    const auto &time = sim->parameters().time;
    J_at_estimate    = integrator->min_J();
    if (!sim->resumed()) // a restart continues with the saved step
    {
      critical_step = integrator->critical_time_step(40);
      set_time_step(ep.fixed_time_step > 0 ? ep.fixed_time_step
                                           : step_fraction() * critical_step);
    }
    else // the saved step (no power iteration: the saved mode stays)
    {
      set_time_step(time_step);
      critical_step = time_step / step_fraction();
    }
    // the damped stable step with the beta this run uses (with a fixed
    // step, beta need not be xi times the mesh's critical step)
    const double beta   = ep.stiffness_damping * time_step / step_fraction();
    const double xi_max = beta / critical_step;
    const double stable_limit =
        critical_step * (std::sqrt(1 + xi_max * xi_max) - xi_max);
    if (ep.fixed_time_step > stable_limit)
      throw InputError(
          "'Explicit dynamics/Fixed time step' (" +
          std::to_string(ep.fixed_time_step) +
          " s) exceeds the critical time step of this mesh and material (" +
          std::to_string(stable_limit) +
          " s, with the stiffness damping): the run would blow up. Fix: set it "
          "to 0 (the stable step) or below the critical step.");
    const auto  &limits  = sim->parameters().limits;
    const double n_steps = (time.end_time - integrator->time()) / time_step;
    if (limits.check_size && n_steps > limits.maximum_explicit_steps)
    {
      std::ostringstream message;
      message << "The explicit run needs about " << n_steps << " steps of "
              << time_step << " s to reach 'Time/End time' = " << time.end_time
              << " s, more than 'Run limits/Maximum explicit steps' = "
              << limits.maximum_explicit_steps
              << ". Fix: a shorter end time, 'Explicit dynamics/Mass scaling "
                 "time step' for quasi-static loading, a coarser mesh, or a "
                 "larger limit ('Run limits/Check run size = false' skips the "
                 "check).";
      throw InputError(message.str());
    }
    sim->out() << "Explicit dynamics: critical step " << critical_step
               << " s, step " << time_step << " s, added mass " << added_mass
               << " %,";
    if (ep.stiffness_damping > 0)
      sim->out() << " stiffness damping beta " << beta << " s (xi = " << xi_max
                 << " at the highest frequency),";
    sim->out() << " about "
               << std::lround((time.end_time - integrator->time()) / time_step)
               << " steps." << std::endl;
  }

  template <int dim>
  void ExplicitStepper<dim>::advance_to(const double t_record)
  {
    const auto &ep = sim->parameters().explicit_dynamics;
    while (integrator->time() < t_record - 1e-9 * time_step)
    {
      const double remaining = t_record - integrator->time();
      const double dt = remaining / std::ceil(remaining / time_step - 1e-9);
      using Result    = typename CentralDifference<dim>::StepResult;
      Result result;
      {
        TimerOutput::Scope scope(sim->timers(), "time steps");
        result = integrator->step(dt);
      }
      switch (result)
      {
      case Result::ok:
        break;
      case Result::not_finite:
        fail("a displacement or acceleration became NaN or infinite",
             "reduce 'Explicit dynamics/Safety factor' (or 'Fixed time "
             "step') and check the material parameters.");
      case Result::inverted:
        fail("an element would invert (det F <= 0)",
             "load more slowly (a longer 'Time/End time'), refine the "
             "mesh where it is compressed most, or add 'Explicit "
             "dynamics/Mass damping'.");
      case Result::unbalanced:
        fail("the energy the integration creates would exceed "
             "'Explicit dynamics/Energy balance limit' = " +
                 std::to_string(ep.energy_balance_limit) +
                 ": the integration is unstable",
             "reduce 'Explicit dynamics/Safety factor' or 'Fixed time "
             "step', and check that the rigid bodies do not move "
             "faster than the tissue can follow.");
      }
      ++steps;
      if (explicit_contact)
        worst_penetration =
            std::max(worst_penetration, explicit_contact->max_penetration());
      // The critical step shrinks as elements are compressed: recompute
      // it every 'Stable step interval' steps, and as soon as the
      // smallest det F has changed by 5 % since the last estimate.
      const bool deformed =
          std::abs(integrator->min_J() - J_at_estimate) > 0.05;
      if (ep.fixed_time_step == 0 &&
          (steps % ep.stable_step_interval == 0 || deformed))
      {
        J_at_estimate = integrator->min_J();
        critical_step = integrator->critical_time_step(8);
        set_time_step(step_fraction() * critical_step);
      }
    }
  }

  template <int dim>
  bool ExplicitStepper<dim>::finish_record(const double t_record)
  {
    RunState   &state      = sim->state();
    const auto &parameters = sim->parameters();
    ++state.step;
    state.time      = t_record;
    state.step_size = time_step;
    record_state(t_record);
    const bool stopped = sim->stop_requested();
    const bool last =
        stopped || state.time >= parameters.time.end_time * (1 - 1e-12);
    const unsigned int vtu = parameters.output.vtu_interval;
    if ((vtu > 0 && state.step % vtu == 0) || last)
      sim->write_fields(t_record);
    const unsigned int every = parameters.checkpoint.interval;
    // A run stopped by its criterion can be continued (or branched from).
    if ((every > 0 && state.step % every == 0) || stopped)
      save_checkpoint();
    print_progress(t_record, time_step);
    return stopped;
  }

  template class ExplicitStepper<2>;
  template class ExplicitStepper<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_TIME_STEPPER(
    softgrasp::ExplicitStepper,
    explicit_dynamic,
    "explicit dynamic",
    "central differences with a lumped mass and the stable time step "
    "(inertia included; the 'Explicit dynamics' subsection applies, and "
    "'Time step' is the interval between recorded states)")
