#ifndef softgrasp_mechanics_quasi_static_solver_h
#define softgrasp_mechanics_quasi_static_solver_h

#include <softgrasp/contact/mortar_contact.h>
#include <softgrasp/mechanics/mechanics_solver.h>
#include <softgrasp/mechanics/newton_solver.h>

namespace softgrasp
{
  /**
   * Quasi-static, total-Lagrangian finite-strain solid on a distributed
   * mesh ('Time/Integrator = quasi-static'): load/time stepping from 0 to
   * the end time, Newton-Raphson with a line search in each step, automatic
   * step cut-back on non-convergence or element inversion, mortar contact
   * by a semi-smooth Newton method, per-step history (CSV), field output
   * (VTU/PVD), progress with estimated time left, and checkpoint/restart.
   *
   * With 'Time/Integrator = implicit dynamic' each step also carries the
   * inertia of the lumped mass by backward Euler (InertiaTerm): v_{n+1} =
   * (u_{n+1} - u_n)/dt, a_{n+1} = (v_{n+1} - v_n)/dt. A slow load then
   * follows the static path, and where that path has no continuation (a
   * frictional snap) a cut-back step makes M/dt^2 dominate the released
   * stiffness, so the step converges and the snap is passed dynamically.
   * The velocity is checkpointed; the history has the kinetic energy.
   *
   * A program is: declare_parameters(), read the .prm with the passes of
   * add_passes(), construct, run(). See examples/cook_membrane.
   */
  template <int dim> class QuasiStaticSolver : public MechanicsSolver<dim>
  {
  public:
    QuasiStaticSolver(MPI_Comm comm, const SolverInputs<dim> &inputs);

    /// Solve all load steps (or continue from the checkpoint).
    void run() override;

  private:
    std::unique_ptr<ContactSurface<dim>>
         make_contact(const double shear_modulus) override;
    bool needs_tangent() const override
    {
      return true;
    }
    bool solve_step(const double time, std::string &failure_report);
    bool dynamic() const;
    /// Set the inertia term of a step of size @p dt from the state
    /// u_n = @p u_start with the velocity v_n.
    void set_inertia(const dealii::TrilinosWrappers::MPI::Vector &u_start,
                     const double                                 dt);
    /// After a converged step of size @p dt: v = (u - u_start)/dt.
    void   update_velocity(const dealii::TrilinosWrappers::MPI::Vector &u_start,
                           const double                                 dt);
    double kinetic_energy() const;
    /// Implicit dynamics: the forces of the initial state u = 0 at t = 0,
    /// for its history row (no equilibrium is solved for).
    void evaluate_initial_state();
    /// The checkpoint, with the velocity in implicit dynamics.
    void write_state();
    void record_step(const double       time,
                     const unsigned int newton_iterations,
                     const unsigned int linear_iterations,
                     const unsigned int cut_backs);

    NewtonSolver<dim>   newton;
    MortarContact<dim> *mortar                 = nullptr; ///< in the base
    unsigned int        last_newton_iterations = 0;
    unsigned int        last_linear_iterations = 0;
    double              last_residual          = 0;
    double              previous_time          = 0;
    /// Implicit dynamics: v_n (m/s, owned), the predictor u_n + dt v_n
    /// (ghosted) and the lumped mass (kg, owned).
    dealii::TrilinosWrappers::MPI::Vector velocity, predictor, mass;
    dealii::TrilinosWrappers::MPI::Vector ghosted_mass; ///< kg, ghosted
  };
} // namespace softgrasp

#endif
