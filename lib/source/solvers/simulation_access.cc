#include <softgrasp/solvers/simulation.h>

namespace softgrasp
{
  template <int dim>
  SimulationAccess<dim>::SimulationAccess(Simulation<dim> &simulation)
      : simulation(&simulation)
  {
  }

  template <int dim> MPI_Comm SimulationAccess<dim>::communicator() const
  {
    return simulation->comm;
  }

  template <int dim>
  const SolverParameters &SimulationAccess<dim>::parameters() const
  {
    return simulation->solver_parameters;
  }

  template <int dim>
  const ContactParameters &SimulationAccess<dim>::contact_parameters() const
  {
    return simulation->contact_parameters;
  }

  template <int dim>
  const MaterialLibrary &SimulationAccess<dim>::materials() const
  {
    return simulation->material_library;
  }

  template <int dim>
  const RigidBodySet &SimulationAccess<dim>::rigid_bodies() const
  {
    return simulation->bodies;
  }

  template <int dim>
  BoundaryConditions<dim> &SimulationAccess<dim>::boundary_conditions() const
  {
    return simulation->boundary_conditions;
  }

  template <int dim> SolidSystem<dim> &SimulationAccess<dim>::solid() const
  {
    return *simulation->solid;
  }

  template <int dim>
  const dealii::parallel::distributed::Triangulation<dim> &
  SimulationAccess<dim>::triangulation() const
  {
    return simulation->triangulation;
  }

  template <int dim> dealii::TimerOutput &SimulationAccess<dim>::timers() const
  {
    return simulation->timers;
  }

  template <int dim>
  dealii::ConditionalOStream &SimulationAccess<dim>::out() const
  {
    return simulation->pcout;
  }

  template <int dim>
  dealii::ConditionalOStream &SimulationAccess<dim>::verbose_out() const
  {
    return simulation->verbose_out;
  }

  template <int dim> RunState &SimulationAccess<dim>::state() const
  {
    return simulation->state;
  }

  template <int dim> ProgressReporter &SimulationAccess<dim>::progress() const
  {
    return simulation->recorder.progress();
  }

  template <int dim> bool SimulationAccess<dim>::resumed() const
  {
    return simulation->solver_parameters.checkpoint.resume;
  }

  template <int dim>
  const std::vector<typename SimulationAccess<dim>::Vector> &
  SimulationAccess<dim>::restored_fields() const
  {
    return simulation->restored_fields;
  }

  template <int dim> bool SimulationAccess<dim>::has_contact() const
  {
    return !simulation->contact_parameters.slave_boundary_ids.empty();
  }

  template <int dim>
  void SimulationAccess<dim>::record(const double         time,
                                     const HistoryValues &leading,
                                     const HistoryValues &trailing) const
  {
    simulation->record(time, leading, trailing);
  }

  template <int dim>
  void SimulationAccess<dim>::write_fields(const double time) const
  {
    simulation->write_fields(time);
  }

  template <int dim>
  void SimulationAccess<dim>::write_checkpoint(
      const std::vector<const Vector *> &extra) const
  {
    auto                      &s = *simulation;
    dealii::TimerOutput::Scope scope(s.timers, "checkpoint");
    s.solid->update_ghosts();
    s.recorder.write_checkpoint(s.triangulation, *s.solid, s.state, extra);
  }

  template <int dim> bool SimulationAccess<dim>::stop_requested() const
  {
    simulation->stopped =
        simulation->stop_criterion && simulation->stop_criterion();
    return simulation->stopped;
  }

  template <int dim>
  void SimulationAccess<dim>::print_summary(const std::string &integrator) const
  {
    simulation->print_summary(integrator);
  }

  template class SimulationAccess<2>;
  template class SimulationAccess<3>;
} // namespace softgrasp
