#include <Eigen/Eigenvalues>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector_operation.h>
#include <iomanip>
#include <softgrasp/contact/potential_contact.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  PotentialContact<dim>::PotentialContact(const ContactParameters &parameters,
                                          const RigidBodySet      &bodies,
                                          const double shear_modulus,
                                          TimerOutput &timer)
      : ImplicitContact<dim>(parameters, bodies)
      , shear_modulus(shear_modulus)
      , timer(timer)
  {
  }

  template <int dim>
  void PotentialContact<dim>::setup(const SolidSystem<dim> &system)
  {
    ContactSurface<dim>::setup(system);
    fd_step     = 1e-7 * system.length_scale();
    slip_length = parameters.slip_tolerance;
    if (parameters.integrate_on_faces)
      make_face_points(system);
    else
      make_node_points();
    set_penalties();
  }

  template <int dim>
  void PotentialContact<dim>::accept_step(const SolidSystem<dim> &system,
                                          const double            time)
  {
    const auto &u = system.ghosted_solution();
    for (Node &node : node_list)
    {
      node.last_converged = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
        node.last_converged[c] += u[node.dofs[c]];
    }
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      points[i].last_converged = position(i, u);
      points[i].accepted       = points[i].lag;
    }
    if (parameters.integrate_on_faces)
      accepted_multiplier = owned_multiplier;
    place_bodies(time, poses_converged);
    step_changes = 0;
  }

  template <int dim> void PotentialContact<dim>::begin_step(const double step)
  {
    slip_length = parameters.slip_length(step, step);
    for (auto &point : points)
      point.lag = point.accepted;
    if (parameters.integrate_on_faces)
      owned_multiplier = accepted_multiplier;
  }

  template <int dim>
  NodalPotentialInput PotentialContact<dim>::potential_input(
      const unsigned int i, const Eigen::Vector3d &x, const Proximity &p) const
  {
    const Point        &d = points[i];
    NodalPotentialInput in;
    in.gap                 = p.body >= 0 ? p.gap : 1e300;
    in.n                   = p.body >= 0 ? p.normal : Eigen::Vector3d::UnitZ();
    in.multiplier          = d.lag.multiplier;
    in.penalty             = d.penalty;
    in.mu                  = parameters.friction_coefficient;
    in.lagged_normal_force = d.lag.normal_force;
    in.slip_tolerance      = slip_length;
    // the nodes' polish: friction against the point's own current force;
    // the faces' (polish_on_faces()): against the projected pressure
    in.current_normal_force = polishing && !parameters.integrate_on_faces;
    if (p.body >= 0 && in.multiplier - in.penalty * in.gap > 0)
      in.H = this->normal_gradient(p, x, fd_step);
    if (d.lag.body >= 0 && d.lag.normal_force > 0)
    {
      in.T = tangent_basis(d.lag.normal, dim);
      // the point's motion relative to the rigid material point it sat at
      // when the last step converged
      const Pose &now = poses_now[d.lag.body][d.lag.geom];
      const Pose &old = poses_converged[d.lag.body][d.lag.geom];
      in.w            = x - now.to_world(old.to_local(d.last_converged));
      if (dim == 2)
        in.w[2] = 0;
    }
    return in;
  }

  template <int dim>
  typename PotentialContact<dim>::Proximity
  PotentialContact<dim>::find_proximity(const unsigned int     i,
                                        const Eigen::Vector3d &x)
  {
    // The nearest geom; but a point that pressed another geom in the lag
    // stays with it while the nearest one does not penetrate it by more
    // than the settle tolerance of the spacing: a node between two links
    // would otherwise change geom (and normal, by tens of degrees) between
    // outer iterations and never settle
    const Proximity nearest_one = nearest(x);
    Point          &d           = points[i];
    d.nearest_gap  = nearest_one.body >= 0 ? nearest_one.gap : 1e300;
    const Lag &lag = d.lag;
    if (lag.body < 0 || !(lag.normal_force > 0) || nearest_one.body < 0 ||
        (nearest_one.body == lag.body && nearest_one.geom == lag.geom) ||
        nearest_one.gap < -parameters.settle_tolerance * d.spacing)
      return nearest_one;
    return this->distance_to(lag.body, lag.geom, x);
  }

  template <int dim>
  void PotentialContact<dim>::evaluate(const SolidSystem<dim> &system)
  {
    TimerOutput::Scope scope(timer, "contact");
    place_bodies(current_time, poses_now);
    const auto  &u       = system.ghosted_solution();
    double       energy  = 0;
    unsigned int changes = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      Point                &point = points[i];
      const Eigen::Vector3d x     = position(i, u);
      point.proximity             = find_proximity(i, x);
      const ContactStatus before  = point.potential.status;
      point.potential =
          evaluate_nodal_potential(potential_input(i, x, point.proximity));
      energy += point.potential.energy;
      changes += point.potential.status != before;
    }
    if (polishing && parameters.integrate_on_faces)
      energy = polish_on_faces(u);
    update_nodes(system);
    unsigned int active = 0, slipping = 0;
    for (const Node &node : node_list)
    {
      active += node.status != ContactStatus::inactive;
      slipping += node.status == ContactStatus::slip;
    }
    total_energy = Utilities::MPI::sum(energy, comm);
    active_count = Utilities::MPI::sum(active, comm);
    slip_count   = Utilities::MPI::sum(slipping, comm);
    change_count = Utilities::MPI::sum(changes, comm);
    step_changes += change_count;
  }

  template <int dim>
  bool PotentialContact<dim>::settle(const SolidSystem<dim> &system,
                                     std::string            &report)
  {
    (void)system;
    // the converged state's normal forces and normals against the lagged
    // ones the solve held fixed
    double       largest = 0, change = 0, turn = 0, penetration = 0;
    double       beyond = 0; // the largest |f_t| - mu lambda (N)
    const double mu     = parameters.friction_coefficient;
    for (const Point &d : points)
    {
      const double f_n = d.potential.normal_force;
      largest          = std::max(largest, f_n);
      beyond = std::max(beyond, d.potential.friction.norm() - mu * f_n);
      change = std::max(change, std::abs(f_n - d.lag.normal_force));
      if (f_n > 0 && d.lag.normal_force > 0)
        turn = std::max(turn, (d.proximity.normal - d.lag.normal).norm());
      if (d.proximity.body >= 0)
        penetration = std::max(penetration, -d.proximity.gap / d.spacing);
      penetration = std::max(penetration, -d.nearest_gap / d.spacing);
    }
    largest     = Utilities::MPI::max(largest, comm);
    change      = Utilities::MPI::max(change, comm);
    turn        = Utilities::MPI::max(turn, comm);
    penetration = Utilities::MPI::max(penetration, comm);
    beyond      = Utilities::MPI::max(beyond, comm);
    excess      = mu * largest > 0 ? std::max(0.0, beyond) / (mu * largest) : 0;
    if (parameters.integrate_on_faces)
    {
      // the face points outnumber the nodes: the part of their force
      // changes no node feels does not move the solution, and the gap is
      // closed in the weighted mean int N_k g dA, not at every point
      const auto nodal = nodal_settle_measures();
      change           = nodal[0];
      largest          = nodal[1];
      penetration      = nodal[2];
      // Coulomb's law at the points against the projected pressure of
      // this solve, the normal force their next solve will lag
      excess = coulomb_excess_on_faces();
    }
    const double tolerance = parameters.settle_tolerance;
    // on the faces the nodes' forces may settle while Coulomb's law at the
    // points, against the pressure projected from them, is still off by a
    // little more than the tolerance (1.1e-3 measured on the 2D drag): the
    // step settles when it holds too
    const bool settled =
        change <= tolerance * largest + force_floor && turn <= tolerance &&
        penetration <= tolerance &&
        (!parameters.integrate_on_faces || excess <= tolerance);
    std::ostringstream line;
    line << std::scientific << std::setprecision(2)
         << "normal forces changed by " << change << " N (largest " << largest
         << " N), normals by " << turn << " rad, penetration/spacing "
         << penetration << ", Coulomb excess " << excess
         << (settled ? ": settled" : "");
    report = line.str();
    if (settled)
      return true;
    if (parameters.integrate_on_faces)
      project_multipliers();
    else
      for (Point &point : points) // Uzawa
        lag_at(point, point.potential.normal_force);
    return false;
  }

  template <int dim>
  void PotentialContact<dim>::lag_at(Point &point, const double normal_force)
  {
    Lag &lag         = point.lag;
    lag.multiplier   = normal_force;
    lag.normal_force = point.proximity.body >= 0 ? normal_force : 0;
    if (lag.normal_force > 0)
    {
      lag.normal = point.proximity.normal;
      lag.body   = point.proximity.body;
      lag.geom   = point.proximity.geom;
    }
    else
      lag.body = -1;
  }

  template <int dim>
  unsigned int PotentialContact<dim>::max_outer_iterations() const
  {
    return parameters.max_outer_iterations;
  }

  template <int dim>
  unsigned int PotentialContact<dim>::max_newton_iterations() const
  {
    return parameters.max_newton_iterations;
  }

  template <int dim> bool PotentialContact<dim>::accept_unsettled() const
  {
    return parameters.accept_unsettled;
  }

  template <int dim> double PotentialContact<dim>::coulomb_excess() const
  {
    return excess;
  }

  template <int dim> unsigned int PotentialContact<dim>::changes_in_step() const
  {
    return step_changes;
  }

  template <int dim>
  void PotentialContact<dim>::apply_to_residual(
      TrilinosWrappers::MPI::Vector &residual) const
  {
    // residual = f_ext - f_int + the contact force (= -grad of the total)
    for (const Node &node : node_list)
      for (unsigned int a = 0; a < dim; ++a)
        if (node.free[a] && node.force[a] != 0)
          residual[node.dofs[a]] += node.force[a];
    residual.compress(VectorOperation::add);
  }

  template <int dim>
  void PotentialContact<dim>::transform_cell_rows(
      const std::vector<types::global_dof_index> &,
      FullMatrix<double> &,
      Vector<double> &) const
  {
    // the nodes keep their own equilibrium rows
  }

  template <int dim>
  void PotentialContact<dim>::add_constraints(AffineConstraints<double> &) const
  {
    // no constraints: contact acts through the potential
  }

  template <int dim>
  void PotentialContact<dim>::add_node_terms(
      const AffineConstraints<double> &constraints,
      TrilinosWrappers::SparseMatrix  &tangent,
      TrilinosWrappers::MPI::Vector   &rhs) const
  {
    FullMatrix<double> H;
    Vector<double>     f;
    for (const Patch &patch : patches)
    {
      const unsigned int n = patch.dofs.size();
      H.reinit(n, n);
      f.reinit(n);
      bool any = false;
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        const NodalPotential &p = points[i].potential;
        if (p.force.isZero(0) && p.hessian.isZero(0))
          continue;
        any                     = true;
        Eigen::Matrix3d hessian = p.hessian;
        if (project)
        {
          // the nearest positive semi-definite matrix: negative eigenvalues
          // (the curvature of the rigid surface) set to zero
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(hessian);
          hessian = eigen.eigenvectors() *
                    eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                    eigen.eigenvectors().transpose();
        }
        // x = X + sum_k N_k u_k: force N_k f, Hessian N_k N_l H
        const auto &N = points[i].shape;
        for (unsigned int r = 0; r < n; ++r)
        {
          const unsigned int k = r / dim, a = r % dim;
          if (!patch.free[r])
            continue;
          f[r] += N[k] * p.force[a];
          for (unsigned int s = 0; s < n; ++s)
            if (patch.free[s])
              H(r, s) += N[k] * N[s / dim] * hessian(a, s % dim);
        }
      }
      if (any)
        constraints.distribute_local_to_global(H, f, patch.dofs, tangent, rhs);
    }
    tangent.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim> bool PotentialContact<dim>::symmetric() const
  {
    return !polishing;
  }

  template <int dim> bool PotentialContact<dim>::is_potential() const
  {
    return !polishing;
  }

  template <int dim> bool PotentialContact<dim>::backtrack_on_residual() const
  {
    return polishing;
  }

  template <int dim> bool PotentialContact<dim>::begin_polish()
  {
    if (parameters.friction_coefficient == 0)
      return false; // nothing is lagged but the multipliers
    lag_before_polish.resize(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      lag_before_polish[i] = points[i].lag;
    if (parameters.integrate_on_faces)
      polish_multiplier = owned_multiplier;
    polishing = true;
    return true;
  }

  template <int dim> void PotentialContact<dim>::end_polish(const bool keep)
  {
    polishing = false;
    if (keep)
      return;
    for (unsigned int i = 0; i < points.size(); ++i)
      points[i].lag = lag_before_polish[i];
    if (parameters.integrate_on_faces)
      owned_multiplier = polish_multiplier;
  }

  template <int dim> unsigned int PotentialContact<dim>::polish_after() const
  {
    return parameters.polish_after;
  }

  template <int dim>
  void PotentialContact<dim>::project_to_positive(const bool on)
  {
    project = on;
  }

  template <int dim> double PotentialContact<dim>::energy() const
  {
    return total_energy;
  }

  template <int dim> std::string PotentialContact<dim>::iteration_report() const
  {
    std::ostringstream out;
    out << "contact " << active_count << " closed (" << slip_count << " slip), "
        << change_count << " changes";
    return out.str();
  }

  template <int dim>
  std::string
  PotentialContact<dim>::describe_node(const types::global_dof_index dof) const
  {
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const Node &node = node_list[j];
      if (std::find(node.dofs.begin(), node.dofs.end(), dof) == node.dofs.end())
        continue;
      const char        *status[] = {"open", "sticking", "sliding"};
      std::ostringstream out;
      out << "a contact node, " << status[static_cast<int>(node.status)];
      if (node.body >= 0)
        out << ", nearest geom "
            << this->bodies.geom_label(node.body, node.geom) << " at gap "
            << node.gap << " m";
      if (!parameters.integrate_on_faces) // point j is node j
        out << ", normal force " << points[j].potential.normal_force
            << " N (lagged " << points[j].lag.normal_force << " N)";
      out << ", slip " << node.slip.norm() << " m, force ("
          << node.force.transpose() << ") N";
      return out.str();
    }
    return "";
  }

  template class PotentialContact<2>;
  template class PotentialContact<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_CONTACT_ENFORCEMENT(
    softgrasp::PotentialContact,
    incremental_potential,
    "incremental potential",
    "each step the minimisation of one potential: an augmented Lagrangian "
    "on the gap and friction as a lagged, smoothed dissipation potential, "
    "Newton with a line search on the potential, outer iterations until "
    "the normal forces and frames settle (cannot cycle between stick and "
    "slip)")
