#ifndef softgrasp_explicit_central_difference_h
#define softgrasp_explicit_central_difference_h

#include <deal.II/base/index_set.h>
#include <functional>
#include <softgrasp/explicit/internal_force_operator.h>
#include <vector>

namespace softgrasp
{
  /**
   * Central-difference (explicit) time integration of
   *   M a = f_ext - f_int(u) - alpha M v
   * with the diagonal mass M of compute_lumped_mass():
   *   v^{n+1/2} = v^{n-1/2} + dt a^n,   u^{n+1} = u^n + dt v^{n+1/2},
   * started by v^{1/2} = v^0 + dt/2 a^0. Dofs in the fixed set move as
   * prescribed (their acceleration is not computed; the internal force
   * there is the reaction). alpha (1/s) is optional mass-proportional
   * damping.
   *
   * Energy bookkeeping per step (J; J/m in 2D): kinetic 1/2 v.M.v at
   * integer steps (v^n as the mean of the half-step velocities), internal
   * (strain) energy, work of the external forces and of the prescribed
   * motion (the reactions), and the energy dissipated by damping; the
   * balance error is |K + U - W_ext - W_fixed + D - (K0 + U0)| over the
   * largest of these terms.
   */
  template <int dim> class CentralDifference
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    struct Energies
    {
      double kinetic = 0, internal = 0, external_work = 0, boundary_work = 0,
             damping       = 0;
      double balance_error = 0; ///< relative, see the class documentation
    };

    /// @p mass from compute_lumped_mass(); @p fixed: locally owned dofs
    /// whose displacement is prescribed by prescribe() (may be empty).
    CentralDifference(const InternalForceOperator<dim> &force,
                      const VectorType                 &mass,
                      const dealii::IndexSet           &fixed,
                      const double                      mass_damping = 0);

    /// Sets the displacement of the fixed dofs at time t (default: zero).
    std::function<void(const double t, VectorType &u)> prescribe;
    /// Adds external forces (N) at time t to f (default: none).
    std::function<void(const double t, const VectorType &u, VectorType &f)>
        external_forces;

    /// Start at time @p t0 from displacement @p u0 and velocity @p v0.
    void
    initialize(const double t0, const VectorType &u0, const VectorType &v0);

    /**
     * The critical time step 2 / omega_max of the current state, omega_max^2
     * the largest eigenvalue of M^{-1} K (K the tangent stiffness), from a
     * power iteration on finite differences of f_int, warm-started from the
     * previous call's eigenvector.
     */
    double critical_time_step(const unsigned int iterations = 40);

    /// Advance by @p dt (s). Returns false if det F <= 0 somewhere or a
    /// value is not finite (the state before the step is kept).
    bool step(const double dt);

    double            time() const;
    const VectorType &displacement() const;
    /// Velocity at the current (integer) step.
    const VectorType &velocity() const;
    Energies          energies() const;
    double            min_J() const;

  private:
    void acceleration(const double t, const VectorType &u, const VectorType &v);
    /// 1/2 v.M.v over all ranks (J; J/m in 2D).
    double kinetic_energy(const VectorType &velocity) const;

    const InternalForceOperator<dim> &force;
    const VectorType                 &mass;
    dealii::IndexSet                  fixed;
    double                            alpha;
    double                            t = 0, last_dt = 0;
    VectorType                        u, v_half, v, a, f, f_ext, eigenvector;
    /// The state before the current step (kept for the rollback and the
    /// work over the step; swapped, not reallocated, each step).
    VectorType u_prev, v_half_prev, a_prev, f_prev, f_ext_prev;
    /// Per locally owned dof (local order): 1 if free, 0 if fixed.
    std::vector<unsigned char> is_free;
    bool                       started = false;
    Energies                   e, e0;
    double                     smallest_J = 1, internal_energy = 0;
  };
} // namespace softgrasp

#endif
