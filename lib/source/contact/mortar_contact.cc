#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector_operation.h>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/contact/mortar_contact.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// @p v after its inserted values are exchanged between processes.
    TrilinosWrappers::MPI::Vector &compressed(TrilinosWrappers::MPI::Vector &v)
    {
      v.compress(VectorOperation::insert);
      return v;
    }
  } // namespace

  template <int dim>
  MortarContact<dim>::MortarContact(const ContactParameters &parameters,
                                    const RigidBodySet      &bodies,
                                    const double             shear_modulus,
                                    TimerOutput             &timer)
      : ImplicitContact<dim>(parameters, bodies)
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
    constraint_coefficients.reinit(owned, ghosts, this->comm);
    constraint_values.reinit(owned, ghosts, this->comm);
    find_relevant_nodes(system);
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
  void MortarContact<dim>::find_relevant_nodes(const SolidSystem<dim> &system)
  {
    const auto                          &fe = system.fe();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    relevant_nodes.clear();
    for (const auto &cell : system.dof_handler().active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      cell->get_dof_indices(indices);
      for (const auto f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary() ||
            !this->is_slave_boundary(cell->face(f)->boundary_id()))
          continue;
        for (const auto &point : cell_nodes)
        {
          if (!fe.has_support_on_face(point[0], f) ||
              !seen.insert(indices[point[0]]).second)
            continue;
          std::array<types::global_dof_index, dim> node;
          for (unsigned int c = 0; c < dim; ++c)
            node[c] = indices[point[c]];
          relevant_nodes.push_back(node);
        }
      }
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
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const bool closed    = node_list[j].status != ContactStatus::inactive;
      law[j].pair_body     = closed ? node_list[j].body : -1;
      law[j].pair_geom     = node_list[j].geom;
      law[j].pair_switches = 0;
    }
    converged_time = time;
    place_bodies(time, poses_converged);
    step_changes = 0;
  }

  template <int dim>
  typename MortarContact<dim>::Proximity
  MortarContact<dim>::pair(const unsigned int j, const Eigen::Vector3d &x)
  {
    NodeLaw        &rule         = law[j];
    const Proximity nearest_geom = this->nearest(x);
    if (rule.pair_body < 0 || nearest_geom.body < 0 ||
        (nearest_geom.body == rule.pair_body &&
         nearest_geom.geom == rule.pair_geom))
      return nearest_geom;
    const Proximity kept = this->distance_to(rule.pair_body, rule.pair_geom, x);
    const double    size =
        std::pow(node_list[j].reference_area, 1.0 / (dim - 1.0));
    if (rule.pair_switches >= 2 || nearest_geom.gap > kept.gap - 0.01 * size)
      return kept;
    ++rule.pair_switches;
    rule.pair_body = nearest_geom.body;
    rule.pair_geom = nearest_geom.geom;
    return nearest_geom;
  }

  template <int dim>
  NodalContactInput MortarContact<dim>::contact_input(const unsigned int     j,
                                                      const Eigen::Vector3d &x,
                                                      const Eigen::Vector3d &f,
                                                      const Proximity &p) const
  {
    NodalContactInput input;
    input.f   = f;
    input.mu  = parameters.friction_coefficient;
    input.c   = law[j].c_n;
    input.c_t = law[j].c_t;
    input.gap = p.gap;
    input.n   = p.body >= 0 ? p.normal : Eigen::Vector3d(0, 0, 1);
    input.H.setZero();
    input.w.setZero();
    if (p.body < 0)
    {
      input.gap = std::numeric_limits<double>::max();
      return input;
    }
    // The slip increment: the node's motion relative to the geom since the
    // last converged step.
    const Pose &now = poses_now[p.body][p.geom];
    const Pose &old = poses_converged[p.body][p.geom];
    input.w = x - now.to_world(old.to_local(node_list[j].last_converged));
    if (dim == 2)
      input.w[2] = 0;
    if (input.n.dot(f) - input.c * input.gap > 0)
      input.H = this->normal_gradient(p, x, fd_step);
    return input;
  }

  template <int dim>
  void MortarContact<dim>::keep_constrained_rows(const Node            &node,
                                                 NodeLaw               &rule,
                                                 const Eigen::Vector3d &f)
  {
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
  }

  template <int dim>
  void MortarContact<dim>::store(const unsigned int               j,
                                 const Proximity                 &p,
                                 const NodalContactInput         &input,
                                 const NodalContactLinearization &lin)
  {
    Node    &node = node_list[j];
    NodeLaw &rule = law[j];
    if (lin.status != ContactStatus::inactive && rule.pair_body < 0)
    {
      rule.pair_body = p.body;
      rule.pair_geom = p.geom;
    }
    node.status = lin.status;
    node.body   = p.body;
    node.geom   = p.geom;
    node.gap    = p.gap;
    node.normal = input.n;
    node.force  = input.f;
    node.slip   = lin.slip;
    rule.phi    = lin.phi;
    rule.A      = lin.A;
    rule.B      = lin.B;
    keep_constrained_rows(node, rule, input.f);
  }

  template <int dim>
  void MortarContact<dim>::evaluate(const SolidSystem<dim> &system)
  {
    TimerOutput::Scope scope(timer, "contact");
    place_bodies(current_time, poses_now);
    const auto &u     = system.ghosted_solution();
    const auto &f_int = system.internal_forces();
    const auto &f_ext = system.external_forces();

    std::array<TrilinosWrappers::MPI::Vector, dim> combination;
    for (auto &v : combination)
      v.reinit(owned_scratch, true), v = 0;
    TrilinosWrappers::MPI::Vector is_governed(owned_scratch),
        coefficients(owned_scratch), values(owned_scratch);
    is_governed  = 0;
    coefficients = 0;
    values       = 0;

    unsigned int active = 0, slipping = 0, changes = 0, unsymmetric = 0,
                 switches = 0;
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      Node           &node = node_list[j];
      NodeLaw        &rule = law[j];
      Eigen::Vector3d x    = node.reference_position;
      Eigen::Vector3d f    = Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < dim; ++c)
      {
        node.free[c] = !system.constraint_set().is_constrained(node.dofs[c]);
        x[c] += u[node.dofs[c]];
        if (node.free[c])
          f[c] = f_int[node.dofs[c]] - f_ext[node.dofs[c]];
      }
      const ContactStatus             before = node.status;
      const Proximity                 p      = pair(j, x);
      const NodalContactInput         input  = contact_input(j, x, f, p);
      const NodalContactLinearization lin    = evaluate_nodal_contact(input);
      if (lin.status != ContactStatus::inactive &&
          before != ContactStatus::inactive &&
          (p.body != node.body || p.geom != node.geom))
        ++switches;

      store(j, p, input, lin);

      if (lin.status != ContactStatus::inactive)
      {
        ++active;
        const Governance how      = constrain(node, rule, coefficients, values);
        is_governed[node.dofs[0]] = how;
        if (how == rows_only ||
            (lin.status == ContactStatus::slip && input.mu > 0))
          ++unsymmetric;
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
      row_combination[b] = compressed(combination[b]);
    governed                = compressed(is_governed);
    constraint_coefficients = compressed(coefficients);
    constraint_values       = compressed(values);
    unsymmetric_count       = Utilities::MPI::sum(unsymmetric, comm);
    active_count            = Utilities::MPI::sum(active, comm);
    slip_count              = Utilities::MPI::sum(slipping, comm);
    change_count            = Utilities::MPI::sum(changes, comm);
    switch_count            = Utilities::MPI::sum(switches, comm);
    step_changes += change_count;
  }

  template <int dim>
  typename MortarContact<dim>::Governance
  MortarContact<dim>::constrain(const Node                    &node,
                                const NodeLaw                 &rule,
                                TrilinosWrappers::MPI::Vector &coefficients,
                                TrilinosWrappers::MPI::Vector &values) const
  {
    // The node's equations on its free components (symmetry planes and
    // hanging nodes keep their own constraints); the other rows become
    // du_a = 0, which the masked law already has (A = I, B = 0, phi = f).
    Eigen::Matrix3d B   = rule.B;
    Eigen::Vector3d phi = rule.phi, n = node.normal;
    bool            any = false;
    for (unsigned int a = 0; a < 3; ++a)
      if (a < dim && node.free[a])
        any = true;
      else
      {
        B.row(a).setZero();
        B.col(a).setZero();
        B(a, a) = 1;
        phi[a]  = 0;
        n[a]    = 0;
      }
    if (!any)
      return rows_only;

    if (node.status == ContactStatus::stick)
    {
      // A = 0: the node's equations B du = -phi do not involve K.
      const Eigen::Vector3d du = B.fullPivLu().solve(-phi);
      if (!du.allFinite() ||
          (B * du + phi).norm() > 1e-8 * phi.norm() + 1e-12 * B.norm())
        return rows_only;
      for (unsigned int a = 0; a < dim; ++a)
        if (node.free[a])
        {
          coefficients[node.dofs[a]] = 1;
          values[node.dofs[a]]       = du[a];
        }
      return fixed;
    }

    // Sliding: n^T A = 0, so n^T (A K du + B du) = -n^T phi is node-local.
    const bool      friction = parameters.friction_coefficient > 0;
    Eigen::Vector3d w        = friction ? Eigen::Vector3d(B.transpose() * n)
                                        : Eigen::Vector3d(rule.c_n * n);
    unsigned int    k        = 0;
    for (unsigned int a = 0; a < dim; ++a)
      if (!node.free[a])
        w[a] = 0;
      else if (std::abs(w[a]) > std::abs(w[k]))
        k = a;
    // The rows left after condensation are tested with directions
    // orthogonal to w; with n . w small they would miss the tangents.
    if (!(std::abs(n.dot(w)) > 1e-3 * w.norm() * n.norm()))
      return rows_only;
    for (unsigned int a = 0; a < dim; ++a)
      coefficients[node.dofs[a]] = w[a];
    values[node.dofs[k]] = -n.dot(phi);
    return normal_line;
  }

  template <int dim>
  void MortarContact<dim>::add_constraints(
      AffineConstraints<double> &constraints) const
  {
    for (const auto &dofs : relevant_nodes)
    {
      const int how = static_cast<int>(governed[dofs[0]]);
      if (how == fixed)
      {
        for (unsigned int c = 0; c < dim; ++c)
          if (constraint_coefficients[dofs[c]] != 0)
          {
            constraints.add_line(dofs[c]);
            constraints.set_inhomogeneity(dofs[c], constraint_values[dofs[c]]);
          }
      }
      else if (how == normal_line)
      {
        // w . du = beta, solved for the component with the largest |w_k|
        // (the one that carries beta); the choice is the same on every rank.
        unsigned int k = 0;
        for (unsigned int c = 1; c < dim; ++c)
          if (std::abs(constraint_coefficients[dofs[c]]) >
              std::abs(constraint_coefficients[dofs[k]]))
            k = c;
        const double w_k = constraint_coefficients[dofs[k]];
        constraints.add_line(dofs[k]);
        for (unsigned int c = 0; c < dim; ++c)
          if (c != k && constraint_coefficients[dofs[c]] != 0)
            constraints.add_entry(
                dofs[k], dofs[c], -constraint_coefficients[dofs[c]] / w_k);
        constraints.set_inhomogeneity(dofs[k],
                                      constraint_values[dofs[k]] / w_k);
      }
    }
  }

  template <int dim> bool MortarContact<dim>::symmetric() const
  {
    return unsymmetric_count == 0;
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
  void MortarContact<dim>::add_node_terms(
      const AffineConstraints<double> &constraints,
      TrilinosWrappers::SparseMatrix  &tangent,
      TrilinosWrappers::MPI::Vector   &rhs) const
  {
    FullMatrix<double>                   B(dim, dim);
    Vector<double>                       b(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const Node    &node = node_list[j];
      const NodeLaw &rule = law[j];
      if (node.status == ContactStatus::inactive)
        continue;
      const Eigen::Vector3d Af = rule.A * node.force;
      B                        = 0;
      b                        = 0;
      for (unsigned int a = 0; a < dim; ++a)
      {
        dofs[a] = node.dofs[a];
        if (!node.free[a])
          continue;
        for (unsigned int c = 0; c < dim; ++c)
          if (node.free[c])
            B(a, c) = rule.B(a, c);
        b[a] = -(rule.phi[a] - Af[a]);
      }
      constraints.distribute_local_to_global(B, b, dofs, tangent, rhs);
    }
    tangent.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim> std::string MortarContact<dim>::iteration_report() const
  {
    std::ostringstream out;
    out << "contact " << active_count << " active (" << slip_count << " slip), "
        << change_count << " changes";
    if (switch_count > 0)
      out << ", " << switch_count << " closed nodes changed geom";
    return out.str();
  }

  template <int dim>
  std::string
  MortarContact<dim>::describe_node(const types::global_dof_index dof) const
  {
    for (const Node &node : node_list)
    {
      if (std::find(node.dofs.begin(), node.dofs.end(), dof) == node.dofs.end())
        continue;
      const char        *status[] = {"open", "sticking", "sliding"};
      std::ostringstream out;
      out << "a contact node, " << status[static_cast<int>(node.status)];
      if (node.body >= 0)
        out << ", nearest geom "
            << this->bodies.geom_label(node.body, node.geom) << " at gap "
            << node.gap << " m";
      out << ", normal (" << node.normal.transpose() << "), force ("
          << node.force.transpose() << ") N";
      return out.str();
    }
    return "";
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

SOFTGRASP_REGISTER_CONTACT_ENFORCEMENT(
    softgrasp::MortarContact,
    lagrange_multipliers,
    "lagrange multipliers",
    "dual mortar Lagrange multipliers condensed at the nodes, KKT and "
    "Coulomb conditions as complementarity functions, active set decided "
    "per Newton iteration (exact, no penalty; may cycle between stick and "
    "slip on a deep frictional drag, doc/contact.md)")
