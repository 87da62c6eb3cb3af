#include <cmath>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector_operation.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/contact/mortar_contact.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  MortarContact<dim>::MortarContact(const ContactParameters &parameters,
                                    const RigidBodySet      &bodies,
                                    const double             shear_modulus,
                                    TimerOutput             &timer)
      : ContactSurface<dim>(parameters, bodies)
      , shear_modulus(shear_modulus)
      , timer(timer)
  {
  }

  template <int dim>
  void MortarContact<dim>::setup(const SolidSystem<dim> &system)
  {
    ContactSurface<dim>::setup(system);
    const IndexSet &owned  = system.locally_owned_dofs();
    const IndexSet &ghosts = system.locally_relevant_dofs();
    for (auto &v : row_combination)
      v.reinit(owned, ghosts, this->comm);
    governed.reinit(owned, ghosts, this->comm);
    owned_scratch.reinit(owned, this->comm);
    fd_step = 1e-7 * system.length_scale();
    law.assign(this->node_list.size(), NodeLaw());
    for (unsigned int j = 0; j < law.size(); ++j)
    {
      const double h = std::pow(this->node_list[j].reference_area,
                                (dim - 2.0) / (dim - 1.0));
      law[j].c =
          this->parameters.complementarity_factor * 2 * shear_modulus * h;
      law[j].c_n = law[j].c;
      law[j].c_t = law[j].c;
    }
  }

  template <int dim>
  void
  MortarContact<dim>::set_inertia(const TrilinosWrappers::MPI::Vector &mass,
                                  const double inverse_dt_squared)
  {
    for (unsigned int j = 0; j < law.size(); ++j)
    {
      law[j].c_n = law[j].c + inverse_dt_squared * mass[node_list[j].dofs[0]];
      law[j].c_t = law[j].c_n;
    }
  }

  template <int dim>
  void MortarContact<dim>::accept_step(const SolidSystem<dim> &system,
                                       const double            time)
  {
    const auto &u = system.ghosted_solution();
    for (auto &node : node_list)
    {
      node.last_converged = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
        node.last_converged[c] += u[node.dofs[c]];
    }
    converged_time = time;
    place_bodies(time, poses_converged);
    step_changes = 0;
  }

  template <int dim>
  Eigen::Matrix3d
  MortarContact<dim>::normal_gradient(const Proximity       &p,
                                      const Eigen::Vector3d &x) const
  {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (unsigned int k = 0; k < dim; ++k)
    {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k]              = fd_step;
      H.col(k) = (normal_at(p, x + e) - normal_at(p, x - e)) / (2 * fd_step);
    }
    return 0.5 * (H + H.transpose());
  }

  template <int dim>
  void MortarContact<dim>::evaluate(const SolidSystem<dim> &system)
  {
    TimerOutput::Scope scope(timer, "contact");
    place_bodies(current_time, poses_now);
    const auto &u           = system.ghosted_solution();
    const auto &f_int       = system.internal_forces();
    const auto &f_ext       = system.external_forces();
    const auto &constraints = system.constraint_set();

    std::array<TrilinosWrappers::MPI::Vector, dim> combination;
    for (auto &v : combination)
      v.reinit(owned_scratch, true), v = 0;
    TrilinosWrappers::MPI::Vector is_governed(owned_scratch);
    is_governed = 0;

    unsigned int active = 0, slipping = 0, changes = 0;
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      Node           &node = node_list[j];
      NodeLaw        &rule = law[j];
      Eigen::Vector3d x    = node.reference_position;
      Eigen::Vector3d f    = Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < dim; ++c)
      {
        node.free[c] = !constraints.is_constrained(node.dofs[c]);
        x[c] += u[node.dofs[c]];
        if (node.free[c])
          f[c] = f_int[node.dofs[c]] - f_ext[node.dofs[c]];
      }
      const ContactStatus before = node.status;
      const Proximity     p      = nearest(x);
      NodalContactInput   input;
      input.f   = f;
      input.mu  = parameters.friction_coefficient;
      input.c   = rule.c_n;
      input.c_t = rule.c_t;
      input.gap = p.gap;
      input.n   = p.body >= 0 ? p.normal : Eigen::Vector3d(0, 0, 1);
      input.H.setZero();
      input.w.setZero();
      if (p.body >= 0)
      {
        const Pose &now = poses_now[p.body][p.geom];
        const Pose &old = poses_converged[p.body][p.geom];
        input.w         = x - now.to_world(old.to_local(node.last_converged));
        if (dim == 2)
          input.w[2] = 0;
        if (input.n.dot(f) - input.c * input.gap > 0)
          input.H = normal_gradient(p, x);
      }
      else
        input.gap = std::numeric_limits<double>::max();
      const NodalContactLinearization lin = evaluate_nodal_contact(input);

      node.status = lin.status;
      node.body   = p.body;
      node.geom   = p.geom;
      node.gap    = p.gap;
      node.normal = input.n;
      node.force  = f;
      node.slip   = lin.slip;
      rule.phi    = lin.phi;
      rule.A      = lin.A;
      rule.B      = lin.B;
      // Constrained components (symmetry planes, hanging nodes) keep their
      // own equations; the contact conditions act on the free ones.
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
        {
          const bool a_free = a < dim && node.free[a];
          const bool b_free = b < dim && node.free[b];
          if (!a_free)
          {
            rule.A(a, b) = (a == b ? 1.0 : 0.0);
            rule.B(a, b) = 0;
          }
          else if (!b_free)
          {
            rule.A(a, b) = 0;
            rule.B(a, b) = 0;
          }
        }
      for (unsigned int a = 0; a < 3; ++a)
        if (a >= dim || !node.free[a])
          rule.phi[a] = f[a];

      if (lin.status != ContactStatus::inactive)
      {
        ++active;
        is_governed[node.dofs[0]] = 1;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            combination[b][node.dofs[a]] = rule.A(a, b);
      }
      if (lin.status == ContactStatus::slip)
        ++slipping;
      if (lin.status != before)
        ++changes;
    }
    for (unsigned int b = 0; b < dim; ++b)
    {
      combination[b].compress(VectorOperation::insert);
      row_combination[b] = combination[b];
    }
    is_governed.compress(VectorOperation::insert);
    governed     = is_governed;
    active_count = Utilities::MPI::sum(active, comm);
    slip_count   = Utilities::MPI::sum(slipping, comm);
    change_count = Utilities::MPI::sum(changes, comm);
    step_changes += change_count;
  }

  template <int dim>
  void MortarContact<dim>::apply_to_residual(
      TrilinosWrappers::MPI::Vector &residual) const
  {
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const Node &node = node_list[j];
      if (node.status != ContactStatus::inactive)
        for (unsigned int a = 0; a < dim; ++a)
          if (node.free[a])
            residual[node.dofs[a]] = -law[j].phi[a];
    }
    residual.compress(VectorOperation::insert);
  }

  template <int dim>
  void MortarContact<dim>::transform_cell_rows(
      const std::vector<types::global_dof_index> &dof_indices,
      FullMatrix<double>                         &matrix,
      Vector<double>                             &rhs) const
  {
    const unsigned int              n = matrix.n();
    std::array<Vector<double>, dim> rows;
    std::array<double, dim>         rhs_rows;
    for (const auto &node : cell_nodes)
    {
      if (governed[dof_indices[node[0]]] == 0)
        continue;
      for (unsigned int b = 0; b < dim; ++b)
      {
        rows[b].reinit(n);
        for (unsigned int j = 0; j < n; ++j)
          rows[b][j] = matrix(node[b], j);
        rhs_rows[b] = rhs[node[b]];
      }
      for (unsigned int a = 0; a < dim; ++a)
      {
        double combined_rhs = 0;
        for (unsigned int j = 0; j < n; ++j)
          matrix(node[a], j) = 0;
        for (unsigned int b = 0; b < dim; ++b)
        {
          const double weight = row_combination[b][dof_indices[node[a]]];
          if (weight == 0)
            continue;
          for (unsigned int j = 0; j < n; ++j)
            matrix(node[a], j) += weight * rows[b][j];
          combined_rhs += weight * rhs_rows[b];
        }
        rhs[node[a]] = combined_rhs;
      }
    }
  }

  template <int dim>
  void
  MortarContact<dim>::add_node_terms(TrilinosWrappers::SparseMatrix &tangent,
                                     TrilinosWrappers::MPI::Vector  &rhs) const
  {
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const Node    &node = node_list[j];
      const NodeLaw &rule = law[j];
      if (node.status == ContactStatus::inactive)
        continue;
      const Eigen::Vector3d Af = rule.A * node.force;
      for (unsigned int a = 0; a < dim; ++a)
      {
        if (!node.free[a])
          continue;
        for (unsigned int b = 0; b < dim; ++b)
          if (node.free[b] && rule.B(a, b) != 0)
            tangent.add(node.dofs[a], node.dofs[b], rule.B(a, b));
        rhs[node.dofs[a]] += -(rule.phi[a] - Af[a]);
      }
    }
    tangent.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim> std::string MortarContact<dim>::iteration_report() const
  {
    std::ostringstream out;
    out << "contact " << active_count << " active (" << slip_count << " slip), "
        << change_count << " changes";
    return out.str();
  }

  template <int dim> unsigned int MortarContact<dim>::n_changes() const
  {
    return change_count;
  }

  template <int dim> unsigned int MortarContact<dim>::changes_in_step() const
  {
    return step_changes;
  }

  template class MortarContact<2>;
  template class MortarContact<3>;
} // namespace softgrasp
