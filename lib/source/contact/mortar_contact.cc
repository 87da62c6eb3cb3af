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
      : parameters(parameters)
      , bodies(bodies)
      , shear_modulus(shear_modulus)
      , timer(timer)
  {
  }

  template <int dim>
  void MortarContact<dim>::setup(const SolidSystem<dim> &system)
  {
    comm                      = system.communicator();
    const auto        &fe     = system.fe();
    const auto        &dofs   = system.dof_handler();
    const IndexSet    &owned  = system.locally_owned_dofs();
    const IndexSet    &ghosts = system.locally_relevant_dofs();
    const unsigned int n_pts  = fe.base_element(0).n_dofs_per_cell();
    const unsigned int degree = fe.degree;
    cell_nodes.assign(n_pts, {});
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      const auto [c, k] = fe.system_to_component_index(i);
      cell_nodes[k][c]  = i;
    }
    for (auto &v : row_combination)
      v.reinit(owned, ghosts, comm);
    governed.reinit(owned, ghosts, comm);
    owned_scratch.reinit(owned, comm);
    fd_step = 1e-7 * system.length_scale();

    const std::set<types::boundary_id> slave(
        parameters.slave_boundary_ids.begin(),
        parameters.slave_boundary_ids.end());
    const auto on_slave = [&](const auto &cell, const unsigned int f)
    {
      return cell->face(f)->at_boundary() &&
             slave.count(cell->face(f)->boundary_id()) > 0;
    };

    // Reference nodal areas D_j = int N_j dA over the slave surface.
    TrilinosWrappers::MPI::Vector area;
    area.reinit(owned, ghosts, comm, true);
    FEFaceValues<dim>                    face_values(system.mapping(),
                                  fe,
                                  QGauss<dim - 1>(degree + 1),
                                  update_values | update_JxW_values);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (on_slave(cell, f))
          {
            face_values.reinit(cell, f);
            cell->get_dof_indices(indices);
            for (unsigned int k = 0; k < n_pts; ++k)
            {
              const unsigned int i   = cell_nodes[k][0];
              double             sum = 0;
              for (const auto q : face_values.quadrature_point_indices())
                sum += face_values.shape_value(i, q) * face_values.JxW(q);
              area[indices[i]] += sum;
            }
          }
    area.compress(VectorOperation::add);

    // The owned nodes, found from owned and ghost cells.
    FEValues<dim>                     support(system.mapping(),
                          fe,
                          Quadrature<dim>(fe.get_unit_support_points()),
                          update_quadrature_points);
    std::set<types::global_dof_index> seen;
    node_list.clear();
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (cell->is_artificial())
        continue;
      bool any = false;
      for (const auto f : cell->face_indices())
        any = any || on_slave(cell, f);
      if (!any)
        continue;
      cell->get_dof_indices(indices);
      support.reinit(cell);
      for (const auto f : cell->face_indices())
        if (on_slave(cell, f))
          for (unsigned int k = 0; k < n_pts; ++k)
          {
            const unsigned int i = cell_nodes[k][0];
            if (!fe.has_support_on_face(i, f) ||
                !owned.is_element(indices[i]) || seen.count(indices[i]))
              continue;
            seen.insert(indices[i]);
            Node node;
            for (unsigned int c = 0; c < dim; ++c)
              node.dofs[c] = indices[cell_nodes[k][c]];
            const Point<dim> &X = support.quadrature_point(i);
            for (unsigned int d = 0; d < dim; ++d)
              node.reference_position[d] = X[d];
            node.last_converged = node.reference_position;
            node.reference_area = area[indices[i]];
            if (!(node.reference_area > 0))
              throw InputError(
                  "The contact surface has a node with non-positive weight "
                  "int N_j dA = " +
                  std::to_string(node.reference_area) +
                  "; the dual mortar basis needs positive weights. Fix: use "
                  "Lagrange elements of degree 1 or 2 on the slave surface.");
            const double h =
                std::pow(node.reference_area, (dim - 2.0) / (dim - 1.0));
            node.c = parameters.complementarity_factor * 2 * shear_modulus * h;
            node_list.push_back(node);
          }
    }
    const unsigned int total =
        Utilities::MPI::sum<unsigned int>(node_list.size(), comm);
    if (total == 0)
      throw InputError("The contact surface is empty: no boundary face has "
                       "one of the ids in 'Contact/Slave boundary ids'. Fix: "
                       "give the boundary ids of the surface that touches "
                       "the rigid bodies.");
  }

  template <int dim> void MortarContact<dim>::set_time(const double time)
  {
    current_time = time;
  }

  template <int dim>
  void
  MortarContact<dim>::place_bodies(const double                    time,
                                   std::vector<std::vector<Pose>> &poses) const
  {
    const auto &list = bodies.bodies();
    poses.resize(list.size());
    for (unsigned int b = 0; b < list.size(); ++b)
    {
      poses[b].resize(list[b].geoms().size());
      for (unsigned int g = 0; g < list[b].geoms().size(); ++g)
        poses[b][g] = list[b].geom_pose(g, time);
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
  Eigen::Vector3d MortarContact<dim>::normal_at(const Proximity       &p,
                                                const Eigen::Vector3d &x) const
  {
    const Pose     &pose = poses_now[p.body][p.geom];
    const auto     &geom = bodies.bodies()[p.body].geoms()[p.geom];
    Eigen::Vector3d n =
        pose.rotate_to_world(geom.shape->query(pose.to_local(x)).normal);
    if (dim == 2)
    {
      n[2] = 0;
      n.normalize();
    }
    return n;
  }

  template <int dim>
  typename MortarContact<dim>::Proximity
  MortarContact<dim>::nearest(const Eigen::Vector3d &x) const
  {
    Proximity   best;
    const auto &list = bodies.bodies();
    for (unsigned int b = 0; b < list.size(); ++b)
      for (unsigned int g = 0; g < list[b].geoms().size(); ++g)
      {
        const Pose  &pose  = poses_now[b][g];
        const Shape &shape = *list[b].geoms()[g].shape;
        // The bounding sphere bounds the distance from below: skip geoms
        // that cannot be nearer than the best so far.
        if ((x - pose.position).norm() - shape.bounding_radius() >= best.gap)
          continue;
        const ShapeQuery q = shape.query(pose.to_local(x));
        if (q.distance < best.gap)
        {
          best.body   = b;
          best.geom   = g;
          best.gap    = q.distance;
          best.normal = pose.rotate_to_world(q.normal);
        }
      }
    if (dim == 2 && best.body >= 0)
    {
      best.normal[2] = 0;
      best.normal.normalize();
    }
    return best;
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
    for (auto &node : node_list)
    {
      Eigen::Vector3d x = node.reference_position;
      Eigen::Vector3d f = Eigen::Vector3d::Zero();
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
      input.c   = node.c;
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
      node.phi    = lin.phi;
      node.A      = lin.A;
      node.B      = lin.B;
      // Constrained components (symmetry planes, hanging nodes) keep their
      // own equations; the contact conditions act on the free ones.
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
        {
          const bool a_free = a < dim && node.free[a];
          const bool b_free = b < dim && node.free[b];
          if (!a_free)
          {
            node.A(a, b) = (a == b ? 1.0 : 0.0);
            node.B(a, b) = 0;
          }
          else if (!b_free)
          {
            node.A(a, b) = 0;
            node.B(a, b) = 0;
          }
        }
      for (unsigned int a = 0; a < 3; ++a)
        if (a >= dim || !node.free[a])
          node.phi[a] = f[a];

      if (lin.status != ContactStatus::inactive)
      {
        ++active;
        is_governed[node.dofs[0]] = 1;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            combination[b][node.dofs[a]] = node.A(a, b);
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
    for (const auto &node : node_list)
      if (node.status != ContactStatus::inactive)
        for (unsigned int a = 0; a < dim; ++a)
          if (node.free[a])
            residual[node.dofs[a]] = -node.phi[a];
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
    for (const auto &node : node_list)
    {
      if (node.status == ContactStatus::inactive)
        continue;
      const Eigen::Vector3d Af = node.A * node.force;
      for (unsigned int a = 0; a < dim; ++a)
      {
        if (!node.free[a])
          continue;
        for (unsigned int b = 0; b < dim; ++b)
          if (node.free[b] && node.B(a, b) != 0)
            tangent.add(node.dofs[a], node.dofs[b], node.B(a, b));
        rhs[node.dofs[a]] += -(node.phi[a] - Af[a]);
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

  template <int dim>
  const std::vector<typename MortarContact<dim>::Node> &
  MortarContact<dim>::nodes() const
  {
    return node_list;
  }

  template <int dim>
  const RigidBodySet &MortarContact<dim>::rigid_bodies() const
  {
    return bodies;
  }

  template <int dim>
  bool MortarContact<dim>::is_slave_boundary(const types::boundary_id id) const
  {
    for (const auto s : parameters.slave_boundary_ids)
      if (s == id)
        return true;
    return false;
  }

  template <int dim> double MortarContact<dim>::time() const
  {
    return current_time;
  }

  template <int dim> unsigned int MortarContact<dim>::n_active() const
  {
    return active_count;
  }

  template <int dim> unsigned int MortarContact<dim>::n_slip() const
  {
    return slip_count;
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
