#ifndef softgrasp_solvers_simulation_access_h
#define softgrasp_solvers_simulation_access_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <softgrasp/base/progress_reporter.h>
#include <softgrasp/contact/contact_parameters.h>
#include <softgrasp/io/checkpoint.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <softgrasp/solvers/run_recorder.h>
#include <vector>

namespace softgrasp
{
  template <int dim> class Simulation;

  /**
   * What a TimeStepper may use of the Simulation that runs it, in the
   * spirit of ASPECT's SimulatorAccess: the settings and the run's
   * pieces (solid, boundary conditions, run state, timers, output
   * streams), and the run's services (record a step, write fields or a
   * checkpoint, ask the stop criterion). Nothing else of the Simulation
   * is reachable, and the Simulation keeps its data private.
   */
  template <int dim> class SimulationAccess
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    explicit SimulationAccess(Simulation<dim> &simulation);

    MPI_Comm                 communicator() const;
    const SolverParameters  &parameters() const;
    const ContactParameters &contact_parameters() const;
    const MaterialLibrary   &materials() const;
    const RigidBodySet      &rigid_bodies() const;
    /// The loads (their time is set by the stepper).
    BoundaryConditions<dim> &boundary_conditions() const;
    SolidSystem<dim>        &solid() const;
    const dealii::parallel::distributed::Triangulation<dim>                      &
    triangulation() const;
    dealii::TimerOutput &timers() const;
    /// Progress and summaries (rank 0).
    dealii::ConditionalOStream &out() const;
    /// Newton details ('Output/Verbose', rank 0).
    dealii::ConditionalOStream &verbose_out() const;
    /// Step, time and step size of the run, and the stepper's scalars
    /// that its checkpoints keep.
    RunState         &state() const;
    ProgressReporter &progress() const;
    /// Whether this run continues from a checkpoint.
    bool resumed() const;
    /// The fields the checkpoint held besides the displacement (a resume).
    const std::vector<Vector> &restored_fields() const;
    /// Whether the run has a contact surface ('Contact/Slave boundary ids').
    bool has_contact() const;

    /// One history row (and contact row) of the current state at @p time:
    /// "step", "time", @p leading, the reactions and monitor points,
    /// @p trailing, the penetration. Writes the tables. Collective.
    void record(const double         time,
                const HistoryValues &leading,
                const HistoryValues &trailing) const;
    /// VTU of the current state (once per step). Collective.
    void write_fields(const double time) const;
    /// Checkpoint of the current state with @p extra fields (ghosted, on
    /// the solid's dofs) and the state's scalars. Collective.
    void write_checkpoint(const std::vector<const Vector *> &extra = {}) const;
    /// After a recorded step: whether the stop criterion ends the run.
    bool stop_requested() const;
    /// The mesh, element, solver and material lines at the start.
    void print_summary(const std::string &integrator) const;

  private:
    Simulation<dim> *simulation;
  };
} // namespace softgrasp

#endif
