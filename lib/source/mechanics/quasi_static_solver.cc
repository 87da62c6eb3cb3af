#include <deal.II/base/multithread_info.h>
#include <filesystem>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/io/hdf5_history.h>
#include <softgrasp/mechanics/quasi_static_solver.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void QuasiStaticSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    SolverParameters::declare_parameters(prm);
    MeshFactory<dim>::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    RigidBodySet::declare_parameters(prm);
  }

  template <int dim>
  void QuasiStaticSolver<dim>::add_passes(ParameterReader &reader)
  {
    MaterialLibrary::add_passes(reader);
    BoundaryConditions<dim>::add_passes(reader);
    RigidBodySet::add_passes(reader);
  }

  namespace
  {
    template <typename T> T parsed(ParameterHandler &prm)
    {
      T object;
      object.parse_parameters(prm);
      return object;
    }
  } // namespace

  template <int dim>
  QuasiStaticSolver<dim>::QuasiStaticSolver(MPI_Comm          comm,
                                            ParameterHandler &prm)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , verbose_out(std::cout, false)
      , solver_parameters(parsed<SolverParameters>(prm))
      , mesh(parsed<MeshFactory<dim>>(prm))
      , material_library(parsed<MaterialLibrary>(prm))
      , boundary_conditions(parsed<BoundaryConditions<dim>>(prm))
      , contact_parameters(parsed<ContactParameters>(prm))
      , bodies(parsed<RigidBodySet>(prm))
      , timers(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
      , triangulation(comm)
      , newton(solver_parameters.newton, verbose_out)
      , field_output(solver_parameters.output.directory,
                     solver_parameters.output.base_name)
      , history_writer(solver_parameters.output.directory + "/" +
                       solver_parameters.output.base_name + "_history.csv")
      , contact_writer(solver_parameters.output.directory + "/" +
                       solver_parameters.output.base_name + "_contact.csv")
      , checkpoint(solver_parameters.output.directory)
  {
    verbose_out.set_condition(solver_parameters.output.verbose &&
                              Utilities::MPI::this_mpi_process(comm) == 0);
    for (const auto &coordinates : solver_parameters.output.monitor_points)
    {
      if (coordinates.size() != dim)
        throw InputError("Parameter 'Output/Monitor points' has a point with " +
                         std::to_string(coordinates.size()) +
                         " coordinates in a " + std::to_string(dim) +
                         "D problem. Fix: give " + std::to_string(dim) +
                         " coordinates per point (m).");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = coordinates[d];
      monitor_points.push_back(p);
    }
    // Every material id of the mesh needs a material: checked in setup.
  }

  template <int dim> void QuasiStaticSolver<dim>::setup_fresh()
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        material_library.get(cell->material_id()); // throws if unmapped
    state           = RunState();
    state.step_size = solver_parameters.time.step_size;

    std::vector<std::string> columns = {"step",
                                        "time",
                                        "step_size",
                                        "newton_iterations",
                                        "linear_iterations",
                                        "cut_backs",
                                        "wall_time"};
    const char              *axes[]  = {"x", "y", "z"};
    for (const auto id : boundary_conditions.reaction_boundary_ids())
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("reaction_" + std::to_string(id) + "_" + axes[d]);
    for (unsigned int p = 0; p < monitor_points.size(); ++p)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("u" + std::to_string(p) + "_" + axes[d]);
    if (mortar_contact)
      for (const char *name :
           {"contact_active_nodes", "contact_slip_nodes", "active_set_changes"})
        columns.push_back(name);
    history_writer.set_columns(columns);
    history_writer.rows.clear();
    if (mortar_contact)
    {
      std::vector<std::string> contact_columns = {"step", "time"};
      for (const auto &name : mortar_output->history_columns())
        contact_columns.push_back(name);
      contact_writer.set_columns(contact_columns);
      contact_writer.rows.clear();
    }
  }

  template <int dim> void QuasiStaticSolver<dim>::setup_contact()
  {
    const bool has_surface = !contact_parameters.slave_boundary_ids.empty();
    if (has_surface && bodies.empty())
      throw InputError("'Contact/Slave boundary ids' is set but there is no "
                       "rigid body. Fix: name the bodies in 'Rigid "
                       "bodies/Names' (or add them in code), or leave the "
                       "slave boundary ids empty.");
    if (!has_surface && !bodies.empty())
      throw InputError("Rigid bodies are given but no contact surface. Fix: "
                       "set 'Contact/Slave boundary ids' to the boundary ids "
                       "of the surface the bodies touch.");
    if (!has_surface)
      return;
    double shear_modulus = 0;
    for (const auto id : material_library.material_ids())
      shear_modulus = std::max(
          shear_modulus, material_library.get(id).initial_shear_modulus());
    mortar_contact = std::make_unique<MortarContact<dim>>(
        contact_parameters, bodies, shear_modulus, timers);
    mortar_contact->setup(*solid);
    mortar_output = std::make_unique<ContactOutput<dim>>(*mortar_contact);
    mortar_output->setup(*solid);
    solid->set_nodal_conditions(mortar_contact.get());
  }

  template <int dim> void QuasiStaticSolver<dim>::setup_from_checkpoint()
  {
    {
      TimerOutput::Scope scope(timers, "setup");
      mesh.create_coarse_mesh(triangulation);
    }
    state                  = checkpoint.load(triangulation, *solid);
    history_writer.columns = state.history_columns;
    history_writer.rows    = state.history_rows;
    contact_writer.columns = state.contact_columns;
    contact_writer.rows    = state.contact_rows;
    field_output.records   = state.output_records;
    previous_time          = state.time;
    pcout << "Resumed from the checkpoint at step " << state.step
          << ", t = " << state.time << " s." << std::endl;
  }

  template <int dim> void QuasiStaticSolver<dim>::run()
  {
    const auto &time = solver_parameters.time;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(solver_parameters.output.directory);
    MPI_Barrier(comm);

    const unsigned int mapping_degree =
        mesh.has_curved_boundary() ? solver_parameters.discretization.degree
                                   : 1;
    solid             = std::make_unique<SolidSystem<dim>>(triangulation,
                                               material_library,
                                               boundary_conditions,
                                               solver_parameters,
                                               mapping_degree,
                                               timers);
    stopped           = false;
    const bool resume = solver_parameters.checkpoint.resume;
    if (resume)
    {
      setup_from_checkpoint();
      setup_contact();
    }
    else
    {
      {
        TimerOutput::Scope scope(timers, "setup");
        mesh.create_coarse_mesh(triangulation);
        mesh.refine(triangulation);
      }
      solid->setup();
      setup_contact();
      setup_fresh();
    }
    if (mortar_contact)
    {
      solid->update_ghosts();
      mortar_contact->accept_step(*solid, state.time);
    }

    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells, "
          << solid->n_dofs() << " displacement dofs (Q"
          << solver_parameters.discretization.degree << ", "
          << (solver_parameters.discretization.formulation ==
                      Formulation::mixed_upJ
                  ? "mixed u-p-J"
                  : "displacement")
          << " formulation), " << Utilities::MPI::n_mpi_processes(comm)
          << " MPI rank(s) x " << MultithreadInfo::n_threads() << " thread(s)."
          << std::endl;
    for (const auto id : material_library.material_ids())
      pcout << "Material " << static_cast<unsigned>(id) << ": "
            << material_library.get(id).summary() << std::endl;

    progress.start(state.time, time.end_time);
    std::string report;
    if (!resume)
    {
      if (!solve_step(0.0, report))
        throw SolverFailure("The initial state (t = 0) is not in equilibrium "
                            "and Newton failed on it: " +
                            report +
                            ". Fix: make the loads and prescribed "
                            "displacements zero at t = 0.");
      record_step(0.0, 0, 0, 0);
      write_fields(0.0);
    }

    double     dt            = state.step_size;
    const auto previous_step = [&]() { return state.time; };
    while (previous_step() < time.end_time * (1 - 1e-12))
    {
      unsigned int                  cut_backs   = 0;
      TrilinosWrappers::MPI::Vector u_converged = solid->solution();
      double                        t_new;
      for (;;)
      {
        t_new = std::min(state.time + dt, time.end_time);
        if (time.end_time - t_new < 1e-9 * dt)
          t_new = time.end_time;
        if (solve_step(t_new, report))
          break;
        solid->solution() = u_converged;
        solid->update_ghosts();
        ++cut_backs;
        if (cut_backs > time.max_cut_backs || dt / 2 < time.minimum_step)
        {
          boundary_conditions.set_time(state.time);
          write_fields(state.time);
          write_checkpoint();
          std::ostringstream message;
          message << report << "\nThe step was cut back " << cut_backs - 1
                  << " time(s) down to dt = " << dt
                  << " s without success. The last converged state (step "
                  << state.step << ", t = " << state.time
                  << " s) was written to '"
                  << solver_parameters.output.directory
                  << "' (VTU and checkpoint). Fix: reduce 'Time/Time step', "
                     "check the loads and boundary conditions, or use the "
                     "'mixed u-p-J' formulation for nearly incompressible "
                     "materials.";
          throw SolverFailure(message.str());
        }
        dt /= 2;
        pcout << report << "\n  -> cutting back to dt = " << dt << " s"
              << std::endl;
      }
      state.time = t_new;
      ++state.step;
      record_step(
          t_new, last_newton_iterations, last_linear_iterations, cut_backs);

      const unsigned int vtu = solver_parameters.output.vtu_interval;
      stopped                = stop_criterion && stop_criterion();
      const bool last = stopped || state.time >= time.end_time * (1 - 1e-12);
      if ((vtu > 0 && state.step % vtu == 0) || last)
        write_fields(state.time);
      const unsigned int every = solver_parameters.checkpoint.interval;
      if (every > 0 && state.step % every == 0)
        write_checkpoint();

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
      if (cut_backs == 0)
        dt = std::min(2 * dt, time.step_size);
      state.step_size = dt;
      if (stopped)
      {
        pcout << "Stop criterion met at t = " << state.time << " s."
              << std::endl;
        break;
      }
    }
    timers.print_wall_time_statistics(comm);
  }

  template <int dim>
  void QuasiStaticSolver<dim>::set_stop_criterion(std::function<bool()> f)
  {
    stop_criterion = std::move(f);
  }

  template <int dim> bool QuasiStaticSolver<dim>::stopped_by_criterion() const
  {
    return stopped;
  }

  template <int dim>
  bool QuasiStaticSolver<dim>::solve_step(const double time,
                                          std::string &report)
  {
    boundary_conditions.set_time(time);
    if (mortar_contact)
      mortar_contact->set_time(time);
    const auto result      = newton.solve(*solid);
    last_newton_iterations = result.iterations;
    last_linear_iterations = result.linear_iterations;
    last_residual = result.residuals.empty() ? 0 : result.residuals.back();
    if (result.converged)
      return true;
    std::ostringstream message;
    message << "Step " << state.step + 1 << " (t = " << time
            << " s, from t = " << state.time << " s) failed: " << result.failure
            << ". Residual history (N):";
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
    std::vector<double> row = {double(state.step),
                               time,
                               state.step == 0 ? 0.0 : time - previous_time,
                               double(newton_iterations),
                               double(linear_iterations),
                               double(cut_backs),
                               progress.elapsed()};
    previous_time           = time;
    for (const auto &[id, force] : solid->reactions())
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(force[d]);
    for (const auto &u : solid->point_displacements(monitor_points))
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(u[d]);
    if (mortar_contact)
    {
      row.push_back(mortar_contact->n_active());
      row.push_back(mortar_contact->n_slip());
      row.push_back(mortar_contact->changes_in_step());
      std::vector<double> contact_row = {double(state.step), time};
      for (const double v : mortar_output->history_values(*solid))
        contact_row.push_back(v);
      contact_writer.add_row(contact_row);
      mortar_contact->accept_step(*solid, time);
    }
    history_writer.add_row(row);
    TimerOutput::Scope scope(timers, "output");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      history_writer.write();
      if (mortar_contact)
      {
        contact_writer.write();
        write_history_hdf5(contact_writer,
                           solver_parameters.output.directory + "/" +
                               solver_parameters.output.base_name +
                               "_contact.h5",
                           "softgrasp contact history 1",
                           dim);
      }
    }
  }

  template <int dim>
  void QuasiStaticSolver<dim>::write_fields(const double time)
  {
    if (last_output_step == state.step)
      return;
    TimerOutput::Scope scope(timers, "output");
    solid->update_ghosts();
    typename FieldOutput<dim>::ExtraFields extra;
    if (mortar_output)
      extra = [this](DataOut<dim> &data_out)
      { mortar_output->add_fields(*solid, data_out); };
    field_output.write(
        *solid, material_library, time, state.n_outputs++, extra);
    last_output_step = state.step;
  }

  template <int dim> void QuasiStaticSolver<dim>::write_checkpoint()
  {
    TimerOutput::Scope scope(timers, "checkpoint");
    state.history_columns = history_writer.columns;
    state.history_rows    = history_writer.rows;
    state.output_records  = field_output.records;
    state.contact_columns = contact_writer.columns;
    state.contact_rows    = contact_writer.rows;
    solid->update_ghosts();
    checkpoint.save(triangulation, *solid, state);
  }

  template <int dim>
  const SolidSystem<dim> &QuasiStaticSolver<dim>::system() const
  {
    return *solid;
  }

  template <int dim>
  const HistoryWriter &QuasiStaticSolver<dim>::history() const
  {
    return history_writer;
  }

  template <int dim>
  const MaterialLibrary &QuasiStaticSolver<dim>::materials() const
  {
    return material_library;
  }

  template <int dim>
  const SolverParameters &QuasiStaticSolver<dim>::parameters() const
  {
    return solver_parameters;
  }

  template <int dim> RigidBodySet &QuasiStaticSolver<dim>::rigid_bodies()
  {
    return bodies;
  }

  template <int dim>
  const MortarContact<dim> *QuasiStaticSolver<dim>::contact() const
  {
    return mortar_contact.get();
  }

  template <int dim>
  const ContactOutput<dim> *QuasiStaticSolver<dim>::contact_output() const
  {
    return mortar_output.get();
  }

  template <int dim>
  const HistoryWriter &QuasiStaticSolver<dim>::contact_history() const
  {
    return contact_writer;
  }

  template <int dim> TimerOutput &QuasiStaticSolver<dim>::timer()
  {
    return timers;
  }

  template class QuasiStaticSolver<2>;
  template class QuasiStaticSolver<3>;
} // namespace softgrasp
