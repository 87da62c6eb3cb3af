#include <deal.II/lac/vector.h>
#include <softgrasp/explicit/explicit_contact.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  ExplicitContact<dim>::ExplicitContact(const ContactParameters &parameters,
                                        const RigidBodySet      &bodies,
                                        TimerOutput             &timer,
                                        const double             shear_modulus)
      : ContactSurface<dim>(parameters, bodies)
      , shear_modulus(shear_modulus)
      , timer(timer)
  {
  }

  template <int dim>
  void ExplicitContact<dim>::set_reference_step(const double step)
  {
    reference_step = step;
  }

  template <int dim>
  FullMatrix<double> ExplicitContact<dim>::dual_coefficients(
      const typename ContactSurface<dim>::SlaveFace &face)
  {
    // the face's mass matrix M_kl = sum_q w_q N_k N_l and A = D M^-1
    const unsigned int n = face.dofs.size() / dim;
    FullMatrix<double> mass(n, n);
    for (unsigned int q = 0; q < face.weight.size(); ++q)
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = 0; l < n; ++l)
          mass(k, l) += face.weight[q] * face.shape[q][k] * face.shape[q][l];
    Vector<double> row_sums(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        row_sums[k] += mass(k, l);
    mass.gauss_jordan();
    FullMatrix<double> dual(n, n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        dual(k, l) = row_sums[k] * mass(k, l);
    return dual;
  }

  template <int dim>
  void ExplicitContact<dim>::setup(const SolidSystem<dim> &system)
  {
    ContactSurface<dim>::setup(system);
    const auto &constraints = system.constraint_set();
    for (auto &node : node_list)
      for (unsigned int c = 0; c < dim; ++c)
        node.free[c] = !constraints.is_constrained(node.dofs[c]);
    tolerance = 1e-12 * system.length_scale();
    poses_now.clear();
    faces.clear();
    sweeps = 0;
    if (!parameters.integrate_on_faces)
      return;
    gap_cap = system.length_scale();
    for (auto &face : this->slave_faces(system))
    {
      ContactFace contact_face;
      if (parameters.explicit_dual_mortar)
        contact_face.dual = dual_coefficients(face);
      contact_face.gap.assign(face.weight.size(), 0.0);
      contact_face.normal.assign(face.weight.size(), Eigen::Vector3d::Zero());
      contact_face.face = std::move(face);
      faces.push_back(std::move(contact_face));
    }
    // the vectors take the integrator's layout at the first enforce()
    weighted_gap.reinit(0);
    if (!parameters.explicit_dual_mortar)
      setup_face_potential(system);
  }

  template <int dim>
  typename ExplicitContact<dim>::Proximity
  ExplicitContact<dim>::project(const int              body,
                                const unsigned int     geom,
                                const Eigen::Vector3d &free_mask,
                                Eigen::Vector3d       &x,
                                const double           target_gap) const
  {
    Proximity q = this->distance_to(body, geom, x);
    // Newton on the signed distance along the free part of the normal;
    // exact in one step for flat surfaces, quadratic for curved ones.
    for (unsigned int it = 0;
         it < 10 && std::abs(q.gap - target_gap) > tolerance;
         ++it)
    {
      const Eigen::Vector3d direction = q.normal.cwiseProduct(free_mask);
      const double          along     = q.normal.dot(direction);
      if (along < 1e-6)
        break; // the free components cannot reach the surface
      x -= (q.gap - target_gap) / along * direction;
      q = this->distance_to(body, geom, x);
    }
    return q;
  }

  template <int dim>
  void ExplicitContact<dim>::correct(Node                  &node,
                                     const Proximity       &p,
                                     const Eigen::Vector3d &mask,
                                     const Eigen::Vector3d &x_old,
                                     const double           k,
                                     const double           allowed,
                                     Eigen::Vector3d       &x) const
  {
    const double mu = parameters.friction_coefficient;
    // Normal multiplier: back onto the surface.
    const Eigen::Vector3d x_trial = x;
    Proximity             q       = project(p.body, p.geom, mask, x, -allowed);
    const double          f_n     = k * q.normal.dot(x - x_trial);
    // Tangential multiplier: stay at the surface point of t^n, carried
    // along by the body; Coulomb's cone bounds it.
    const Pose           &now     = poses_now[p.body][p.geom];
    const Pose           &old     = poses_old[p.body][p.geom];
    const Eigen::Vector3d x_stick = now.to_world(old.to_local(x_old));
    Eigen::Vector3d       d       = x_stick - x;
    d -= q.normal * q.normal.dot(d);
    d           = d.cwiseProduct(mask);
    node.status = ContactStatus::stick;
    if (mu == 0 || !(f_n > 0))
    {
      d.setZero();
      node.status = ContactStatus::slip;
    }
    else if (k * d.norm() > mu * f_n)
    {
      d *= mu * f_n / (k * d.norm());
      node.status = ContactStatus::slip;
    }
    if (d.squaredNorm() > 0)
    {
      x += d;
      q = project(p.body, p.geom, mask, x, -allowed); // curved surfaces
    }
    node.force  = k * (x - x_trial);
    node.gap    = q.gap;
    node.normal = q.normal;
    node.slip   = x - x_stick;
    node.slip -= q.normal * q.normal.dot(node.slip);
  }

  template <int dim>
  void ExplicitContact<dim>::enforce(const double      time,
                                     const double      dt,
                                     const double      h,
                                     const VectorType &mass,
                                     const VectorType &u_old,
                                     VectorType       &u)
  {
    TimerOutput::Scope scope(timer, "contact");
    if (poses_now.empty())
      this->place_bodies(time - dt, poses_now);
    poses_old.swap(poses_now);
    this->set_time(time);
    this->place_bodies(time, poses_now);
    unsigned int active = 0, slipping = 0;
    double       worst = 0;
    // What is left of the initial overlaps: they shrink linearly to zero.
    const double left = steps_done < relaxation
                            ? 1.0 - double(steps_done + 1) / relaxation
                            : 0.0;
    ++steps_done;
    if (parameters.integrate_on_faces && parameters.explicit_dual_mortar)
    {
      enforce_on_faces(dt, h, mass, u_old, left, u);
      return;
    }
    if (parameters.integrate_on_faces)
    {
      for (auto &node : node_list)
      {
        node.last_converged = node.reference_position;
        for (unsigned int c = 0; c < dim; ++c)
          node.last_converged[c] += u_old(node.dofs[c]);
        node.slip.setZero();
      }
      enforce_face_potential(dt, h, mass, u);
      return;
    }
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      auto           &node    = node_list[j];
      const double    allowed = allowance.empty() ? 0.0 : left * allowance[j];
      Eigen::Vector3d x = node.reference_position, x_old = x;
      Eigen::Vector3d mask = Eigen::Vector3d::Zero();
      double          m    = 0;
      for (unsigned int c = 0; c < dim; ++c)
      {
        x[c] += u(node.dofs[c]);
        x_old[c] += u_old(node.dofs[c]);
        if (node.free[c])
        {
          mask[c] = 1;
          m       = mass(node.dofs[c]);
        }
      }
      node.last_converged = x_old;
      node.force.setZero();
      node.slip.setZero();
      const Proximity p = this->nearest(x);
      node.body         = p.body;
      node.geom         = p.geom;
      node.gap          = p.gap;
      node.normal       = p.body >= 0 ? p.normal : Eigen::Vector3d::Zero();
      node.status       = ContactStatus::inactive;
      if (p.body < 0 || p.gap >= -allowed || m == 0)
        continue;

      correct(node, p, mask, x_old, m / (dt * h), allowed, x);
      for (unsigned int c = 0; c < dim; ++c)
        if (node.free[c])
          u(node.dofs[c]) = x[c] - node.reference_position[c];
      worst = std::max(worst, -node.gap - allowed);
      ++active;
      if (node.status == ContactStatus::slip)
        ++slipping;
    }
    double counts[2] = {double(active), double(slipping)};
    Utilities::MPI::sum(counts, comm, counts);
    this->active_count = static_cast<unsigned int>(counts[0]);
    this->slip_count   = static_cast<unsigned int>(counts[1]);
    penetration        = Utilities::MPI::max(worst, comm);
  }

  template <int dim>
  std::pair<unsigned int, double> ExplicitContact<dim>::relax_initial_overlap(
      const double time, const VectorType &u, const unsigned int steps)
  {
    allowance  = this->node_overlaps(time, u);
    relaxation = steps;
    steps_done = 0;
    return this->overlap_summary(allowance);
  }

  template <int dim> double ExplicitContact<dim>::max_penetration() const
  {
    return penetration;
  }

  template <int dim> unsigned int ExplicitContact<dim>::last_sweeps() const
  {
    return parameters.explicit_dual_mortar ? sweeps : newton_iterations;
  }

  template class ExplicitContact<2>;
  template class ExplicitContact<3>;
} // namespace softgrasp
