#ifndef softgrasp_mechanics_quasi_static_solver_h
#define softgrasp_mechanics_quasi_static_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <functional>
#include <memory>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/progress_reporter.h>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/contact/mortar_contact.h>
#include <softgrasp/io/checkpoint.h>
#include <softgrasp/io/field_output.h>
#include <softgrasp/io/history_writer.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/newton_solver.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <stdexcept>

namespace softgrasp
{
  /**
   * Thrown when a load step still fails after all cut-backs. The message
   * names the step, the time, the residual history and the cause; the last
   * converged state has been written (VTU and checkpoint) before.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Quasi-static, total-Lagrangian finite-strain solid on a distributed
   * mesh: load/time stepping from 0 to the end time, Newton-Raphson with a
   * line search in each step, automatic step cut-back on non-convergence or
   * element inversion, per-step history (CSV), field output (VTU/PVD),
   * progress with estimated time left, and checkpoint/restart.
   *
   * A program is: declare_parameters(), read the .prm with the passes of
   * add_passes(), construct, run(). See examples/cook_membrane.
   */
  template <int dim> class QuasiStaticSolver
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    static void add_passes(ParameterReader &reader);

    QuasiStaticSolver(MPI_Comm comm, dealii::ParameterHandler &prm);

    /// Solve all load steps (or continue from the checkpoint).
    void run();

    const SolidSystem<dim> &system() const;
    const HistoryWriter    &history() const;
    const MaterialLibrary  &materials() const;
    const SolverParameters &parameters() const;
    /// The rigid bodies; add bodies or reference normals before run().
    RigidBodySet &rigid_bodies();
    /// The contact, if the run has one (after run() started).
    const MortarContact<dim> *contact() const;
    const ContactOutput<dim> *contact_output() const;
    /// Per-step contact forces per geom and body (CSV).
    const HistoryWriter &contact_history() const;
    /**
     * Stop the run after the first converged step at which @p criterion
     * (called on all ranks, after the step's history is recorded) returns
     * true, e.g. a target force on a finger link; the state is written.
     */
    void set_stop_criterion(std::function<bool()> criterion);
    /// True if the last run() ended by the stop criterion.
    bool stopped_by_criterion() const;

    /// Wall-clock times per phase (setup, assembly, linear solve, output).
    dealii::TimerOutput &timer();

  private:
    void setup_contact();
    void setup_fresh();
    void setup_from_checkpoint();
    bool solve_step(const double time, std::string &failure_report);
    void record_step(const double       time,
                     const unsigned int newton_iterations,
                     const unsigned int linear_iterations,
                     const unsigned int cut_backs);
    void write_fields(const double time);
    void write_checkpoint();

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
    std::unique_ptr<MortarContact<dim>>               mortar_contact;
    std::unique_ptr<ContactOutput<dim>>               mortar_output;
    NewtonSolver<dim>                                 newton;
    FieldOutput<dim>                                  field_output;
    HistoryWriter                                     history_writer;
    HistoryWriter                                     contact_writer;
    Checkpoint<dim>                                   checkpoint;
    ProgressReporter                                  progress;
    RunState                                          state;
    std::vector<dealii::Point<dim>>                   monitor_points;
    std::function<bool()>                             stop_criterion;
    bool                                              stopped = false;
    unsigned int last_output_step       = static_cast<unsigned int>(-1);
    unsigned int last_newton_iterations = 0;
    unsigned int last_linear_iterations = 0;
    double       last_residual          = 0;
    double       previous_time          = 0;
  };
} // namespace softgrasp

#endif
