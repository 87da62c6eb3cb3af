#ifndef softgrasp_mechanics_mechanics_solver_h
#define softgrasp_mechanics_mechanics_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <functional>
#include <memory>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/progress_reporter.h>
#include <softgrasp/base/run_directory.h>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/io/checkpoint.h>
#include <softgrasp/io/field_output.h>
#include <softgrasp/io/history_writer.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/mechanics/solver_inputs.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Thrown when a run cannot go on (a load step fails after all cut-backs,
   * an explicit step blows up). The message names the step, the time and
   * the cause; the last good state has been written (VTU and checkpoint)
   * before.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * What every solver program of a finite-strain solid shares, whatever the
   * time integration: the .prm sections (mesh, materials, boundary
   * conditions, rigid bodies and contact, output, checkpoints), the
   * distributed mesh and the SolidSystem (dofs, constraints, reactions,
   * fields), the contact output per geom and body, the history tables
   * (CSV, HDF5), VTU output, checkpoints and progress. Derived classes
   * implement run(): QuasiStaticSolver (implicit, Newton per load step)
   * and ExplicitSolver (central difference). create() picks one by
   * 'Time/Integrator', so that the same .prm switches a program between
   * them.
   */
  template <int dim> class MechanicsSolver
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    static void add_passes(ParameterReader &reader);

    /// The solver that 'Time/Integrator' names, for the .prm's inputs.
    static std::unique_ptr<MechanicsSolver<dim>>
    create(MPI_Comm comm, dealii::ParameterHandler &prm);

    /// The solver that inputs.solver.time.integrator names, for typed
    /// inputs (parsed once, then set by a study).
    static std::unique_ptr<MechanicsSolver<dim>>
    create(MPI_Comm comm, const SolverInputs<dim> &inputs);

    MechanicsSolver(MPI_Comm comm, const SolverInputs<dim> &inputs);
    virtual ~MechanicsSolver() = default;

    /// Run from 0 to the end time (or continue from the checkpoint).
    virtual void run() = 0;

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

  protected:
    /// Create the output directory, the SolidSystem and the mesh (fresh or
    /// from the checkpoint, as 'Checkpoint/Resume' says), the contact (by
    /// make_contact()) and the history columns: "step", "time",
    /// @p leading, the reactions and monitor points, then @p trailing.
    void prepare_run(const std::vector<std::string> &leading,
                     const std::vector<std::string> &trailing);
    /// Whether the SolidSystem needs its tangent matrix (Newton) or only
    /// residuals.
    virtual bool needs_tangent() const = 0;
    /// The contact enforcement of the derived solver.
    virtual std::unique_ptr<ContactSurface<dim>>
    make_contact(const double shear_modulus) = 0;
    /// One history row (and one contact row) at the current state; writes
    /// the tables. Collective.
    void record(const double               time,
                const std::vector<double> &leading,
                const std::vector<double> &trailing);
    /// VTU of the current state (once per step). Collective.
    void write_fields(const double time);
    /// Checkpoint of the current state; @p extra fields (ghosted, on the
    /// system's dofs) and the RunState's scalars go with it. Collective.
    void write_checkpoint(
        const std::vector<const dealii::TrilinosWrappers::MPI::Vector *>
            &extra = {});
    /// The mesh, element and material lines at the start of a run;
    /// @p integrator names the time integration.
    void print_summary(const std::string &integrator) const;
    /// Lock the output directory (and clear an earlier run's results).
    void claim_output_directory();
    /// Refuse a body held by nothing, and contact without bodies or
    /// bodies without contact.
    void check_contact_setup() const;
    /// The history tables' columns of a new run.
    void set_history_columns(const std::vector<std::string> &leading,
                             const std::vector<std::string> &trailing);
    /// Refuse runs that need more memory or steps than allowed.
    void check_run_size() const;
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
    dealii::TimerOutput                               timers;
    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<SolidSystem<dim>>                 solid;
    std::unique_ptr<ContactSurface<dim>>              contact_surface;
    std::unique_ptr<ContactOutput<dim>>               surface_output;
    FieldOutput<dim>                                  field_output;
    HistoryWriter                                     history_writer;
    HistoryWriter                                     contact_writer;
    std::vector<ContactForceRecord>                   contact_forces;
    Checkpoint<dim>                                   checkpoint;
    std::unique_ptr<RunDirectory>                     run_directory;
    ProgressReporter                                  progress;
    RunState                                          state;
    std::vector<dealii::Point<dim>>                   monitor_points;
    /// Fields restored from the checkpoint besides the displacement.
    std::vector<dealii::TrilinosWrappers::MPI::Vector> restored_fields;
    unsigned int                                       n_restored_fields = 0;
    std::function<bool()>                              stop_criterion;
    bool                                               stopped = false;

  private:
    unsigned int last_output_step = static_cast<unsigned int>(-1);
  };
} // namespace softgrasp

#endif
