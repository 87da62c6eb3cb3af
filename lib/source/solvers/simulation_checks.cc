#include <algorithm>
#include <cmath>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>
#include <unistd.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim> void Simulation<dim>::check_contact_setup() const
  {
    const bool has_surface  = !contact_parameters.slave_boundary_ids.empty();
    const bool static_solve = !stepper->has_inertia();
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

  template <int dim>
  void Simulation<dim>::check_run_size(const double n_coarse_cells) const
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
    const unsigned int k = solver_parameters.discretization.degree;
    const double       cells =
        n_coarse_cells * std::pow(2.0, dim * mesh.global_refinements);
    const double dofs = cells * std::pow(double(k), dim) * dim;
    const double row  = 12.0 * dim * std::pow(2.0 * k + 1, dim);
    const double factor =
        !stepper->needs_tangent()
            ? 0.05
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

  template <int dim> void Simulation<dim>::check_mesh_references() const
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

  template void Simulation<2>::check_contact_setup() const;
  template void Simulation<3>::check_contact_setup() const;
  template void Simulation<2>::check_run_size(const double) const;
  template void Simulation<3>::check_run_size(const double) const;
  template void Simulation<2>::check_mesh_references() const;
  template void Simulation<3>::check_mesh_references() const;
} // namespace softgrasp
