#ifndef softgrasp_solvers_explicit_stepper_h
#define softgrasp_solvers_explicit_stepper_h

#include <optional>
#include <softgrasp/explicit/central_difference.h>
#include <softgrasp/explicit/explicit_contact.h>
#include <softgrasp/explicit/internal_force_operator.h>
#include <softgrasp/solvers/time_stepper.h>

namespace softgrasp
{
  /**
   * Explicit dynamic time stepping of a total-Lagrangian finite-strain
   * solid ('Time/Integrator = explicit dynamic'): central differences
   * (CentralDifference) with the lumped mass, matrix-free internal forces
   * (InternalForceOperator) and forward-increment Lagrange-multiplier
   * contact with Coulomb friction (ExplicitContact), on the same .prm
   * sections, SolidSystem, contact output and postprocessors as the
   * implicit steppers.
   *
   * The step is the 'Explicit dynamics/Safety factor' times the critical
   * step of the current state, recomputed every 'Stable step interval'
   * steps; 'Mass scaling time step' adds mass where elements are too
   * small or stiff (reported in percent). The state is recorded every
   * 'Time/Time step' (history with the energies, contact forces, progress
   * with ETA; VTU every 'Output/VTU interval' records; checkpoints every
   * 'Checkpoint/Interval' records, with the velocity). A step that
   * produces NaN, inverts an element or breaks the energy balance is
   * undone, the last good state is written (VTU and checkpoint), and the
   * run stops with a SolverFailure naming the cause and the fix.
   *
   * Formulations: displacement, or 'mixed u-p-J' with the implicit
   * solver's element ('Finite element/Pressure degree': Q1-P0, Q2-P1 or
   * Q2-P0; the pressure is projected element by element). Loads:
   * prescribed displacements (Dirichlet, as functions of t) and contact
   * with the rigid bodies. Tractions, pressures and gravity are
   * not offered here yet (an InputError says so).
   */
  template <int dim> class ExplicitStepper : public TimeStepper<dim>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    bool needs_tangent() const override;
    bool has_inertia() const override;
    unsigned int
         n_checkpoint_fields(const SolverParameters &parameters) const override;
    void check_inputs(const SimulationAccess<dim> &run) const override;
    std::unique_ptr<ContactSurface<dim>>
         make_contact(const SimulationAccess<dim> &run,
                      double                       shear_modulus) override;
    void run(const SimulationAccess<dim> &run) override;

  private:
    /// Operator, lumped (and scaled) mass, fixed dofs, integrator.
    void setup_integrator();
    /// The integrator's state: a fresh start (recorded) or the checkpoint.
    void start(VectorType &u, VectorType &v);
    /// Restore the integrator from the checkpoint's fields and scalars.
    void restore(VectorType &u, VectorType &v);
    /// The first time step (or the saved one), checked against the
    /// critical step and the run's size limits; prints the summary.
    void choose_time_step();
    /// Integrate up to the recorded time @p t_record.
    void advance_to(const double t_record);
    /// Record, write and report the state at @p t_record; returns true
    /// if the run ends here (stop criterion).
    bool finish_record(const double t_record);
    void scale_mass(const double target_step);
    /// The time step over the critical step 2/omega_max: the safety factor
    /// times the stable fraction with the stiffness damping.
    double step_fraction() const;
    /// Set the time step (s) and the stiffness damping beta that belongs
    /// to it.
    void set_time_step(const double dt);
    /// Dirichlet dofs with their support points and functions.
    void setup_prescribed();
    void prescribe(const double time, VectorType &u);
    /// Copy the integrator's displacement and forces into the SolidSystem.
    void              update_system();
    void              record_state(const double time);
    void              save_checkpoint();
    void              write_last_good_state(const double time);
    [[noreturn]] void fail(const std::string &cause, const std::string &fix);
    void              print_progress(const double time, const double dt) const;

    struct PrescribedDof
    {
      dealii::types::global_dof_index index;
      unsigned int                    component;
      dealii::Point<dim>              point;
      const dealii::Function<dim>    *function;
    };

    /// The run being integrated (from make_contact() or run() on).
    std::optional<SimulationAccess<dim>>        sim;
    ExplicitContact<dim>                       *explicit_contact = nullptr;
    dealii::AffineConstraints<double>           hanging;
    std::unique_ptr<InternalForceOperator<dim>> force;
    VectorType                                  mass;
    dealii::IndexSet                            fixed;
    std::vector<PrescribedDof>                  prescribed;
    std::unique_ptr<CentralDifference<dim>>     integrator;
    double                                      physical_mass     = 0;
    double                                      added_mass        = 0; ///< %
    double                                      time_step         = 0; ///< s
    double                                      critical_step     = 0; ///< s
    double                                      worst_penetration = 0; ///< m
    double J_at_estimate = 1; ///< smallest det F at the last critical step
    unsigned long steps  = 0;
  };
} // namespace softgrasp

#endif
