#include <deal.II/base/multithread_info.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/postprocess/contact_force_report.h>
#include <softgrasp/postprocess/corner_jacobian.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// Where the implicit solvers' incremental potential puts its contact
    /// terms, its penalty factor and its friction's slip length or speed,
    /// for the run's summary; empty for the Lagrange multipliers.
    std::string potential_summary(const ContactParameters &given)
    {
      if (given.implicit_enforcement() != "incremental potential")
        return "";
      const ContactParameters used = given.for_implicit();
      std::ostringstream      text;
      text << ", on the " << (used.integrate_on_faces ? "faces" : "nodes")
           << (given.potential_integration == "automatic" ? " (automatic)" : "")
           << ", penalty factor " << used.penalty_factor
           << (given.penalty_factor == 0 ? " (automatic)" : "");
      if (given.friction_coefficient > 0)
      {
        if (given.slip_speed > 0)
          text << ", slip speed " << given.slip_speed
               << " m/s (slip length = speed x step)";
        else
          text << ", slip length " << given.slip_tolerance << " m";
      }
      return text.str();
    }
  } // namespace

  template <int dim>
  void Simulation<dim>::declare_parameters(ParameterHandler &prm)
  {
    std::vector<std::pair<std::string, std::string>> integrators;
    for (const auto &[name, entry] : TimeStepperRegistry<dim>::all())
      integrators.emplace_back(name, entry.description);
    SolverParameters::declare_parameters(prm, integrators);
    for (const auto &[name, entry] : TimeStepperRegistry<dim>::all())
      entry.declare_parameters(prm);
    MeshFactory<dim>::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    RigidBodySet::declare_parameters(prm);
  }

  template <int dim> void Simulation<dim>::add_passes(ParameterReader &reader)
  {
    MaterialLibrary::add_passes(reader);
    BoundaryConditions<dim>::add_passes(reader);
    RigidBodySet::add_passes(reader);
  }

  template <int dim>
  std::unique_ptr<Simulation<dim>>
  Simulation<dim>::create(MPI_Comm comm, ParameterHandler &prm)
  {
    return create(comm, SolverInputs<dim>::parse(prm));
  }

  template <int dim>
  std::unique_ptr<Simulation<dim>>
  Simulation<dim>::create(MPI_Comm comm, const SolverInputs<dim> &inputs)
  {
    return std::make_unique<Simulation<dim>>(comm, inputs);
  }

  template <int dim>
  Simulation<dim>::Simulation(MPI_Comm comm, const SolverInputs<dim> &inputs)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , verbose_out(std::cout,
                    inputs.solver.output.verbose &&
                        Utilities::MPI::this_mpi_process(comm) == 0)
      , solver_parameters(inputs.solver)
      , mesh(inputs.mesh)
      , material_library(inputs.materials)
      , boundary_conditions(inputs.boundary_conditions)
      , contact_parameters(inputs.contact)
      , bodies(inputs.bodies)
      , stepper(TimeStepperRegistry<dim>::create(
            inputs.solver.time.integrator,
            "time integrator ('Time/Integrator')"))
      // Per-rank timers (statistics over ranks come from
      // print_wall_time_statistics): no barrier per section, and no MPI in
      // the destructor, which may run while an error unwinds.
      , timers(pcout, TimerOutput::never, TimerOutput::wall_times)
      , triangulation(comm)
      , recorder(inputs.solver.output, inputs.resume_settings)
  {
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
  }

  template <int dim> void Simulation<dim>::run()
  {
    const SimulationAccess<dim> access(*this);
    stepper->check_inputs(access);
    prepare_run();
    folding = Folding();
    stepper->run(access);
    if (folding.records > 0)
      pcout << "Warning: " << folding.records << " recorded step(s) had a "
            << "folded element (J <= 0 at a cell vertex), the first at t = "
            << folding.first_time << " s (see the first warning)." << std::endl;
    timers.print_wall_time_statistics(comm);
  }

  template <int dim> void Simulation<dim>::prepare_run()
  {
    const bool resume = solver_parameters.checkpoint.resume;
    // A resume holds the lock before it reads the checkpoint; a new run
    // takes the directory (and moves earlier results aside) only after its
    // input has been checked, so that a refused run changes nothing.
    recorder.release_directory();
    if (resume)
      recorder.claim_directory(comm, true);
    const unsigned int mapping_degree =
        mesh.has_curved_boundary() ? solver_parameters.discretization.degree
                                   : 1;
    solid = std::make_unique<SolidSystem<dim>>(triangulation,
                                               material_library,
                                               boundary_conditions,
                                               solver_parameters,
                                               mapping_degree,
                                               timers);
    solid->set_tangent_needed(stepper->needs_tangent());
    stopped = false;
    check_contact_setup();
    {
      TimerOutput::Scope scope(timers, "setup");
      // A generated mesh's size is known before it is built: a run too
      // large for the machine is refused before it runs out of memory.
      const double coarse_cells = mesh.generator().n_coarse_cells();
      if (!resume && coarse_cells > 0)
        check_run_size(coarse_cells);
      mesh.create_coarse_mesh(triangulation);
      if (resume)
      {
        state = recorder.load_checkpoint(
            triangulation,
            *solid,
            restored_fields,
            stepper->n_checkpoint_fields(solver_parameters),
            std::cout);
      }
      else
      {
        if (!(coarse_cells > 0)) // a file: counted once read
          check_run_size(triangulation.n_global_active_cells());
        mesh.refine(triangulation);
        solid->setup();
      }
    }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        material_library.get(cell->material_id()); // throws if unmapped
    check_mesh_references();
    make_contact();
    if (resume)
    {
      pcout << "Resumed from the checkpoint at step " << state.step
            << ", t = " << state.time << " s." << std::endl;
      return;
    }
    recorder.claim_directory(comm, false);
    recorder.start_fresh();
    state           = RunState();
    state.step_size = solver_parameters.time.phase_at(0).step;
  }

  template <int dim> void Simulation<dim>::make_contact()
  {
    contact_surface.reset();
    surface_output.reset();
    if (contact_parameters.slave_boundary_ids.empty())
      return;
    double shear_modulus = 0;
    for (const auto id : material_library.material_ids())
      shear_modulus = std::max(
          shear_modulus, material_library.get(id).initial_shear_modulus());
    contact_surface =
        stepper->make_contact(SimulationAccess<dim>(*this), shear_modulus);
    surface_output = std::make_unique<ContactOutput<dim>>(*contact_surface);
    surface_output->setup(*solid);
  }

  template <int dim>
  void Simulation<dim>::record(const double         time,
                               const HistoryValues &leading,
                               const HistoryValues &trailing)
  {
    static const char *const axes[] = {"x", "y", "z"};
    HistoryValues row = {{"step", double(state.step)}, {"time", time}};
    row.insert(row.end(), leading.begin(), leading.end());
    for (const auto &[id, force] : solid->reactions())
      for (unsigned int d = 0; d < dim; ++d)
        row.emplace_back("reaction_" + std::to_string(id) + "_" + axes[d],
                         force[d]);
    const auto displacements = solid->point_displacements(monitor_points);
    for (std::size_t p = 0; p < displacements.size(); ++p)
      for (unsigned int d = 0; d < dim; ++d)
        row.emplace_back("u" + std::to_string(p) + "_" + axes[d],
                         displacements[p][d]);
    row.insert(row.end(), trailing.begin(), trailing.end());
    row.emplace_back("min_corner_J", report_folding(time));
    if (surface_output)
    {
      // the deepest penetration of the tissue into a geom, and where
      const auto deepest =
          contact_surface->deepest_penetration(solid->ghosted_solution());
      row.emplace_back("penetration", deepest.depth);
      for (unsigned int d = 0; d < dim; ++d)
        row.emplace_back(std::string("penetration_") + axes[d],
                         deepest.position[d]);
    }
    recorder.add_history_row(row);
    if (surface_output)
    {
      ContactForceRecord record;
      record.step               = state.step;
      record.time               = time;
      record.forces             = surface_output->geom_forces(*solid);
      HistoryValues contact_row = {{"step", double(state.step)},
                                   {"time", time}};
      const auto    names       = surface_output->history_columns();
      const auto    values      = surface_output->history_values(record.forces);
      for (std::size_t k = 0; k < names.size(); ++k)
        contact_row.emplace_back(names[k], values[k]);
      contact_row.emplace_back("stick_slip_drop", report_force_drops(record));
      recorder.add_contact_row(std::move(record), contact_row);
    }
    TimerOutput::Scope scope(timers, "output");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      recorder.write_tables();
  }

  template <int dim>
  double Simulation<dim>::report_force_drops(const ContactForceRecord &record)
  {
    // a drop of more than 3 % of a drag within one step
    const auto &records = recorder.contact_forces();
    if (records.empty())
      return 0;
    double largest = 0;
    for (const auto &drop : lateral_force_drops(records.back(), record, 0.03))
    {
      largest = std::max(largest, drop.fraction());
      pcout << "Stick-slip event at t = " << record.time << " s: the lateral "
            << "force on " << bodies.geom_label(drop.body, drop.geom)
            << " fell by " << 100 * drop.fraction() << " % in one step ("
            << drop.before << " -> " << drop.after << " N)." << std::endl;
    }
    return largest;
  }

  template <int dim> double Simulation<dim>::report_folding(const double time)
  {
    solid->update_ghosts();
    const auto corner = smallest_corner_jacobian(solid->mapping(),
                                                 solid->dof_handler(),
                                                 solid->ghosted_solution(),
                                                 comm);
    if (corner.folded())
    {
      if (folding.records == 0)
        folding.first_time = time;
      if (!folding.now)
        pcout << "Warning: folded element at t = " << time
              << " s: J = det F = " << corner.J
              << " at a cell vertex at reference position " << corner.position
              << " m (positive at the quadrature points, so the solver "
              << "accepts it). Forces after a fold are not to be trusted: "
              << "the mesh is too coarse there, or the tissue creases "
              << "(self-contact is not modelled). Fix: refine the mesh there "
              << "(e.g. Mesh/Block/Fine zone) and see whether the fold "
              << "stays; column 'min_corner_J' of the history." << std::endl;
      ++folding.records;
    }
    folding.now = corner.folded();
    return corner.J;
  }

  template <int dim> void Simulation<dim>::write_fields(const double time)
  {
    if (recorder.fields_written_at(state.step))
      return;
    TimerOutput::Scope scope(timers, "output");
    solid->update_ghosts();
    typename FieldOutput<dim>::ExtraFields extra;
    if (surface_output)
      extra = [this](DataOut<dim> &data_out)
      { surface_output->add_fields(*solid, data_out); };
    recorder.write_fields(*solid, material_library, time, state, extra);
  }

  template <int dim>
  void Simulation<dim>::print_summary(const std::string &integrator) const
  {
    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells, "
          << solid->n_dofs() << " displacement dofs ("
          << solver_parameters.discretization.element_name() << ", "
          << integrator << "), " << Utilities::MPI::n_mpi_processes(comm)
          << " MPI rank(s) x " << MultithreadInfo::n_threads() << " thread(s)."
          << std::endl;
    if (stepper->needs_tangent())
      pcout << "Linear solver: " << solid->linear_solver_name() << std::endl;
    if (stepper->needs_tangent() &&
        !contact_parameters.slave_boundary_ids.empty())
      pcout << "Contact enforcement: "
            << contact_parameters.implicit_enforcement()
            << (contact_parameters.enforcement == "automatic"
                    ? " ('automatic': friction coefficient " +
                          std::to_string(
                              contact_parameters.friction_coefficient) +
                          ")"
                    : "")
            << potential_summary(contact_parameters) << std::endl;
    for (const auto id : material_library.material_ids())
      pcout << "Material " << static_cast<unsigned>(id) << ": "
            << material_library.get(id).summary() << std::endl;
    for (const auto &line : material_library.implausible_constants())
      pcout << "Warning: " << line << std::endl;
  }

  template <int dim>
  void Simulation<dim>::set_stop_criterion(std::function<bool()> f)
  {
    stop_criterion = std::move(f);
  }

  template <int dim> bool Simulation<dim>::stopped_by_criterion() const
  {
    return stopped;
  }

  template <int dim> const SolidSystem<dim> &Simulation<dim>::system() const
  {
    return *solid;
  }

  template <int dim> const HistoryWriter &Simulation<dim>::history() const
  {
    return recorder.history();
  }

  template <int dim> const MaterialLibrary &Simulation<dim>::materials() const
  {
    return material_library;
  }

  template <int dim> const SolverParameters &Simulation<dim>::parameters() const
  {
    return solver_parameters;
  }

  template <int dim> RigidBodySet &Simulation<dim>::rigid_bodies()
  {
    return bodies;
  }

  template <int dim> const RigidBodySet &Simulation<dim>::rigid_bodies() const
  {
    return bodies;
  }

  template <int dim> const ContactSurface<dim> *Simulation<dim>::contact() const
  {
    return contact_surface.get();
  }

  template <int dim>
  const ContactOutput<dim> *Simulation<dim>::contact_output() const
  {
    return surface_output.get();
  }

  template <int dim>
  const HistoryWriter &Simulation<dim>::contact_history() const
  {
    return recorder.contact_history();
  }

  template <int dim>
  const std::vector<ContactForceRecord> &
  Simulation<dim>::contact_force_history() const
  {
    return recorder.contact_forces();
  }

  template <int dim> TimerOutput &Simulation<dim>::timer()
  {
    return timers;
  }

  template <int dim>
  void report_contact_forces(const Simulation<dim> &simulation,
                             const std::string     &base,
                             std::ostream          &out)
  {
    report_contact_forces(simulation.system().communicator(),
                          simulation.rigid_bodies(),
                          simulation.contact_force_history(),
                          dim,
                          simulation.parameters().output.directory,
                          base,
                          out);
  }

  template class Simulation<2>;
  template class Simulation<3>;
  template void report_contact_forces(const Simulation<2> &,
                                      const std::string &,
                                      std::ostream &);
  template void report_contact_forces(const Simulation<3> &,
                                      const std::string &,
                                      std::ostream &);
} // namespace softgrasp
