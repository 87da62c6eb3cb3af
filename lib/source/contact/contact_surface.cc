#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector_operation.h>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/contact/contact_surface.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  ContactSurface<dim>::ContactSurface(const ContactParameters &parameters,
                                      const RigidBodySet      &bodies)
      : parameters(parameters)
      , bodies(bodies)
  {
  }

  template <int dim>
  template <typename CellIterator>
  bool ContactSurface<dim>::on_slave(const CellIterator &cell,
                                     const unsigned int  f) const
  {
    return cell->face(f)->at_boundary() &&
           is_slave_boundary(cell->face(f)->boundary_id());
  }

  template <int dim>
  void ContactSurface<dim>::setup(const SolidSystem<dim> &system)
  {
    comm                     = system.communicator();
    const auto        &fe    = system.fe();
    const unsigned int n_pts = fe.base_element(0).n_dofs_per_cell();
    cell_nodes.assign(n_pts, {});
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      const auto [c, k] = fe.system_to_component_index(i);
      cell_nodes[k][c]  = i;
    }
    collect_nodes(system, nodal_areas(system));
    const unsigned int total =
        Utilities::MPI::sum<unsigned int>(node_list.size(), comm);
    if (total == 0)
      throw InputError("The contact surface is empty: no boundary face has "
                       "one of the ids in 'Contact/Slave boundary ids'. Fix: "
                       "give the boundary ids of the surface that touches "
                       "the rigid bodies.");
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  ContactSurface<dim>::nodal_areas(const SolidSystem<dim> &system) const
  {
    const auto                   &fe = system.fe();
    TrilinosWrappers::MPI::Vector area;
    area.reinit(system.locally_owned_dofs(),
                system.locally_relevant_dofs(),
                comm,
                true);
    FEFaceValues<dim>                    face_values(system.mapping(),
                                  fe,
                                  QGauss<dim - 1>(fe.degree + 1),
                                  update_values | update_JxW_values);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (on_slave(cell, f))
          {
            face_values.reinit(cell, f);
            cell->get_dof_indices(indices);
            for (const auto &node : cell_nodes)
            {
              const unsigned int i   = node[0];
              double             sum = 0;
              for (const auto q : face_values.quadrature_point_indices())
                sum += face_values.shape_value(i, q) * face_values.JxW(q);
              area[indices[i]] += sum;
            }
          }
    area.compress(VectorOperation::add);
    return area;
  }

  template <int dim>
  std::vector<typename ContactSurface<dim>::SlaveFace>
  ContactSurface<dim>::slave_faces(const SolidSystem<dim> &system) const
  {
    const auto                          &fe = system.fe();
    FEFaceValues<dim>                    face_values(system.mapping(),
                                  fe,
                                  QGauss<dim - 1>(fe.degree + 2),
                                  update_values | update_JxW_values |
                                      update_quadrature_points);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::vector<SlaveFace>               faces;
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
        {
          if (!on_slave(cell, f))
            continue;
          face_values.reinit(cell, f);
          cell->get_dof_indices(indices);
          SlaveFace                 face;
          std::vector<unsigned int> on_face; // support points of the face
          for (unsigned int k = 0; k < cell_nodes.size(); ++k)
            if (fe.has_support_on_face(cell_nodes[k][0], f))
            {
              on_face.push_back(k);
              for (unsigned int c = 0; c < dim; ++c)
                face.dofs.push_back(indices[cell_nodes[k][c]]);
            }
          for (const auto q : face_values.quadrature_point_indices())
          {
            std::vector<double> shape;
            for (const unsigned int k : on_face)
              shape.push_back(face_values.shape_value(cell_nodes[k][0], q));
            face.shape.push_back(shape);
            face.weight.push_back(face_values.JxW(q));
            Eigen::Vector3d X = Eigen::Vector3d::Zero();
            for (unsigned int d = 0; d < dim; ++d)
              X[d] = face_values.quadrature_point(q)[d];
            face.position.push_back(X);
          }
          faces.push_back(face);
        }
    return faces;
  }

  template <int dim>
  void
  ContactSurface<dim>::collect_nodes(const SolidSystem<dim> &system,
                                     const TrilinosWrappers::MPI::Vector &area)
  {
    const auto                          &fe    = system.fe();
    const IndexSet                      &owned = system.locally_owned_dofs();
    FEValues<dim>                        support(system.mapping(),
                          fe,
                          Quadrature<dim>(fe.get_unit_support_points()),
                          update_quadrature_points);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    node_list.clear();
    for (const auto &cell : system.dof_handler().active_cell_iterators())
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
          for (const auto &local : cell_nodes)
          {
            const unsigned int i = local[0];
            if (!fe.has_support_on_face(i, f) ||
                !owned.is_element(indices[i]) || seen.count(indices[i]))
              continue;
            seen.insert(indices[i]);
            Node node;
            for (unsigned int c = 0; c < dim; ++c)
              node.dofs[c] = indices[local[c]];
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
            node_list.push_back(node);
          }
    }
  }

  template <int dim>
  template <typename VectorType>
  std::vector<double> ContactSurface<dim>::node_overlaps(const double      time,
                                                         const VectorType &u)
  {
    set_time(time);
    place_bodies(time, poses_now);
    std::vector<double> overlaps(node_list.size(), 0.0);
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      Eigen::Vector3d x = node_list[j].reference_position;
      for (unsigned int c = 0; c < dim; ++c)
        x[c] += u(node_list[j].dofs[c]);
      const Proximity p = nearest(x);
      if (p.body >= 0 && p.gap < 0)
        overlaps[j] = -p.gap;
    }
    return overlaps;
  }

  template <int dim>
  typename ContactSurface<dim>::Penetration
  ContactSurface<dim>::deepest_penetration(
      const TrilinosWrappers::MPI::Vector &u) const
  {
    Penetration here;
    if (!poses_now.empty())
      for (const auto &node : node_list)
      {
        Eigen::Vector3d x = node.reference_position;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] += u(node.dofs[c]);
        const Proximity p = nearest(x);
        if (p.body >= 0 && -p.gap > here.depth)
          here = {-p.gap, x};
      }
    const auto all =
        Utilities::MPI::all_gather(comm,
                                   std::array<double, 4>{{here.depth,
                                                          here.position[0],
                                                          here.position[1],
                                                          here.position[2]}});
    Penetration deepest;
    for (const auto &a : all)
      if (a[0] > deepest.depth)
        deepest = {a[0], Eigen::Vector3d(a[1], a[2], a[3])};
    return deepest;
  }

  template <int dim>
  std::pair<unsigned int, double> ContactSurface<dim>::overlap_summary(
      const std::vector<double> &overlaps) const
  {
    unsigned int inside  = 0;
    double       deepest = 0;
    for (const double depth : overlaps)
      if (depth > 0)
      {
        ++inside;
        deepest = std::max(deepest, depth);
      }
    return {Utilities::MPI::sum(inside, comm),
            Utilities::MPI::max(deepest, comm)};
  }

  template <int dim> void ContactSurface<dim>::set_time(const double time)
  {
    current_time = time;
  }

  template <int dim>
  void
  ContactSurface<dim>::place_bodies(const double                    time,
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
  Eigen::Matrix3d ContactSurface<dim>::normal_gradient(const Proximity       &p,
                                                       const Eigen::Vector3d &x,
                                                       const double h) const
  {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (unsigned int k = 0; k < dim; ++k)
    {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k]              = h;
      H.col(k)          = (normal_at(p, x + e) - normal_at(p, x - e)) / (2 * h);
    }
    return 0.5 * (H + H.transpose());
  }

  template <int dim>
  Eigen::Vector3d ContactSurface<dim>::normal_at(const Proximity       &p,
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
  typename ContactSurface<dim>::Proximity
  ContactSurface<dim>::nearest(const Eigen::Vector3d &x) const
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
  typename ContactSurface<dim>::Proximity ContactSurface<dim>::distance_to(
      const int body, const unsigned int geom, const Eigen::Vector3d &x) const
  {
    const Pose      &pose = poses_now[body][geom];
    const ShapeQuery q =
        bodies.bodies()[body].geoms()[geom].shape->query(pose.to_local(x));
    Proximity p;
    p.body   = body;
    p.geom   = geom;
    p.gap    = q.distance;
    p.normal = pose.rotate_to_world(q.normal);
    if (dim == 2)
    {
      p.normal[2] = 0;
      p.normal.normalize();
    }
    return p;
  }

  template <int dim>
  const std::vector<typename ContactSurface<dim>::Node> &
  ContactSurface<dim>::nodes() const
  {
    return node_list;
  }

  template <int dim>
  const RigidBodySet &ContactSurface<dim>::rigid_bodies() const
  {
    return bodies;
  }

  template <int dim>
  bool ContactSurface<dim>::is_slave_boundary(const types::boundary_id id) const
  {
    for (const auto s : parameters.slave_boundary_ids)
      if (s == id)
        return true;
    return false;
  }

  template <int dim> double ContactSurface<dim>::time() const
  {
    return current_time;
  }

  template <int dim> unsigned int ContactSurface<dim>::n_active() const
  {
    return active_count;
  }

  template <int dim> unsigned int ContactSurface<dim>::n_slip() const
  {
    return slip_count;
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
  template std::vector<double>
  ContactSurface<2>::node_overlaps(const double,
                                   const TrilinosWrappers::MPI::Vector &);
  template std::vector<double>
                               ContactSurface<3>::node_overlaps(const double,
                                   const TrilinosWrappers::MPI::Vector &);
  template std::vector<double> ContactSurface<2>::node_overlaps(
      const double, const LinearAlgebra::distributed::Vector<double> &);
  template std::vector<double> ContactSurface<3>::node_overlaps(
      const double, const LinearAlgebra::distributed::Vector<double> &);
} // namespace softgrasp
