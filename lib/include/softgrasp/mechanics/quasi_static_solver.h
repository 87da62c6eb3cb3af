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
  };
} // namespace softgrasp

#endif
