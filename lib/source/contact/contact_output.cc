#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <softgrasp/contact/contact_output.h>

namespace softgrasp
{
  using namespace dealii;

  std::vector<LateralForceDrop>
  lateral_force_drops(const ContactForceRecord &before,
                      const ContactForceRecord &after,
                      const double              threshold)
  {
    std::vector<LateralForceDrop> drops;
    for (unsigned int b = 0;
         b < std::min(before.forces.size(), after.forces.size());
         ++b)
      for (unsigned int g = 0;
           g < std::min(before.forces[b].size(), after.forces[b].size());
           ++g)
      {
        const GeomContactForce &f0 = before.forces[b][g];
        LateralForceDrop        drop;
        drop.body   = b;
        drop.geom   = g;
        drop.before = f0.lateral_part.norm();
        drop.after  = after.forces[b][g].lateral_part.norm();
        if (drop.before > 0.05 * std::abs(f0.normal_force()) &&
            drop.fraction() > threshold)
          drops.push_back(drop);
      }
    return drops;
  }

  std::pair<Eigen::Vector3d, Eigen::Vector3d>
  body_resultant(const RigidBody                     &body,
                 const std::vector<GeomContactForce> &forces,
                 const double                         time)
  {
    const Pose      body_pose = body.trajectory().pose(time);
    Eigen::Vector3d total     = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque    = Eigen::Vector3d::Zero();
    for (unsigned int g = 0; g < forces.size(); ++g)
    {
      const Pose geom = body.geom_pose(g, time);
      total += forces[g].force;
      torque += forces[g].moment +
                (geom.position - body_pose.position).cross(forces[g].force);
    }
    return {total, torque};
  }

  template <int dim>
  ContactOutput<dim>::ContactOutput(const ContactSurface<dim> &contact)
      : contact(contact)
  {
  }

  template <int dim>
  void ContactOutput<dim>::setup(const SolidSystem<dim> &system)
  {
    const auto &fe = system.fe();
    scalar_fe      = std::make_unique<FE_Q<dim>>(fe.degree);
    scalar_dofs    = std::make_unique<DoFHandler<dim>>(
        system.dof_handler().get_triangulation());
    scalar_dofs->distribute_dofs(*scalar_fe);

    // Scalar dof k of a cell sits where the vector element's component-0
    // dof of support point k sits.
    std::map<types::global_dof_index, types::global_dof_index> to_scalar;
    std::vector<types::global_dof_index> vector_indices(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> indices(scalar_fe->n_dofs_per_cell());
    auto scalar_cell = scalar_dofs->begin_active();
    for (const auto &cell : system.dof_handler().active_cell_iterators())
    {
      if (cell->is_locally_owned())
      {
        cell->get_dof_indices(vector_indices);
        scalar_cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto [c, k] = fe.system_to_component_index(i);
          if (c == 0)
            to_scalar[vector_indices[i]] = indices[k];
        }
      }
      ++scalar_cell;
    }
    scalar_index.clear();
    for (const auto &node : contact.nodes())
      scalar_index.push_back(to_scalar.at(node.dofs[0]));

    const IndexSet owned = scalar_dofs->locally_owned_dofs();
    const IndexSet relevant =
        DoFTools::extract_locally_relevant_dofs(*scalar_dofs);
    const MPI_Comm comm = system.communicator();
    for (auto *v : {&pressure, &gap, &status})
      v->reinit(owned, relevant, comm);
    traction.reinit(
        system.locally_owned_dofs(), system.locally_relevant_dofs(), comm);
  }

  template <int dim>
  std::vector<double>
  ContactOutput<dim>::current_areas(const SolidSystem<dim> &system) const
  {
    const auto                   &fe   = system.fe();
    const MPI_Comm                comm = system.communicator();
    TrilinosWrappers::MPI::Vector area;
    area.reinit(system.locally_owned_dofs(),
                system.locally_relevant_dofs(),
                comm,
                true);
    FEFaceValues<dim>                    face_values(system.mapping(),
                                  fe,
                                  QGauss<dim - 1>(fe.degree + 1),
                                  update_values | update_gradients |
                                      update_normal_vectors |
                                      update_JxW_values);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    std::vector<Tensor<2, dim>>      grad_u(face_values.n_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact.is_slave_boundary(cell->face(f)->boundary_id()))
          {
            face_values.reinit(cell, f);
            cell->get_dof_indices(indices);
            face_values[displacement].get_function_gradients(
                system.ghosted_solution(), grad_u);
            for (const auto q : face_values.quadrature_point_indices())
            {
              // Nanson: da = J |F^-T N| dA
              Tensor<2, dim> F = unit_symmetric_tensor<dim>();
              F += grad_u[q];
              const double stretch =
                  determinant(F) *
                  (transpose(invert(F)) * face_values.normal_vector(q)).norm();
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.system_to_component_index(i).first == 0)
                  area[indices[i]] += face_values.shape_value(i, q) * stretch *
                                      face_values.JxW(q);
            }
          }
    area.compress(VectorOperation::add);
    std::vector<double> result;
    for (const auto &node : contact.nodes())
      result.push_back(area[node.dofs[0]]);
    return result;
  }

  template <int dim>
  std::vector<std::vector<GeomContactForce>>
  ContactOutput<dim>::geom_forces(const SolidSystem<dim> &system) const
  {
    const auto                                &set    = contact.rigid_bodies();
    const auto                                &bodies = set.bodies();
    const auto                                 areas  = current_areas(system);
    const auto                                &nodes  = contact.nodes();
    const auto                                &u = system.ghosted_solution();
    std::vector<std::vector<GeomContactForce>> result(bodies.size());
    const auto &constraints = system.constraint_set();
    // per geom: the area-weighted normal sum of its patch, and which
    // symmetry planes (normal along axis c) its closed nodes touch
    std::vector<std::vector<Eigen::Vector3d>> mean_normal(bodies.size());
    std::vector<std::vector<Eigen::Vector3d>> symmetry(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      result[b].resize(bodies[b].geoms().size());
      mean_normal[b].assign(bodies[b].geoms().size(), Eigen::Vector3d::Zero());
      symmetry[b].assign(bodies[b].geoms().size(), Eigen::Vector3d::Zero());
    }
    for (unsigned int j = 0; j < nodes.size(); ++j)
    {
      const auto &node = nodes[j];
      if (node.status == ContactStatus::inactive || node.body < 0)
        continue;
      auto      &out  = result[node.body][node.geom];
      const Pose pose = bodies[node.body].geom_pose(node.geom, contact.time());
      Eigen::Vector3d x = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
        x[c] += u[node.dofs[c]];
      const Eigen::Vector3d on_geom = -node.force;
      out.force += on_geom;
      out.moment += (x - pose.position).cross(on_geom);
      out.friction += on_geom - node.normal * node.normal.dot(on_geom);
      out.nodal_normal += std::abs(node.normal.dot(on_geom));
      out.area += areas[j];
      ++out.active;
      if (node.status == ContactStatus::slip)
        ++out.slipping;
      mean_normal[node.body][node.geom] += areas[j] * node.normal;
      // a node with exactly one fixed component lies on a symmetry plane
      unsigned int fixed = 0, axis = 0;
      for (unsigned int c = 0; c < dim; ++c)
        if (constraints.is_constrained(node.dofs[c]))
        {
          ++fixed;
          axis = c;
        }
      if (fixed == 1)
        symmetry[node.body][node.geom][axis] = 1;
    }
    const MPI_Comm comm = system.communicator();
    const auto     sum  = [&](Eigen::Vector3d &v)
    {
      Tensor<1, 3> a({v[0], v[1], v[2]});
      a = Utilities::MPI::sum(a, comm);
      v = Eigen::Vector3d(a[0], a[1], a[2]);
    };
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (unsigned int g = 0; g < result[b].size(); ++g)
      {
        auto &out = result[b][g];
        sum(out.force);
        sum(out.moment);
        sum(out.friction);
        sum(mean_normal[b][g]);
        sum(symmetry[b][g]);
        out.nodal_normal = Utilities::MPI::sum(out.nodal_normal, comm);
        out.area         = Utilities::MPI::sum(out.area, comm);
        out.active       = Utilities::MPI::sum(out.active, comm);
        out.slipping     = Utilities::MPI::sum(out.slipping, comm);
        out.normal =
            reference_direction(b, g, mean_normal[b][g], symmetry[b][g]);
        out.normal_part  = out.normal * out.normal.dot(out.force);
        out.lateral_part = out.force - out.normal_part;
      }
    return result;
  }

  template <int dim>
  Eigen::Vector3d ContactOutput<dim>::reference_direction(
      const unsigned int     b,
      const unsigned int     g,
      const Eigen::Vector3d &normal_sum,
      const Eigen::Vector3d &symmetry_planes) const
  {
    const auto &choice = contact.rigid_bodies().reference_normal(b, g);
    switch (choice.kind)
    {
    case ReferenceNormal::Kind::world:
      return choice.direction;
    case ReferenceNormal::Kind::geom_frame:
      return contact.rigid_bodies()
                 .bodies()[b]
                 .geom_pose(g, contact.time())
                 .orientation *
             choice.direction;
    case ReferenceNormal::Kind::patch_mean:
      break;
    }
    // The mirror images of the patch across the symmetry planes it touches
    // cancel the normal sum's components across those planes.
    Eigen::Vector3d mean = normal_sum;
    for (unsigned int c = 0; c < 3; ++c)
      if (symmetry_planes[c] > 0)
        mean[c] = 0;
    if (mean.norm() > 1e-12 * normal_sum.norm() && mean.norm() > 0)
      return mean.normalized();
    return normal_sum.norm() > 0 ? Eigen::Vector3d(normal_sum.normalized())
                                 : Eigen::Vector3d::Zero();
  }

  template <int dim>
  std::vector<std::string> ContactOutput<dim>::history_columns() const
  {
    std::vector<std::string> columns;
    const char              *axes[] = {"x", "y", "z"};
    const auto              &set    = contact.rigid_bodies();
    const auto vector = [&](const std::string &prefix, const std::string &name)
    {
      for (const char *axis : axes)
        columns.push_back(prefix + name + "_" + axis);
    };
    for (unsigned int b = 0; b < set.bodies().size(); ++b)
    {
      for (unsigned int g = 0; g < set.bodies()[b].geoms().size(); ++g)
      {
        const std::string p = set.geom_label(b, g) + ":";
        vector(p, "F");
        vector(p, "M");
        vector(p, "n");
        vector(p, "F_n");
        vector(p, "F_mu");
        vector(p, "F_friction");
        for (const char *name : {"normal_force",
                                 "lateral_force",
                                 "friction_force",
                                 "area",
                                 "active_nodes",
                                 "slip_nodes"})
          columns.push_back(p + name);
      }
      vector(set.bodies()[b].name() + ":", "F");
      vector(set.bodies()[b].name() + ":", "M");
    }
    return columns;
  }

  template <int dim>
  std::vector<double>
  ContactOutput<dim>::history_values(const SolidSystem<dim> &system) const
  {
    return history_values(geom_forces(system));
  }

  template <int dim>
  std::vector<double> ContactOutput<dim>::history_values(
      const std::vector<std::vector<GeomContactForce>> &forces) const
  {
    const auto         &bodies = contact.rigid_bodies().bodies();
    std::vector<double> row;
    const auto          vector = [&](const Eigen::Vector3d &v) {
      row.insert(row.end(), {v[0], v[1], v[2]});
    };
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      for (unsigned int g = 0; g < forces[b].size(); ++g)
      {
        const auto &f = forces[b][g];
        vector(f.force);
        vector(f.moment);
        vector(f.normal);
        vector(f.normal_part);
        vector(f.lateral_part);
        vector(f.friction);
        // normal force: positive when the tissue pushes the geom inwards
        row.push_back(f.normal_force());
        row.push_back(f.lateral_part.norm());
        row.push_back(f.friction.norm());
        row.push_back(f.area);
        row.push_back(f.active);
        row.push_back(f.slipping);
      }
      const auto [total, torque] =
          body_resultant(bodies[b], forces[b], contact.time());
      vector(total);
      vector(torque);
    }
    return row;
  }

  template <int dim>
  void ContactOutput<dim>::add_fields(const SolidSystem<dim> &system,
                                      DataOut<dim>           &data_out)
  {
    const auto                    areas = current_areas(system);
    const auto                   &nodes = contact.nodes();
    TrilinosWrappers::MPI::Vector t(system.locally_owned_dofs(),
                                    system.communicator());
    TrilinosWrappers::MPI::Vector p(scalar_dofs->locally_owned_dofs(),
                                    system.communicator());
    TrilinosWrappers::MPI::Vector g(p), s(p);
    for (unsigned int j = 0; j < nodes.size(); ++j)
    {
      const auto           &node   = nodes[j];
      const bool            closed = node.status != ContactStatus::inactive;
      const Eigen::Vector3d traction_j =
          closed ? Eigen::Vector3d(node.force / areas[j])
                 : Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < dim; ++c)
        t[node.dofs[c]] = traction_j[c];
      p[scalar_index[j]] = contact_pressure(node, areas[j]);
      g[scalar_index[j]] = std::isfinite(node.gap) ? node.gap : 0.0;
      s[scalar_index[j]] = static_cast<double>(node.status);
    }
    for (auto *v : {&t, &p, &g, &s})
      v->compress(VectorOperation::insert);
    traction = t;
    pressure = p;
    gap      = g;
    status   = s;
    data_out.add_data_vector(
        system.dof_handler(),
        traction,
        std::vector<std::string>(dim, "contact_traction"),
        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(*scalar_dofs, pressure, "contact_pressure");
    data_out.add_data_vector(*scalar_dofs, gap, "contact_gap");
    data_out.add_data_vector(*scalar_dofs, status, "contact_status");
  }

  template class ContactOutput<2>;
  template class ContactOutput<3>;

  std::vector<double> ContactForceRecord::pack() const
  {
    std::vector<double> data = {double(step), time, double(forces.size())};
    for (const auto &body : forces)
    {
      data.push_back(body.size());
      for (const auto &f : body)
      {
        for (const Eigen::Vector3d *v : {&f.force,
                                         &f.moment,
                                         &f.normal,
                                         &f.normal_part,
                                         &f.lateral_part,
                                         &f.friction})
          data.insert(data.end(), v->data(), v->data() + 3);
        data.insert(
            data.end(),
            {f.nodal_normal, f.area, double(f.active), double(f.slipping)});
      }
    }
    return data;
  }

  ContactForceRecord ContactForceRecord::unpack(const std::vector<double> &data)
  {
    std::size_t i    = 0;
    const auto  next = [&]()
    {
      if (i >= data.size())
        throw std::runtime_error("A packed contact force record is "
                                 "truncated.");
      return data[i++];
    };
    ContactForceRecord r;
    r.step = static_cast<unsigned int>(next());
    r.time = next();
    r.forces.resize(static_cast<std::size_t>(next()));
    for (auto &body : r.forces)
    {
      body.resize(static_cast<std::size_t>(next()));
      for (auto &f : body)
      {
        for (Eigen::Vector3d *v : {&f.force,
                                   &f.moment,
                                   &f.normal,
                                   &f.normal_part,
                                   &f.lateral_part,
                                   &f.friction})
          for (unsigned int d = 0; d < 3; ++d)
            (*v)[d] = next();
        f.nodal_normal = next();
        f.area         = next();
        f.active       = static_cast<unsigned int>(next());
        f.slipping     = static_cast<unsigned int>(next());
      }
    }
    return r;
  }
} // namespace softgrasp
