#include <algorithm>
#include <cmath>
#include <deal.II/base/multithread_info.h>
#include <filesystem>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/explicit/explicit_solver.h>
#include <softgrasp/io/hdf5_history.h>
#include <softgrasp/mechanics/mechanics_solver.h>
#include <softgrasp/mechanics/quasi_static_solver.h>
#include <sstream>
#include <unistd.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void MechanicsSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    SolverParameters::declare_parameters(prm);
    MeshFactory<dim>::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    RigidBodySet::declare_parameters(prm);
  }

  template <int dim>
  void MechanicsSolver<dim>::add_passes(ParameterReader &reader)
  {
    MaterialLibrary::add_passes(reader);
    BoundaryConditions<dim>::add_passes(reader);
    RigidBodySet::add_passes(reader);
  }

  template <int dim>
  std::unique_ptr<MechanicsSolver<dim>>
  MechanicsSolver<dim>::create(MPI_Comm comm, ParameterHandler &prm)
  {
    return create(comm, SolverInputs<dim>::parse(prm));
  }

  template <int dim>
  std::unique_ptr<MechanicsSolver<dim>>
  MechanicsSolver<dim>::create(MPI_Comm comm, const SolverInputs<dim> &inputs)
  {
    if (inputs.solver.time.integrator == TimeIntegrator::explicit_dynamic)
      return std::make_unique<ExplicitSolver<dim>>(comm, inputs);
    return std::make_unique<QuasiStaticSolver<dim>>(comm, inputs);
  }

  template <int dim>
  MechanicsSolver<dim>::MechanicsSolver(MPI_Comm                 comm,
                                        const SolverInputs<dim> &inputs)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , verbose_out(std::cout, false)
      , solver_parameters(inputs.solver)
      , mesh(inputs.mesh)
      , material_library(inputs.materials)
      , boundary_conditions(inputs.boundary_conditions)
      , contact_parameters(inputs.contact)
      , bodies(inputs.bodies)
      // Per-rank timers (statistics over ranks come from
      // print_wall_time_statistics): no barrier per section, and no MPI in
      // the destructor, which may run while an error unwinds.
      , timers(pcout, TimerOutput::never, TimerOutput::wall_times)
      , triangulation(comm)
      , field_output(solver_parameters.output.directory,
                     solver_parameters.output.base_name)
      , history_writer(solver_parameters.output.directory + "/" +
                       solver_parameters.output.base_name + "_history.csv")
      , contact_writer(solver_parameters.output.directory + "/" +
                       solver_parameters.output.base_name + "_contact.csv")
      , checkpoint(solver_parameters.output.directory, inputs.resume_settings)
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
  }

  template <int dim>
  void
  MechanicsSolver<dim>::prepare_run(const std::vector<std::string> &leading,
                                    const std::vector<std::string> &trailing)
  {
    const bool resume = solver_parameters.checkpoint.resume;
    // A resume holds the lock before it reads the checkpoint; a new run
    // takes the directory (and moves earlier results aside) only after its
    // input has been checked, so that a refused run changes nothing.
    run_directory.reset();
    if (resume)
      claim_output_directory();
    const unsigned int mapping_degree =
        mesh.has_curved_boundary() ? solver_parameters.discretization.degree
                                   : 1;
    solid = std::make_unique<SolidSystem<dim>>(triangulation,
                                               material_library,
                                               boundary_conditions,
                                               solver_parameters,
                                               mapping_degree,
                                               timers);
    solid->set_tangent_needed(needs_tangent());
    stopped          = false;
    last_output_step = static_cast<unsigned int>(-1);
    check_contact_setup();
    {
      TimerOutput::Scope scope(timers, "setup");
      mesh.create_coarse_mesh(triangulation);
      if (resume)
      {
        state =
            checkpoint.load(triangulation, *solid, restored_fields, std::cout);
        if (restored_fields.size() != n_restored_fields)
          throw InputError(
              "The checkpoint in '" + solver_parameters.output.directory +
              "' holds " + std::to_string(restored_fields.size()) +
              " field(s) besides the displacement, this solver needs " +
              std::to_string(n_restored_fields) +
              ": it was written by the other time integrator (or, for the "
              "explicit one, with 'Explicit dynamics/Stiffness damping' "
              "switched on or off). Fix: resume with the 'Time/Integrator' "
              "and the stiffness damping of the run that wrote it.");
      }
      else
      {
        check_run_size();
        mesh.refine(triangulation);
        solid->setup();
      }
    }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        material_library.get(cell->material_id()); // throws if unmapped
    check_mesh_references();

    contact_surface.reset();
    surface_output.reset();
    if (!contact_parameters.slave_boundary_ids.empty())
    {
      double shear_modulus = 0;
      for (const auto id : material_library.material_ids())
        shear_modulus = std::max(
            shear_modulus, material_library.get(id).initial_shear_modulus());
      contact_surface = make_contact(shear_modulus);
      surface_output  = std::make_unique<ContactOutput<dim>>(*contact_surface);
      surface_output->setup(*solid);
    }

    if (resume)
    {
      history_writer.columns = state.history_columns;
      history_writer.rows    = state.history_rows;
      contact_writer.columns = state.contact_columns;
      contact_writer.rows    = state.contact_rows;
      contact_forces.clear();
      for (const auto &packed : state.contact_force_records)
        contact_forces.push_back(ContactForceRecord::unpack(packed));
      field_output.records = state.output_records;
      pcout << "Resumed from the checkpoint at step " << state.step
            << ", t = " << state.time << " s." << std::endl;
      return;
    }
    claim_output_directory();
    state           = RunState();
    state.step_size = solver_parameters.time.phase_at(0).step;
    set_history_columns(leading, trailing);
  }

  template <int dim> void MechanicsSolver<dim>::claim_output_directory()
  {
    run_directory = std::make_unique<RunDirectory>(
        comm,
        solver_parameters.output.directory,
        solver_parameters.output.existing_results,
        solver_parameters.checkpoint.resume,
        std::cout);
  }

  template <int dim> void MechanicsSolver<dim>::check_contact_setup() const
  {
    const bool has_surface = !contact_parameters.slave_boundary_ids.empty();
    const bool static_solve =
        solver_parameters.time.integrator == TimeIntegrator::quasi_static;
    if (static_solve && boundary_conditions.dirichlet.empty() && !has_surface)
      throw InputError(
          "No Dirichlet boundary and no contact: nothing holds the body, so "
          "it is free to move as a rigid body and the quasi-static problem "
          "has no unique solution. Fix: fix a boundary ('Boundary "
          "conditions/Dirichlet boundary ids'), or use 'Time/Integrator = "
          "implicit dynamic' or 'explicit dynamic', where inertia decides "
          "the motion.");
    if (has_surface && bodies.empty())
      throw InputError("'Contact/Slave boundary ids' is set but there is no "
                       "rigid body. Fix: name the bodies in 'Rigid "
                       "bodies/Names' (or add them in code), or leave the "
                       "slave boundary ids empty.");
    if (!has_surface && !bodies.empty())
      throw InputError("Rigid bodies are given but no contact surface. Fix: "
                       "set 'Contact/Slave boundary ids' to the boundary ids "
                       "of the surface the bodies touch.");
  }

  template <int dim>
  void MechanicsSolver<dim>::set_history_columns(
      const std::vector<std::string> &leading,
      const std::vector<std::string> &trailing)
  {
    std::vector<std::string> columns = {"step", "time"};
    columns.insert(columns.end(), leading.begin(), leading.end());
    const char *axes[] = {"x", "y", "z"};
    for (const auto id : boundary_conditions.reaction_boundary_ids())
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("reaction_" + std::to_string(id) + "_" + axes[d]);
    for (unsigned int p = 0; p < monitor_points.size(); ++p)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("u" + std::to_string(p) + "_" + axes[d]);
    columns.insert(columns.end(), trailing.begin(), trailing.end());
    if (surface_output)
    {
      // the deepest penetration of the tissue into a geom, and where
      columns.push_back("penetration");
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("penetration_") + axes[d]);
    }
    history_writer.set_columns(columns);
    history_writer.rows.clear();
    if (surface_output)
    {
      std::vector<std::string> contact_columns = {"step", "time"};
      for (const auto &name : surface_output->history_columns())
        contact_columns.push_back(name);
      contact_writer.set_columns(contact_columns);
      contact_writer.rows.clear();
      contact_forces.clear();
    }
  }

  namespace
  {
    /// Physical memory of the machines the ranks of @p comm run on (bytes).
    double memory_of_machines(const MPI_Comm comm)
    {
      char name[MPI_MAX_PROCESSOR_NAME] = {};
      int  length                       = 0;
      MPI_Get_processor_name(name, &length);
      const auto   names = Utilities::MPI::gather(comm, std::string(name), 0);
      const double here =
          double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
      const double machines =
          std::set<std::string>(names.begin(), names.end()).size();
      return Utilities::MPI::broadcast(comm, here * machines, 0);
    }
  } // namespace

  template <int dim> void MechanicsSolver<dim>::check_run_size() const
  {
    const auto &limits = solver_parameters.limits;
    if (!limits.check_size)
      return;
    const auto &time  = solver_parameters.time;
    double      steps = 0, begin = 0;
    for (const auto &phase : time.phase_list())
    {
      steps += (phase.end - begin) / phase.step;
      begin = phase.end;
    }
    if (steps > limits.maximum_steps)
      throw InputError(
          "'Time/End time' / 'Time/Time step' (summed over 'Time/Phases') "
          "= " +
          std::to_string(std::llround(steps)) +
          " steps (or recorded states) exceed 'Run limits/Maximum steps' = " +
          std::to_string(limits.maximum_steps) +
          ". Fix: a larger 'Time/Time step' (explicit runs take their own "
          "stable step; 'Time step' is only the recording interval), or "
          "raise 'Run limits/Maximum steps'.");
    // Memory: cells after refinement x dofs per cell x bytes per dof (the
    // sparse tangent with (2k+1)^dim coupled nodes per row, a direct
    // factorisation about 4 times that; explicit runs hold vectors only).
    const unsigned int k     = solver_parameters.discretization.degree;
    const double       cells = double(triangulation.n_global_active_cells()) *
                         std::pow(2.0, dim * mesh.global_refinements);
    const double dofs = cells * std::pow(double(k), dim) * dim;
    const double row  = 12.0 * dim * std::pow(2.0 * k + 1, dim);
    const double factor =
        !needs_tangent() ? 0.05
                         : (solver_parameters.linear_solver.resolve(
                                static_cast<types::global_dof_index>(dofs)) ==
                                    LinearSolverType::direct
                                ? 5.0
                                : 2.0);
    const double bytes     = dofs * (row * factor + 400);
    const double available = memory_of_machines(comm);
    if (bytes > available)
      throw InputError(
          "The mesh after 'Mesh/Global refinements' = " +
          std::to_string(mesh.global_refinements) + " has about " +
          std::to_string(std::llround(cells)) + " cells and " +
          std::to_string(std::llround(dofs)) + " unknowns, and needs about " +
          std::to_string(std::llround(bytes / 1e9)) +
          " GB; the machines of this job have " +
          std::to_string(std::llround(available / 1e9)) +
          " GB. Fix: fewer refinements, more machines, or set 'Run "
          "limits/Check run size = false' to try anyway.");
  }

  template <int dim> void MechanicsSolver<dim>::check_mesh_references() const
  {
    // The coarse mesh, and so its boundary ids, is known on every rank.
    const auto  ids = triangulation.get_boundary_ids();
    std::string present;
    for (const auto id : ids)
      present += (present.empty() ? "" : ", ") + std::to_string(id);
    const auto check =
        [&](const types::boundary_id id, const std::string &parameter)
    {
      if (std::find(ids.begin(), ids.end(), id) == ids.end())
        throw InputError(
            "Parameter '" + parameter + "' names boundary id " +
            std::to_string(id) +
            ", which the mesh does not have (its boundary ids: " + present +
            "). Fix: use the boundary ids of the mesh (see the "
            "mesh type's documentation or the mesh file).");
    };
    for (const auto &d : boundary_conditions.dirichlet)
      check(d.boundary_id, "Boundary conditions/Dirichlet boundary ids");
    for (const auto &t : boundary_conditions.tractions)
      check(t.boundary_id, "Boundary conditions/Traction boundary ids");
    for (const auto &p : boundary_conditions.pressures)
      check(p.boundary_id, "Boundary conditions/Pressure boundary ids");
    for (const auto id : contact_parameters.slave_boundary_ids)
      check(id, "Contact/Slave boundary ids");

    const auto values = solid->point_displacements(monitor_points);
    for (std::size_t k = 0; k < values.size(); ++k)
      if (std::isnan(values[k][0]))
      {
        std::ostringstream point;
        for (unsigned int d = 0; d < dim; ++d)
          point << (d ? ", " : "") << monitor_points[k][d];
        throw InputError("Parameter 'Output/Monitor points': point " +
                         std::to_string(k + 1) + " (" + point.str() +
                         " m) is not inside the mesh. Fix: give reference "
                         "positions inside the body (m).");
      }
  }

  template <int dim>
  void MechanicsSolver<dim>::print_summary(const std::string &integrator) const
  {
    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells, "
          << solid->n_dofs() << " displacement dofs ("
          << solver_parameters.discretization.element_name() << ", "
          << integrator << "), " << Utilities::MPI::n_mpi_processes(comm)
          << " MPI rank(s) x " << MultithreadInfo::n_threads() << " thread(s)."
          << std::endl;
    if (needs_tangent())
      pcout << "Linear solver: " << solid->linear_solver_name() << std::endl;
    for (const auto id : material_library.material_ids())
      pcout << "Material " << static_cast<unsigned>(id) << ": "
            << material_library.get(id).summary() << std::endl;
  }

  template <int dim>
  void MechanicsSolver<dim>::record(const double               time,
                                    const std::vector<double> &leading,
                                    const std::vector<double> &trailing)
  {
    std::vector<double> row = {double(state.step), time};
    row.insert(row.end(), leading.begin(), leading.end());
    for (const auto &[id, force] : solid->reactions())
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(force[d]);
    for (const auto &u : solid->point_displacements(monitor_points))
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(u[d]);
    row.insert(row.end(), trailing.begin(), trailing.end());
    if (surface_output)
    {
      const auto deepest =
          contact_surface->deepest_penetration(solid->ghosted_solution());
      row.push_back(deepest.depth);
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(deepest.position[d]);
    }
    history_writer.add_row(row);
    if (surface_output)
    {
      ContactForceRecord record;
      record.step                     = state.step;
      record.time                     = time;
      record.forces                   = surface_output->geom_forces(*solid);
      std::vector<double> contact_row = {double(state.step), time};
      for (const double v : surface_output->history_values(record.forces))
        contact_row.push_back(v);
      contact_writer.add_row(contact_row);
      contact_forces.push_back(std::move(record));
    }
    TimerOutput::Scope scope(timers, "output");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      history_writer.write();
      if (surface_output)
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

  template <int dim> void MechanicsSolver<dim>::write_fields(const double time)
  {
    if (last_output_step == state.step)
      return;
    TimerOutput::Scope scope(timers, "output");
    solid->update_ghosts();
    typename FieldOutput<dim>::ExtraFields extra;
    if (surface_output)
      extra = [this](DataOut<dim> &data_out)
      { surface_output->add_fields(*solid, data_out); };
    field_output.write(
        *solid, material_library, time, state.n_outputs++, extra);
    last_output_step = state.step;
  }

  template <int dim>
  void MechanicsSolver<dim>::write_checkpoint(
      const std::vector<const TrilinosWrappers::MPI::Vector *> &extra)
  {
    TimerOutput::Scope scope(timers, "checkpoint");
    state.history_columns = history_writer.columns;
    state.history_rows    = history_writer.rows;
    state.output_records  = field_output.records;
    state.contact_columns = contact_writer.columns;
    state.contact_rows    = contact_writer.rows;
    state.contact_force_records.clear();
    for (const auto &record : contact_forces)
      state.contact_force_records.push_back(record.pack());
    solid->update_ghosts();
    checkpoint.save(triangulation, *solid, state, extra);
  }

  template <int dim>
  void MechanicsSolver<dim>::set_stop_criterion(std::function<bool()> f)
  {
    stop_criterion = std::move(f);
  }

  template <int dim> bool MechanicsSolver<dim>::stopped_by_criterion() const
  {
    return stopped;
  }

  template <int dim>
  const SolidSystem<dim> &MechanicsSolver<dim>::system() const
  {
    return *solid;
  }

  template <int dim> const HistoryWriter &MechanicsSolver<dim>::history() const
  {
    return history_writer;
  }

  template <int dim>
  const MaterialLibrary &MechanicsSolver<dim>::materials() const
  {
    return material_library;
  }

  template <int dim>
  const SolverParameters &MechanicsSolver<dim>::parameters() const
  {
    return solver_parameters;
  }

  template <int dim> RigidBodySet &MechanicsSolver<dim>::rigid_bodies()
  {
    return bodies;
  }

  template <int dim>
  const RigidBodySet &MechanicsSolver<dim>::rigid_bodies() const
  {
    return bodies;
  }

  template <int dim>
  const ContactSurface<dim> *MechanicsSolver<dim>::contact() const
  {
    return contact_surface.get();
  }

  template <int dim>
  const ContactOutput<dim> *MechanicsSolver<dim>::contact_output() const
  {
    return surface_output.get();
  }

  template <int dim>
  const HistoryWriter &MechanicsSolver<dim>::contact_history() const
  {
    return contact_writer;
  }

  template <int dim>
  const std::vector<ContactForceRecord> &
  MechanicsSolver<dim>::contact_force_history() const
  {
    return contact_forces;
  }

  template <int dim> TimerOutput &MechanicsSolver<dim>::timer()
  {
    return timers;
  }

  template class MechanicsSolver<2>;
  template class MechanicsSolver<3>;
} // namespace softgrasp
