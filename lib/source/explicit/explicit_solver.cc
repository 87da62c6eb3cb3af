#include <array>
#include <cmath>
#include <deal.II/dofs/dof_tools.h>
#include <iomanip>
#include <limits>
#include <softgrasp/base/input_error.h>
#include <softgrasp/explicit/explicit_solver.h>
#include <softgrasp/explicit/lumped_mass.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  ExplicitSolver<dim>::ExplicitSolver(MPI_Comm                 comm,
                                      const SolverInputs<dim> &inputs)
      : MechanicsSolver<dim>(comm, inputs)
  {
    // half-step velocity, highest mode and, with stiffness damping, the
    // damping force of the last step
    this->n_restored_fields =
        this->solver_parameters.explicit_dynamics.stiffness_damping > 0 ? 3 : 2;
  }

  template <int dim>
  std::unique_ptr<ContactSurface<dim>>
  ExplicitSolver<dim>::make_contact(const double /*shear_modulus*/)
  {
    auto contact = std::make_unique<ExplicitContact<dim>>(
        this->contact_parameters, this->bodies, this->timers);
    contact->setup(*this->solid);
    explicit_contact = contact.get();
    return contact;
  }

  template <int dim> void ExplicitSolver<dim>::check_loads() const
  {
    const auto &bcs = this->boundary_conditions;
    if (!bcs.tractions.empty() || !bcs.pressures.empty() || bcs.has_gravity())
      throw InputError(
          "The explicit solver ('Time/Integrator = explicit dynamic') takes "
          "prescribed displacements and contact with rigid bodies; "
          "tractions, pressures and gravity are not offered by it yet. Fix: "
          "use 'Time/Integrator = quasi-static', or apply the load through a "
          "prescribed displacement or a rigid body.");
  }

  template <int dim> void ExplicitSolver<dim>::setup_integrator()
  {
    const auto &dofs = this->solid->dof_handler();
    hanging.clear();
    hanging.reinit(this->solid->locally_relevant_dofs());
    DoFTools::make_hanging_node_constraints(dofs, hanging);
    hanging.close();
    const auto &element = this->solver_parameters.discretization;
    using Operator      = InternalForceOperator<dim>;
    using Kernel        = typename Operator::Kernel;
    using Dilatation    = typename Operator::Dilatation;
    const Dilatation dilatation =
        element.formulation == Formulation::displacement
            ? Dilatation::pointwise
            : (element.pressure_degree() == 0 ? Dilatation::element_constant
                                              : Dilatation::element_linear);
    force = std::make_unique<Operator>(
        this->solid->mapping(),
        dofs,
        hanging,
        this->material_library,
        dilatation,
        this->solver_parameters.explicit_dynamics.vectorized_force_kernel
            ? Kernel::vectorized
            : Kernel::reference);
    force->initialize_dof_vector(mass);
    compute_lumped_mass(
        this->solid->mapping(), dofs, hanging, this->material_library, mass);
    physical_mass = mass.l1_norm() / dim;
    added_mass    = 0;
    setup_prescribed();
    const auto &constraints = this->solid->constraint_set();
    fixed                   = IndexSet(dofs.n_dofs());
    for (const auto i : this->solid->locally_owned_dofs())
      if (constraints.is_constrained(i))
        fixed.add_index(i);
    fixed.compress();
    integrator = std::make_unique<CentralDifference<dim>>(
        *force,
        mass,
        fixed,
        this->solver_parameters.explicit_dynamics.mass_damping);
    // The balance limit acts after the first 2 % of the run.
    integrator->set_balance_limit(
        this->solver_parameters.explicit_dynamics.energy_balance_limit,
        0.02 * this->solver_parameters.time.end_time);
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
        this->solver_parameters.explicit_dynamics.mass_scaling_time_step;
    if (target > 0)
      scale_mass(target);
  }

  template <int dim> double ExplicitSolver<dim>::step_fraction() const
  {
    // central differences with damping lagged half a step: the highest
    // mode is stable up to 2/omega (sqrt(1 + xi^2) - xi), xi = beta omega/2
    const auto  &ep = this->solver_parameters.explicit_dynamics;
    const double xi = ep.stiffness_damping;
    return ep.safety_factor * (std::sqrt(1 + xi * xi) - xi);
  }

  template <int dim> void ExplicitSolver<dim>::set_time_step(const double dt)
  {
    // beta = xi x the critical step the time step stands for, so that a
    // restart (which knows the time step) damps exactly as before
    time_step = dt;
    integrator->set_stiffness_damping(
        this->solver_parameters.explicit_dynamics.stiffness_damping * dt /
        step_fraction());
  }

  template <int dim>
  void ExplicitSolver<dim>::scale_mass(const double target_step)
  {
    // Element estimates dt_e = k h_e / c_e (h_e the smallest vertex
    // distance, c_e the dilatational wave speed), calibrated by k so that
    // the smallest equals the critical step of the unscaled mesh (power
    // iteration). Elements below the target get their density scaled by
    // (target / dt_e)^2; the scaled mesh's critical step is then measured
    // again by the caller.
    const double        critical = integrator->critical_time_step(40);
    const auto         &tria     = this->triangulation;
    std::vector<double> estimate(tria.n_active_cells(), 0.0);
    double              smallest = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const double c = this->material_library.get(cell->material_id())
                             .reference_wave_speed();
        estimate[cell->active_cell_index()] =
            cell->minimum_vertex_distance() / c;
        smallest = std::min(smallest, estimate[cell->active_cell_index()]);
      }
    smallest              = Utilities::MPI::min(smallest, this->comm);
    const double        k = critical / smallest;
    std::vector<double> factor(tria.n_active_cells(), 1.0);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const double dt_e = k * estimate[cell->active_cell_index()];
        if (dt_e < target_step)
          factor[cell->active_cell_index()] = std::pow(target_step / dt_e, 2);
      }
    compute_lumped_mass(this->solid->mapping(),
                        this->solid->dof_handler(),
                        hanging,
                        this->material_library,
                        mass,
                        factor);
    added_mass = 100 * (mass.l1_norm() / dim - physical_mass) / physical_mass;
  }

  template <int dim> void ExplicitSolver<dim>::setup_prescribed()
  {
    const auto &dofs  = this->solid->dof_handler();
    const auto &owned = this->solid->locally_owned_dofs();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(this->solid->mapping(), dofs, points);
    prescribed.clear();
    std::set<types::global_dof_index> claimed;
    for (const auto &d : this->boundary_conditions.dirichlet)
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
  void ExplicitSolver<dim>::prescribe(const double time, VectorType &u)
  {
    this->boundary_conditions.set_time(time);
    for (const auto &p : prescribed)
      u(p.index) = p.function->value(p.point, p.component);
    if (hanging.n_constraints() > 0)
      hanging.distribute(u);
  }

  template <int dim> void ExplicitSolver<dim>::update_system()
  {
    const VectorType &u        = integrator->displacement();
    auto             &solution = this->solid->solution();
    for (const auto i : this->solid->locally_owned_dofs())
      solution[i] = u(i);
    solution.compress(VectorOperation::insert);
    this->solid->update_ghosts();
    // The reactions f_int - f_ext at the supports: the integrator's own
    // (matrix-free) forces of this state.
    const VectorType &f_int = integrator->internal_forces();
    const VectorType &f_ext = integrator->external_forces_now();
    this->solid->set_forces(
        [&](const types::global_dof_index i) { return f_int(i); },
        [&](const types::global_dof_index i) { return f_ext(i); });
  }

  template <int dim> void ExplicitSolver<dim>::record_state(const double time)
  {
    update_system();
    const auto          e        = integrator->energies();
    std::vector<double> trailing = {e.kinetic,
                                    e.internal,
                                    e.external_work,
                                    e.support_work,
                                    e.contact_work,
                                    e.damping,
                                    e.balance_error,
                                    integrator->min_J(),
                                    added_mass};
    if (explicit_contact)
    {
      trailing.push_back(explicit_contact->n_active());
      trailing.push_back(explicit_contact->n_slip());
      trailing.push_back(worst_penetration);
    }
    this->record(
        time, {time_step, double(steps), this->progress.elapsed()}, trailing);
    worst_penetration = 0;
  }

  template <int dim> void ExplicitSolver<dim>::save_checkpoint()
  {
    // Ghosted Trilinos copies of the half-step velocity, the highest mode
    // (the power iteration's warm start) and the damping force.
    std::array<TrilinosWrappers::MPI::Vector, 3> fields;
    const std::array<const VectorType *, 3>      sources = {
             {&integrator->velocity_half_step(),
              &integrator->highest_mode(),
              &integrator->damping_force()}};
    for (unsigned int k = 0; k < this->n_restored_fields; ++k)
    {
      TrilinosWrappers::MPI::Vector owned(this->solid->locally_owned_dofs(),
                                          this->comm);
      for (const auto i : this->solid->locally_owned_dofs())
        owned[i] = (*sources[k])(i);
      owned.compress(VectorOperation::insert);
      fields[k].reinit(this->solid->locally_owned_dofs(),
                       this->solid->locally_relevant_dofs(),
                       this->comm);
      fields[k] = owned;
    }
    this->state.integrator_state = integrator->state_scalars();
    this->state.integrator_state.insert(this->state.integrator_state.end(),
                                        {double(steps), time_step});
    std::vector<const TrilinosWrappers::MPI::Vector *> written;
    for (unsigned int k = 0; k < this->n_restored_fields; ++k)
      written.push_back(&fields[k]);
    this->write_checkpoint(written);
  }

  template <int dim>
  void ExplicitSolver<dim>::write_last_good_state(const double time)
  {
    ++this->state.step;
    this->state.time = time;
    record_state(time);
    this->write_fields(time);
    save_checkpoint();
  }

  template <int dim>
  void ExplicitSolver<dim>::fail(const std::string &cause,
                                 const std::string &fix)
  {
    const double t = integrator->time();
    write_last_good_state(t);
    std::ostringstream message;
    message << "Explicit step " << steps + 1 << " (from t = " << t
            << " s, dt = " << time_step << " s) was refused: " << cause
            << ". The last good state (t = " << t << " s) was written to '"
            << this->solver_parameters.output.directory
            << "' (VTU and checkpoint). Fix: " << fix;
    throw SolverFailure(message.str());
  }

  template <int dim>
  void ExplicitSolver<dim>::print_progress(const double time,
                                           const double dt) const
  {
    const auto   e   = integrator->energies();
    const double end = this->solver_parameters.time.end_time;
    this->pcout << "Record " << std::setw(4) << this->state.step
                << "  t = " << std::setw(10) << time << " s (" << std::setw(3)
                << std::lround(100 * time / end) << "%)  steps " << steps
                << "  dt = " << std::setprecision(3) << dt
                << " s  E_kin = " << e.kinetic << " J  balance "
                << 100 * e.balance_error << "%";
    if (explicit_contact)
      this->pcout << "  contact " << explicit_contact->n_active() << " ("
                  << explicit_contact->n_slip() << " slip)";
    this->pcout << std::setprecision(6) << "  wall "
                << ProgressReporter::format_duration(this->progress.elapsed())
                << "  ETA "
                << ProgressReporter::format_duration(this->progress.eta(time))
                << std::endl;
  }

  template <int dim> void ExplicitSolver<dim>::run()
  {
    check_loads();
    const auto              &ep   = this->solver_parameters.explicit_dynamics;
    const auto              &time = this->solver_parameters.time;
    std::vector<std::string> trailing = {"kinetic_energy",
                                         "internal_energy",
                                         "external_work",
                                         "support_work",
                                         "contact_work",
                                         "damping_energy",
                                         "energy_balance_error",
                                         "min_J",
                                         "added_mass_percent"};
    if (!this->contact_parameters.slave_boundary_ids.empty())
      for (const char *name :
           {"contact_active_nodes", "contact_slip_nodes", "max_penetration"})
        trailing.push_back(name);
    explicit_contact = nullptr;
    this->prepare_run({"time_step", "time_steps", "wall_time"}, trailing);
    setup_integrator();
    this->print_summary("explicit dynamic");

    VectorType u, v;
    force->initialize_dof_vector(u);
    force->initialize_dof_vector(v);
    const bool resume = this->solver_parameters.checkpoint.resume;
    this->progress.start(this->state.time, time.end_time);
    for (const auto i : this->solid->locally_owned_dofs())
      u(i) = this->solid->solution()[i];
    if (resume)
    {
      VectorType mode, damping;
      force->initialize_dof_vector(mode);
      force->initialize_dof_vector(damping);
      const bool damped = this->n_restored_fields > 2;
      for (const auto i : this->solid->locally_owned_dofs())
      {
        v(i)    = this->restored_fields[0][i];
        mode(i) = this->restored_fields[1][i];
        if (damped)
          damping(i) = this->restored_fields[2][i];
      }
      auto scalars = this->state.integrator_state;
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
    else
    {
      steps = 0;
      if (explicit_contact)
      {
        const auto [inside, overlap] =
            explicit_contact->relax_initial_overlap(0.0, u, 100);
        if (inside > 0)
          this->pcout << "Initial overlap: " << inside
                      << " contact node(s) start inside a rigid body (up to "
                      << overlap
                      << " m); they are pushed out over the first 100 steps."
                      << std::endl;
      }
      integrator->initialize(0.0, u, v);
      record_state(0.0);
      this->write_fields(0.0);
    }

    J_at_estimate = integrator->min_J();
    if (!resume) // a restart continues with the saved step
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
    const auto  &limits  = this->solver_parameters.limits;
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
    this->pcout << "Explicit dynamics: critical step " << critical_step
                << " s, step " << time_step << " s, added mass " << added_mass
                << " %,";
    if (ep.stiffness_damping > 0)
      this->pcout << " stiffness damping beta " << beta << " s (xi = " << xi_max
                  << " at the highest frequency),";
    this->pcout << " about "
                << std::lround((time.end_time - integrator->time()) / time_step)
                << " steps." << std::endl;

    while (this->state.time < time.end_time * (1 - 1e-12))
    {
      // the next recorded time: on the grid of the phase's interval
      const TimePhase phase = time.phase_at(this->state.time);
      const double    begin = time.phase_begin(this->state.time);
      const double    k =
          std::floor((this->state.time - begin) / phase.step + 0.5);
      const double t_record = std::min(phase.end, begin + (k + 1) * phase.step);
      while (integrator->time() < t_record - 1e-9 * time_step)
      {
        const double remaining = t_record - integrator->time();
        const double dt = remaining / std::ceil(remaining / time_step - 1e-9);
        using Result    = typename CentralDifference<dim>::StepResult;
        Result result;
        {
          TimerOutput::Scope scope(this->timers, "time steps");
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
      ++this->state.step;
      this->state.time      = t_record;
      this->state.step_size = time_step;
      record_state(t_record);
      this->stopped = this->stop_criterion && this->stop_criterion();
      const bool last =
          this->stopped || this->state.time >= time.end_time * (1 - 1e-12);
      const unsigned int vtu = this->solver_parameters.output.vtu_interval;
      if ((vtu > 0 && this->state.step % vtu == 0) || last)
        this->write_fields(t_record);
      const unsigned int every = this->solver_parameters.checkpoint.interval;
      // A run stopped by its criterion can be continued (or branched from).
      if ((every > 0 && this->state.step % every == 0) || this->stopped)
        save_checkpoint();
      print_progress(t_record, time_step);
      if (this->stopped)
      {
        this->pcout << "Stop criterion met at t = " << t_record << " s."
                    << std::endl;
        break;
      }
    }
    this->timers.print_wall_time_statistics(this->comm);
  }

  template <int dim> double ExplicitSolver<dim>::added_mass_percent() const
  {
    return added_mass;
  }

  template <int dim> unsigned long ExplicitSolver<dim>::n_time_steps() const
  {
    return steps;
  }

  template class ExplicitSolver<2>;
  template class ExplicitSolver<3>;
} // namespace softgrasp
