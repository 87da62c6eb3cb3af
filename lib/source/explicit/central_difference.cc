#include <algorithm>
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
      const double                      mass_damping,
      const double                      stiffness_damping)
      : force(force)
      , mass(mass)
      , fixed(fixed)
      , alpha(mass_damping)
      , beta(stiffness_damping)
  {
    for (auto *vector : {&u,
                         &v_half,
                         &v,
                         &a,
                         &f,
                         &f_ext,
                         &f_contact,
                         &u_trial,
                         &v_now,
                         &eigenvector,
                         &u_prev,
                         &v_half_prev,
                         &a_prev,
                         &f_prev,
                         &f_ext_prev,
                         &f_damping,
                         &f_damping_prev})
      force.initialize_dof_vector(*vector);
    const IndexSet &owned = u.locally_owned_elements();
    is_free.resize(owned.n_elements());
    for (unsigned int k = 0; k < is_free.size(); ++k)
      is_free[k] = !fixed.is_element(owned.nth_index_in_set(k));
  }

  template <int dim>
  void CentralDifference<dim>::acceleration(const double      time,
                                            const VectorType &displacement,
                                            const VectorType &velocity,
                                            const double      rate_dt)
  {
    const auto result = force.apply(displacement, f);
    internal_energy   = result.energy;
    smallest_J        = result.min_J;
    f_ext             = 0;
    if (external_forces)
      external_forces(time, displacement, f_ext);
    // beta K v^{n+1/2} as the rate of the internal forces over the step;
    // without a step (start, restart) the damping force is kept as it is
    const bool rate = beta > 0 && rate_dt > 0;
    for (unsigned int k = 0; k < is_free.size(); ++k)
    {
      if (rate)
        f_damping.local_element(k) =
            is_free[k] ? beta * (f.local_element(k) - f_prev.local_element(k)) /
                             rate_dt
                       : 0.0;
      a.local_element(k) = is_free[k]
                               ? (f_ext.local_element(k) - f.local_element(k) -
                                  f_damping.local_element(k)) /
                                         mass.local_element(k) -
                                     alpha * velocity.local_element(k)
                               : 0.0;
    }
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

  template <int dim>
  void CentralDifference<dim>::set_stiffness_damping(const double damping)
  {
    beta = damping;
  }

  template <int dim>
  void CentralDifference<dim>::set_balance_limit(const double limit,
                                                 const double active_from)
  {
    balance_limit = limit;
    balance_from  = active_from;
  }

  template <int dim> bool CentralDifference<dim>::energy_keeps_growing()
  {
    const bool over = balance_limit > 0 && steps_taken >= 50 &&
                      t >= balance_from && e.created > balance_limit;
    steps_over_limit =
        over && e.created >= created_before ? steps_over_limit + 1 : 0;
    created_before = e.created;
    return steps_over_limit >= balance_patience;
  }

  template <int dim>
  void CentralDifference<dim>::set_constrained_dofs(
      const std::vector<types::global_dof_index> &dofs)
  {
    constrained.clear();
    const IndexSet &owned = u.locally_owned_elements();
    for (const auto i : dofs)
      if (owned.is_element(i) && !fixed.is_element(i))
        constrained.push_back(owned.index_within_set(i));
    std::sort(constrained.begin(), constrained.end());
    constrained.erase(std::unique(constrained.begin(), constrained.end()),
                      constrained.end());
    constrained_trial.resize(constrained.size());
    f_contact = 0;
  }

  template <int dim>
  void CentralDifference<dim>::apply_constraints(const double dt,
                                                 const double h)
  {
    if (!constrain)
    {
      f_contact = 0;
      return;
    }
    // A correction du of a free dof is the contact force M du / (dt h).
    const auto correct = [&](const unsigned int k, const double trial)
    {
      const double du            = u.local_element(k) - trial;
      f_contact.local_element(k) = 0;
      if (du == 0 || !is_free[k])
        return;
      v_half.local_element(k) += du / dt;
      f_contact.local_element(k) = mass.local_element(k) * du / (dt * h);
    };
    if (constrained.empty()) // every dof may change
    {
      u_trial = u;
      constrain(t + dt, dt, h, u_prev, u);
      for (unsigned int k = 0; k < is_free.size(); ++k)
        correct(k, u_trial.local_element(k));
      return;
    }
    for (unsigned int j = 0; j < constrained.size(); ++j)
      constrained_trial[j] = u.local_element(constrained[j]);
    constrain(t + dt, dt, h, u_prev, u);
    for (unsigned int j = 0; j < constrained.size(); ++j)
      correct(constrained[j], constrained_trial[j]);
  }

  template <int dim>
  void CentralDifference<dim>::predict(const double dt, const double h)
  {
    if (!started)
      v_half = v; // v^{-1/2} := v^0 for the first step's mean velocity
    const unsigned int n = u.locally_owned_size();
    double *const uu = u.begin(), *const vv = v_half.begin();
    double *const up = u_prev.begin(), *const vp = v_half_prev.begin();
    const double *const ap = a_prev.begin();
    for (unsigned int k = 0; k < n; ++k)
    {
      up[k]          = uu[k];
      vp[k]          = vv[k];
      const double v = vv[k] + h * ap[k];
      vv[k]          = v;
      uu[k] += dt * v;
    }
    // ghost entries as a vector copy (operator=) leaves them
    if (u.has_ghost_elements())
      u_prev.update_ghost_values();
    else
      u_prev.zero_out_ghost_values();
    if (v_half.has_ghost_elements())
      v_half_prev.update_ghost_values();
    else
      v_half_prev.zero_out_ghost_values();
  }

  template <int dim>
  bool CentralDifference<dim>::update_energies(const double h)
  {
    // Power of the forces at t^n times h, with the mean velocity
    // (v^{n-1/2} + v^{n+1/2})/2: the change of the half-step kinetic
    // energy, exactly.
    double external = 0, supports = 0, contact = 0, damping = 0, kinetic = 0;
    bool   finite = std::isfinite(internal_energy);
    for (unsigned int k = 0; k < is_free.size(); ++k)
    {
      const double v_new  = v_half.local_element(k);
      const double v_mean = 0.5 * (v_half_prev.local_element(k) + v_new);
      if (is_free[k])
      {
        const double m = mass.local_element(k);
        external += f_ext_prev.local_element(k) * v_mean * h;
        contact += f_contact.local_element(k) * v_mean * h;
        damping += (alpha * m * v_half_prev.local_element(k) +
                    f_damping_prev.local_element(k)) *
                   v_mean * h;
        kinetic += 0.5 * m * v_new * v_new;
      }
      else // the reaction f_int - f_ext is the supports' force on the body
        supports += (f_prev.local_element(k) - f_ext_prev.local_element(k)) *
                    v_mean * h;
      finite = finite && std::isfinite(u.local_element(k)) &&
               std::isfinite(a.local_element(k));
    }
    const MPI_Comm comm = u.get_mpi_communicator();
    if (Utilities::MPI::min(finite ? 1 : 0, comm) == 0)
      return false;
    double sums[5] = {external, supports, contact, damping, kinetic};
    Utilities::MPI::sum(sums, comm, sums);
    e.external_work += sums[0];
    e.support_work += sums[1];
    e.contact_work += sums[2];
    e.damping += sums[3];
    e.kinetic              = sums[4];
    e.internal             = 0.5 * (internal_start + internal_energy);
    const double imbalance = e.kinetic + e.internal - e0.kinetic - e0.internal -
                             e.external_work - e.support_work - e.contact_work +
                             e.damping;
    const double scale = std::max({e.kinetic,
                                   std::abs(e.internal),
                                   std::abs(e.external_work),
                                   std::abs(e.support_work),
                                   std::abs(e.contact_work),
                                   e.damping,
                                   e0.kinetic + std::abs(e0.internal),
                                   1e-300});
    e.balance_error    = std::abs(imbalance) / scale;
    e.created          = std::max(imbalance, 0.0) / scale;
    return true;
  }

  template <int dim>
  void CentralDifference<dim>::undo_step(const double internal_old,
                                         const double J_old,
                                         const double previous_time)
  {
    u.swap(u_prev);
    v_half.swap(v_half_prev);
    f.swap(f_prev);
    f_ext.swap(f_ext_prev);
    f_damping.swap(f_damping_prev);
    a.swap(a_prev);
    internal_energy = internal_old;
    smallest_J      = J_old;
    t               = previous_time;
  }

  template <int dim>
  typename CentralDifference<dim>::StepResult
  CentralDifference<dim>::step(const double dt)
  {
    // Keep the state before the step: copies of u and v^{n-1/2} (in
    // predict()); the force vectors are swapped (acceleration() overwrites
    // f, f_ext and a).
    f_prev.swap(f);
    f_ext_prev.swap(f_ext);
    f_damping_prev.swap(f_damping);
    a_prev.swap(a);
    const Energies e_old        = e;
    const double   internal_old = internal_energy, J_old = smallest_J;
    internal_start = internal_energy;
    // v^{n+1/2} and u^{n+1}; the fixed dofs move as prescribed
    const double h = started ? 0.5 * (last_dt + dt) : 0.5 * dt;
    predict(dt, h);
    if (prescribe)
    {
      prescribe(t + dt, u);
      for (const auto i : fixed)
        v_half[i] = (u[i] - u_prev[i]) / dt;
    }
    apply_constraints(dt, h);
    const double previous_time = t;
    t += dt;
    acceleration(t, u, v_half, dt);

    StepResult result = StepResult::ok;
    if (!update_energies(h))
      result = StepResult::not_finite;
    else if (!(smallest_J > 0))
      result = StepResult::inverted;
    else if (energy_keeps_growing())
      result = StepResult::unbalanced;
    if (result != StepResult::ok)
    {
      undo_step(internal_old, J_old, previous_time);
      e = e_old;
      return result;
    }
    started = true;
    last_dt = dt;
    ++steps_taken;
    return result;
  }

  template <int dim>
  std::vector<double> CentralDifference<dim>::state_scalars() const
  {
    return {t,
            last_dt,
            started ? 1.0 : 0.0,
            e.kinetic,
            e.internal,
            e.external_work,
            e.support_work,
            e.contact_work,
            e.damping,
            e0.kinetic,
            e0.internal};
  }

  template <int dim>
  void CentralDifference<dim>::restore(const VectorType          &u0,
                                       const VectorType          &v_half0,
                                       const std::vector<double> &s,
                                       const VectorType          *damping_force)
  {
    AssertThrow(s.size() == 11,
                ExcMessage("The explicit integrator's saved state has " +
                           std::to_string(s.size()) +
                           " entries instead of 11: the checkpoint was not "
                           "written by this version."));
    t       = s[0];
    last_dt = s[1];
    started = s[2] > 0;
    u       = u0;
    v_half  = v_half0;
    if (damping_force)
      f_damping = *damping_force;
    acceleration(t, u, v_half);
    e.kinetic       = s[3];
    e.internal      = s[4];
    e.external_work = s[5];
    e.support_work  = s[6];
    e.contact_work  = s[7];
    e.damping       = s[8];
    e0.kinetic      = s[9];
    e0.internal     = s[10];
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::damping_force() const
  {
    return f_damping;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::velocity_half_step() const
  {
    return v_half;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::highest_mode() const
  {
    return eigenvector;
  }

  template <int dim>
  void CentralDifference<dim>::set_highest_mode(const VectorType &mode)
  {
    eigenvector = mode;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::internal_forces() const
  {
    return f;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::external_forces_now() const
  {
    return f_ext;
  }

  template <int dim>
  const typename CentralDifference<dim>::VectorType &
  CentralDifference<dim>::contact_forces() const
  {
    return f_contact;
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
    // Computed on demand (not on every step): v^n = v^{n-1/2} + dt/2 a^n.
    if (!started)
      return v;
    v_now = v_half;
    v_now.add(0.5 * last_dt, a);
    return v_now;
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
