#include <cmath>
#include <softgrasp/explicit/central_difference.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  CentralDifference<dim>::CentralDifference(
      const InternalForceOperator<dim> &force,
      const VectorType                 &mass,
      const IndexSet                   &fixed,
      const double                      mass_damping)
      : force(force)
      , mass(mass)
      , fixed(fixed)
      , alpha(mass_damping)
  {
    for (auto *vector : {&u,
                         &v_half,
                         &v,
                         &a,
                         &f,
                         &f_ext,
                         &eigenvector,
                         &u_prev,
                         &v_half_prev,
                         &a_prev,
                         &f_prev,
                         &f_ext_prev})
      force.initialize_dof_vector(*vector);
    const IndexSet &owned = u.locally_owned_elements();
    is_free.resize(owned.n_elements());
    for (unsigned int k = 0; k < is_free.size(); ++k)
      is_free[k] = !fixed.is_element(owned.nth_index_in_set(k));
  }

  template <int dim>
  void CentralDifference<dim>::acceleration(const double      time,
                                            const VectorType &displacement,
                                            const VectorType &velocity)
  {
    const auto result = force.apply(displacement, f);
    internal_energy   = result.energy;
    smallest_J        = result.min_J;
    f_ext             = 0;
    if (external_forces)
      external_forces(time, displacement, f_ext);
    for (unsigned int k = 0; k < is_free.size(); ++k)
      a.local_element(k) = is_free[k]
                               ? (f_ext.local_element(k) - f.local_element(k)) /
                                         mass.local_element(k) -
                                     alpha * velocity.local_element(k)
                               : 0.0;
  }

  /// 1/2 v.M.v over all ranks.
  template <int dim>
  double
  CentralDifference<dim>::kinetic_energy(const VectorType &velocity) const
  {
    double kinetic = 0;
    for (unsigned int k = 0; k < is_free.size(); ++k)
      kinetic += 0.5 * mass.local_element(k) * velocity.local_element(k) *
                 velocity.local_element(k);
    return Utilities::MPI::sum(kinetic, velocity.get_mpi_communicator());
  }

  template <int dim>
  void CentralDifference<dim>::initialize(const double      t0,
                                          const VectorType &u0,
                                          const VectorType &v0)
  {
    t = t0;
    u = u0;
    v = v0;
    if (prescribe)
      prescribe(t, u);
    acceleration(t, u, v);
    started    = false;
    e          = Energies();
    e.kinetic  = kinetic_energy(v);
    e.internal = internal_energy;
    e0         = e;
  }

  template <int dim>
  double
  CentralDifference<dim>::critical_time_step(const unsigned int iterations)
  {
    const MPI_Comm comm = u.get_mpi_communicator();
    if (eigenvector.l2_norm() == 0) // deterministic start, same on any ranks
      for (const auto i : eigenvector.locally_owned_elements())
        eigenvector[i] =
            fixed.is_element(i) ? 0.0 : std::sin(12.9898 * i + 1.0);
    VectorType perturbed(u), f0(f), y(u);
    force.apply(u, f0);
    double lambda = 0;
    for (unsigned int k = 0; k < iterations; ++k)
    {
      eigenvector /= eigenvector.linfty_norm();
      const double epsilon = 1e-7 * std::max(1e-3, u.linfty_norm() + 1e-3);
      perturbed            = u;
      perturbed.add(epsilon, eigenvector);
      force.apply(perturbed, y);
      double xMy = 0, xMx = 0;
      for (unsigned int k = 0; k < is_free.size(); ++k)
      {
        double      &yk = y.local_element(k);
        const double m  = mass.local_element(k),
                     x  = eigenvector.local_element(k);
        yk = is_free[k] ? (yk - f0.local_element(k)) / (epsilon * m) : 0.0;
        xMy += x * m * yk;
        xMx += x * m * x;
      }
      lambda = Utilities::MPI::sum(xMy, comm) / Utilities::MPI::sum(xMx, comm);
      eigenvector = y;
    }
    return 2.0 / std::sqrt(std::max(lambda, 1e-300));
  }

  template <int dim> bool CentralDifference<dim>::step(const double dt)
  {
    const MPI_Comm comm = u.get_mpi_communicator();
    // Keep the state before the step: copies of u and v^{n-1/2}; the force
    // vectors are swapped (acceleration() overwrites f, f_ext and a).
    u_prev      = u;
    v_half_prev = v_half;
    f_prev.swap(f);
    f_ext_prev.swap(f_ext);
    a_prev.swap(a);
    const double internal_old = internal_energy, J_old = smallest_J;
    // v^{n+1/2}
    const double average = started ? 0.5 * (last_dt + dt) : 0.5 * dt;
    if (!started)
      v_half = v;
    v_half.add(average, a_prev);
    // u^{n+1}; the fixed dofs move as prescribed
    u.add(dt, v_half);
    if (prescribe)
    {
      prescribe(t + dt, u);
      for (const auto i : fixed)
        v_half[i] = (u[i] - u_prev[i]) / dt;
    }
    const double previous_time = t;
    t += dt;
    acceleration(t, u, v_half);
    // work over the step (trapezoidal), damping dissipation, finiteness
    double external = 0, boundary = 0, damping = 0;
    bool   finite = std::isfinite(internal_energy) && smallest_J > 0;
    for (unsigned int k = 0; k < is_free.size(); ++k)
    {
      const double du = u.local_element(k) - u_prev.local_element(k);
      if (is_free[k])
      {
        external +=
            0.5 * (f_ext_prev.local_element(k) + f_ext.local_element(k)) * du;
        damping += alpha * mass.local_element(k) * v_half.local_element(k) *
                   v_half.local_element(k) * dt;
      }
      else // the reactions f_int - f_ext do work on the body
        boundary += 0.5 *
                    (f_prev.local_element(k) - f_ext_prev.local_element(k) +
                     f.local_element(k) - f_ext.local_element(k)) *
                    du;
      finite = finite && std::isfinite(u.local_element(k)) &&
               std::isfinite(a.local_element(k));
    }
    if (Utilities::MPI::min(finite ? 1 : 0, comm) == 0)
    {
      u.swap(u_prev);
      v_half.swap(v_half_prev);
      f.swap(f_prev);
      f_ext.swap(f_ext_prev);
      a.swap(a_prev);
      internal_energy = internal_old;
      smallest_J      = J_old;
      t               = previous_time;
      return false;
    }
    // v^{n+1} for the kinetic energy
    v = v_half;
    v.add(0.5 * dt, a);
    e.kinetic  = kinetic_energy(v);
    e.internal = internal_energy;
    e.external_work += Utilities::MPI::sum(external, comm);
    e.boundary_work += Utilities::MPI::sum(boundary, comm);
    e.damping += Utilities::MPI::sum(damping, comm);
    const double imbalance = e.kinetic + e.internal - e.external_work +
                             e.boundary_work + e.damping - e0.kinetic -
                             e0.internal;
    const double scale = std::max({e.kinetic,
                                   std::abs(e.internal),
                                   std::abs(e.external_work),
                                   std::abs(e.boundary_work),
                                   e.damping,
                                   e0.kinetic + std::abs(e0.internal),
                                   1e-300});
    e.balance_error    = std::abs(imbalance) / scale;
    started            = true;
    last_dt            = dt;
    return true;
  }

  template <int dim> double CentralDifference<dim>::time() const
  {
    return t;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::displacement() const
  {
    return u;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::velocity() const
  {
    return v;
  }

  template <int dim>
  typename CentralDifference<dim>::Energies
  CentralDifference<dim>::energies() const
  {
    return e;
  }

  template <int dim> double CentralDifference<dim>::min_J() const
  {
    return smallest_J;
  }

  template class CentralDifference<2>;
  template class CentralDifference<3>;
} // namespace softgrasp
