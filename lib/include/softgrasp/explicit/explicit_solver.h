#ifndef softgrasp_explicit_explicit_solver_h
#define softgrasp_explicit_explicit_solver_h

#include <softgrasp/explicit/central_difference.h>
#include <softgrasp/explicit/explicit_contact.h>
#include <softgrasp/explicit/internal_force_operator.h>
#include <softgrasp/mechanics/mechanics_solver.h>

namespace softgrasp
{
  /**
   * Explicit dynamic, total-Lagrangian finite-strain solid
   * ('Time/Integrator = explicit dynamic'): central differences
   * (CentralDifference) with the lumped mass, matrix-free internal forces
   * (InternalForceOperator) and forward-increment Lagrange-multiplier
   * contact with Coulomb friction (ExplicitContact), on the same .prm
   * sections, SolidSystem, contact output and postprocessors as the
   * quasi-static solver.
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
   * Formulations: displacement, or 'mixed u-p-J' with the quasi-static
   * solver's element ('Finite element/Pressure degree': Q1-P0, Q2-P1 or
   * Q2-P0; the pressure is projected element by element). Loads:
   * prescribed displacements (Dirichlet, as functions of t) and contact
   * with the rigid bodies. Tractions, pressures and gravity are
   * not offered here yet (an InputError says so).
   */
  template <int dim> class ExplicitSolver : public MechanicsSolver<dim>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    ExplicitSolver(MPI_Comm comm, const SolverInputs<dim> &inputs);

    void run() override;

    /// Added mass of the mass scaling, percent of the physical mass.
    double added_mass_percent() const;
    /// Integration steps taken so far.
    unsigned long n_time_steps() const;

  private:
    std::unique_ptr<ContactSurface<dim>>
         make_contact(const double shear_modulus) override;
    bool needs_tangent() const override
    {
      return false;
    }
    void check_loads() const;
    /// Operator, lumped (and scaled) mass, fixed dofs, integrator.
    void setup_integrator();
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
