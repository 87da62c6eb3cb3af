#ifndef softgrasp_solvers_simulation_h
#define softgrasp_solvers_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <functional>
#include <memory>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/solvers/run_recorder.h>
#include <softgrasp/solvers/simulation_access.h>
#include <softgrasp/solvers/solver_inputs.h>
#include <softgrasp/solvers/time_stepper.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * One run of a finite-strain solid, whatever its time integration: it
   * owns the inputs (settings, mesh, materials, boundary conditions,
   * contact settings, rigid bodies), the distributed mesh, the
   * SolidSystem, the contact and the RunRecorder, prepares a run (fresh,
   * or from a checkpoint) and hands it to the TimeStepper that
   * 'Time/Integrator' names (TimeStepperRegistry). Its results are read
   * through the const accessors after run(). The same .prm switches a
   * program between the integrators.
   *
   * A program is: declare_parameters(), read the .prm with the passes of
   * add_passes(), create(), run(). See examples/cook_membrane.
   */
  template <int dim> class Simulation
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    static void add_passes(ParameterReader &reader);

    /// The simulation of the .prm's inputs.
    static std::unique_ptr<Simulation<dim>>
    create(MPI_Comm comm, dealii::ParameterHandler &prm);
    /// The simulation of typed inputs (parsed once, then set by a study).
    static std::unique_ptr<Simulation<dim>>
    create(MPI_Comm comm, const SolverInputs<dim> &inputs);

    /// Throws an InputError naming the valid integrators for an unknown
    /// inputs.solver.time.integrator.
    Simulation(MPI_Comm comm, const SolverInputs<dim> &inputs);

    /// Run from 0 to the end time (or continue from the checkpoint).
    void run();

    const SolidSystem<dim> &system() const;
    const HistoryWriter    &history() const;
    const MaterialLibrary  &materials() const;
    const SolverParameters &parameters() const;
    /// The rigid bodies; add bodies or reference normals before run().
    RigidBodySet       &rigid_bodies();
    const RigidBodySet &rigid_bodies() const;
    /// The contact, if the run has one (after run() started).
    const ContactSurface<dim> *contact() const;
    const ContactOutput<dim>  *contact_output() const;
    /// Per-step contact forces per geom and body (CSV).
    const HistoryWriter &contact_history() const;
    /// The same as typed records, one per recorded step (all ranks).
    const std::vector<ContactForceRecord> &contact_force_history() const;
    /**
     * Stop the run after the first recorded step at which @p criterion
     * (called on all ranks, after the step's history is recorded) returns
     * true, e.g. a target force on a finger link; the state is written
     * (VTU and checkpoint, so that the run can be resumed from there).
     */
    void set_stop_criterion(std::function<bool()> criterion);
    /// True if the last run() ended by the stop criterion.
    bool stopped_by_criterion() const;

    /// Wall-clock times per phase.
    dealii::TimerOutput &timer();

  private:
    friend class SimulationAccess<dim>;

    /// Mesh, solid, contact and state of a fresh run or of the checkpoint.
    void prepare_run();
    /// The contact surface and its output, if the run has one.
    void make_contact();
    /// The stepper's row with the common columns around it. Collective.
    void record(const double         time,
                const HistoryValues &leading,
                const HistoryValues &trailing);
    void write_fields(const double time);
    /// Log the geoms whose lateral force fell by more than 3 % since the
    /// last record (stick-slip events); the largest relative drop (0: none)
    /// for the contact history's column 'stick_slip_drop'.
    double report_force_drops(const ContactForceRecord &record);
    /// Warn when a cell first folds (J <= 0 at a vertex, see
    /// CornerJacobian) and count the records that have one; the smallest
    /// vertex J for the history's column 'min_corner_J'. Collective.
    double report_folding(const double time);
    void   print_summary(const std::string &integrator) const;
    /// Refuse a body held by nothing, and contact without bodies or
    /// bodies without contact.
    void check_contact_setup() const;
    /// Refuse runs that need more memory or steps than allowed, for a
    /// coarse mesh of @p n_coarse_cells cells before refinement.
    void check_run_size(const double n_coarse_cells) const;
    /// Boundary ids and monitor points that the mesh must have.
    void check_mesh_references() const;

    MPI_Comm                                          comm;
    dealii::ConditionalOStream                        pcout;
    dealii::ConditionalOStream                        verbose_out;
    SolverParameters                                  solver_parameters;
    MeshFactory<dim>                                  mesh;
    MaterialLibrary                                   material_library;
    BoundaryConditions<dim>                           boundary_conditions;
    ContactParameters                                 contact_parameters;
    RigidBodySet                                      bodies;
    std::vector<dealii::Point<dim>>                   monitor_points;
    std::unique_ptr<TimeStepper<dim>>                 stepper;
    dealii::TimerOutput                               timers;
    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<SolidSystem<dim>>                 solid;
    std::unique_ptr<ContactSurface<dim>>              contact_surface;
    std::unique_ptr<ContactOutput<dim>>               surface_output;
    RunRecorder<dim>                                  recorder;
    RunState                                          state;
    /// Fields restored from the checkpoint besides the displacement.
    std::vector<dealii::TrilinosWrappers::MPI::Vector> restored_fields;
    std::function<bool()>                              stop_criterion;
    bool                                               stopped = false;
    /// Recorded steps with a folded cell in this run (report_folding()).
    struct Folding
    {
      unsigned int records    = 0;
      double       first_time = 0;
      bool         now        = false;
    } folding;
  };

  /// The earlier name of Simulation, kept for one release.
  template <int dim> using MechanicsSolver = Simulation<dim>;

  /**
   * After a run: print the ContactForceReport of @p simulation on rank 0
   * and write @p base.dat and @p base.png into its output directory. Does
   * nothing for a run without rigid bodies.
   */
  template <int dim>
  void report_contact_forces(const Simulation<dim> &simulation,
                             const std::string     &base,
                             std::ostream          &out);
} // namespace softgrasp

#endif
