// Where the incremental potential's contact terms live on the slave
// surface (PotentialContact's points and patches), and how the nodes report
// the forces of points between them.

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector_operation.h>
#include <softgrasp/contact/potential_contact.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim> void PotentialContact<dim>::make_node_points()
  {
    points.assign(node_list.size(), Point());
    patches.assign(node_list.size(), Patch());
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const Node &node  = node_list[j];
      Patch      &patch = patches[j];
      patch.dofs.assign(node.dofs.begin(), node.dofs.end());
      patch.free.assign(dim, true);
      patch.begin              = j;
      patch.end                = j + 1;
      Point &point             = points[j];
      point.patch              = j;
      point.shape              = {1.0};
      point.reference_position = node.reference_position;
      point.last_converged     = node.reference_position;
      point.weight             = node.reference_area;
      point.spacing = std::pow(node.reference_area, 1.0 / (dim - 1.0));
    }
  }

  template <int dim>
  void PotentialContact<dim>::make_face_points(const SolidSystem<dim> &system)
  {
    const unsigned int degree = std::max(1u, system.fe().degree);
    points.clear();
    patches.clear();
    for (const auto &face : this->slave_faces(system))
    {
      Patch patch;
      patch.dofs = face.dofs;
      patch.free.assign(patch.dofs.size(), true);
      patch.begin = points.size();
      double area = 0;
      for (const double w : face.weight)
        area += w;
      // the spacing of the face's nodes, as a node's in the node mode
      const double spacing = std::pow(area, 1.0 / (dim - 1.0)) / degree;
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        Point point;
        point.patch              = patches.size();
        point.shape              = face.shape[q];
        point.reference_position = face.position[q];
        point.last_converged     = point.reference_position;
        point.weight             = face.weight[q];
        point.spacing            = spacing;
        points.push_back(point);
      }
      patch.end = points.size();
      patches.push_back(patch);
    }
    for (auto *v :
         {&nodal_force, &nodal_slip, &nodal_weight, &nodal_change, &nodal_gap})
      v->reinit(system.locally_owned_dofs(),
                system.locally_relevant_dofs(),
                comm,
                true);
    for (auto *v : {&owned_multiplier,
                    &accepted_multiplier,
                    &polish_multiplier,
                    &projected_multiplier})
      v->reinit(system.locally_owned_dofs(), comm);
    for (auto *v : {&nodal_multiplier, &projected_ghosted})
      v->reinit(
          system.locally_owned_dofs(), system.locally_relevant_dofs(), comm);
  }

  template <int dim> void PotentialContact<dim>::set_penalties()
  {
    // k = factor * 2 mu_0 w / h (N/m; per metre of thickness in 2D): for a
    // node of area w = h^(dim-1), factor * 2 mu_0 h^(dim-2)
    force_floor = 0;
    for (Point &point : points)
    {
      point.penalty = parameters.penalty_factor * 2 * shear_modulus *
                      point.weight / point.spacing;
      force_floor = std::max(force_floor, point.penalty * point.spacing);
    }
    // a change of normal force below that of a gap change of 1e-8 of the
    // spacing is round-off (a body that only touches: forces of 1e-13 N
    // changing by 1e-15 N would never settle on a relative test)
    force_floor = 1e-8 * Utilities::MPI::max(force_floor, comm);
  }

  template <int dim>
  Eigen::Vector3d
  PotentialContact<dim>::position(const unsigned int                   i,
                                  const TrilinosWrappers::MPI::Vector &u) const
  {
    const Point    &point = points[i];
    const Patch    &patch = patches[point.patch];
    Eigen::Vector3d x     = point.reference_position;
    for (unsigned int k = 0; k < point.shape.size(); ++k)
      for (unsigned int c = 0; c < dim; ++c)
        x[c] += point.shape[k] * u[patch.dofs[k * dim + c]];
    return x;
  }

  template <int dim> void PotentialContact<dim>::gather_face_points()
  {
    // the force on node k is sum_q N_k(x_q) f_q; its slip the mean of its
    // closed points' slips, weighted by |N_k| w_q; it slips when most of
    // that weight does
    nodal_force  = 0;
    nodal_slip   = 0;
    nodal_weight = 0;
    for (const Patch &patch : patches)
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        const NodalPotential &p = points[i].potential;
        if (p.status == ContactStatus::inactive && p.force.isZero(0))
          continue;
        for (unsigned int k = 0; k < points[i].shape.size(); ++k)
        {
          const double N = points[i].shape[k];
          const double w = std::abs(N) * points[i].weight;
          for (unsigned int c = 0; c < dim; ++c)
          {
            nodal_force[patch.dofs[k * dim + c]] += N * p.force[c];
            nodal_slip[patch.dofs[k * dim + c]] += w * p.slip[c];
          }
          nodal_weight[patch.dofs[k * dim]] += w;
          if (p.status == ContactStatus::slip)
            nodal_weight[patch.dofs[k * dim + 1]] += w;
        }
      }
    for (auto *v : {&nodal_force, &nodal_slip, &nodal_weight})
      v->compress(VectorOperation::add);
  }

  template <int dim>
  void PotentialContact<dim>::update_nodes(const SolidSystem<dim> &system)
  {
    const auto &constraints = system.constraint_set();
    for (Patch &patch : patches)
      for (unsigned int r = 0; r < patch.dofs.size(); ++r)
        patch.free[r] = !constraints.is_constrained(patch.dofs[r]);
    for (Node &node : node_list)
      for (unsigned int c = 0; c < dim; ++c)
        node.free[c] = !constraints.is_constrained(node.dofs[c]);
    if (!parameters.integrate_on_faces)
    {
      for (unsigned int j = 0; j < node_list.size(); ++j)
      {
        Node            &node  = node_list[j];
        const Point     &point = points[j];
        const Proximity &p     = point.proximity;
        node.status            = point.potential.status;
        node.body              = p.body;
        node.geom              = p.geom;
        node.gap               = p.gap;
        node.normal = p.body >= 0 ? p.normal : Eigen::Vector3d::Zero();
        node.force  = point.potential.force;
        node.slip   = point.potential.slip;
      }
      return;
    }
    gather_face_points();
    // the geom and gap a node reports are those of its own position
    // (a node between two links reports its face points' forces to the
    // nearer one)
    const auto &u = system.ghosted_solution();
    for (Node &node : node_list)
    {
      Eigen::Vector3d x = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
      {
        x[c] += u[node.dofs[c]];
        node.force[c] = nodal_force[node.dofs[c]];
      }
      const double closed   = nodal_weight[node.dofs[0]];
      const double slipping = nodal_weight[node.dofs[1]];
      node.status           = !(closed > 0)           ? ContactStatus::inactive
                              : 2 * slipping > closed ? ContactStatus::slip
                                                      : ContactStatus::stick;
      node.slip.setZero();
      for (unsigned int c = 0; c < dim && closed > 0; ++c)
        node.slip[c] = nodal_slip[node.dofs[c]] / closed;
      const Proximity p = nearest(x);
      node.body         = p.body;
      node.geom         = p.geom;
      node.gap          = p.gap;
      node.normal       = p.body >= 0 ? p.normal : Eigen::Vector3d::Zero();
    }
  }

  template <int dim>
  std::array<double, 3> PotentialContact<dim>::nodal_settle_measures()
  {
    // per node, of nodal_change: sum_q N_k lambda_q and D_k = sum_q N_k w_q;
    // of nodal_gap: sum_q N_k w_q g_q
    nodal_change = 0;
    nodal_gap    = 0;
    for (const Patch &patch : patches)
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        const Point &point = points[i];
        double       gap   = std::min(point.nearest_gap, point.spacing);
        if (point.proximity.body >= 0)
          gap = std::min(gap, point.proximity.gap);
        for (unsigned int k = 0; k < point.shape.size(); ++k)
        {
          const double N = point.shape[k];
          nodal_change[patch.dofs[k * dim]] += N * point.potential.normal_force;
          nodal_change[patch.dofs[k * dim + 1]] += N * point.weight;
          nodal_gap[patch.dofs[k * dim]] += N * point.weight * gap;
        }
      }
    nodal_change.compress(VectorOperation::add);
    nodal_gap.compress(VectorOperation::add);
    // Lambda_k = max(0, sum_q N_k lambda_q / D_k) against the multiplier of
    // the solve, as forces D_k Lambda_k
    double change = 0, largest = 0, penetration = 0;
    projected_multiplier = 0;
    for (const Node &node : node_list)
    {
      const double area    = nodal_change[node.dofs[1]];
      const double spacing = std::pow(node.reference_area, 1.0 / (dim - 1.0));
      if (!(area > 0))
        continue;
      const double Lambda =
          std::max(0.0, nodal_change[node.dofs[0]] / area); // Pa
      projected_multiplier[node.dofs[0]] = Lambda;
      change                             = std::max(
          change, area * std::abs(Lambda - owned_multiplier[node.dofs[0]]));
      largest = std::max(largest, area * Lambda);
      penetration =
          std::max(penetration, -nodal_gap[node.dofs[0]] / area / spacing);
    }
    projected_multiplier.compress(VectorOperation::insert);
    return {{Utilities::MPI::max(change, comm),
             Utilities::MPI::max(largest, comm),
             Utilities::MPI::max(penetration, comm)}};
  }

  template <int dim>
  double PotentialContact<dim>::point_pressure(
      const Point &point, const TrilinosWrappers::MPI::Vector &nodal) const
  {
    const Patch &patch    = patches[point.patch];
    double       pressure = 0;
    for (unsigned int k = 0; k < point.shape.size(); ++k)
      pressure += point.shape[k] * nodal[patch.dofs[k * dim]];
    return pressure;
  }

  template <int dim> void PotentialContact<dim>::project_multipliers()
  {
    owned_multiplier = projected_multiplier;
    nodal_multiplier = owned_multiplier;
    for (const Patch &patch : patches)
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        Point       &point    = points[i];
        const double pressure = point_pressure(point, nodal_multiplier);
        // friction against the same smooth pressure: the points' own
        // forces flip where their gap is near zero
        lag_at(point, std::max(0.0, pressure) * point.weight);
      }
  }

  template <int dim>
  double
  PotentialContact<dim>::polish_on_faces(const TrilinosWrappers::MPI::Vector &u)
  {
    // the pressure Lambda_k(x) = max(0, sum_q N_k lambda_q(x) / D_k)
    // projected from the points' current forces, as the settle test
    // measures Coulomb's law against it; the points' friction again with
    // that bound. Its derivative through the projection, which couples the
    // points of neighbouring faces, is left out of the Hessian: Newton's
    // method with backtracking on the residual still converges where the
    // friction's own stiffness dominates.
    nodal_settle_measures();
    projected_ghosted = projected_multiplier;
    double energy     = 0;
    for (const Patch &patch : patches)
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        Point              &point    = points[i];
        const double        pressure = point_pressure(point, projected_ghosted);
        NodalPotentialInput in =
            potential_input(i, position(i, u), point.proximity);
        in.lagged_normal_force = std::max(0.0, pressure) * point.weight;
        point.potential        = evaluate_nodal_potential(in);
        energy += point.potential.energy;
      }
    return energy;
  }

  template <int dim> double PotentialContact<dim>::coulomb_excess_on_faces()
  {
    projected_ghosted   = projected_multiplier;
    const double mu     = parameters.friction_coefficient;
    double       beyond = 0, largest = 0;
    for (const Patch &patch : patches)
      for (unsigned int i = patch.begin; i < patch.end; ++i)
      {
        const Point &point        = points[i];
        const double pressure     = point_pressure(point, projected_ghosted);
        const double normal_force = std::max(0.0, pressure) * point.weight;
        largest                   = std::max(largest, normal_force);
        beyond                    = std::max(beyond,
                          point.potential.friction.norm() - mu * normal_force);
      }
    beyond  = Utilities::MPI::max(beyond, comm);
    largest = Utilities::MPI::max(largest, comm);
    return mu * largest > 0 ? std::max(0.0, beyond) / (mu * largest) : 0;
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  PotentialContact<dim>::count_points() const
  {
    unsigned int closed = 0;
    for (const Point &point : points)
      closed += point.potential.normal_force > 0;
    return {Utilities::MPI::sum<unsigned int>(points.size(), comm),
            Utilities::MPI::sum(closed, comm)};
  }

  // the members defined here (PotentialContact itself is instantiated in
  // potential_contact.cc)
#define SOFTGRASP_INSTANTIATE(dim)                                             \
  template void PotentialContact<dim>::make_node_points();                     \
  template void PotentialContact<dim>::make_face_points(                       \
      const SolidSystem<dim> &);                                               \
  template void            PotentialContact<dim>::set_penalties();             \
  template Eigen::Vector3d PotentialContact<dim>::position(                    \
      const unsigned int, const TrilinosWrappers::MPI::Vector &) const;        \
  template void PotentialContact<dim>::update_nodes(const SolidSystem<dim> &); \
  template void PotentialContact<dim>::gather_face_points();                   \
  template std::pair<unsigned int, unsigned int>                               \
  PotentialContact<dim>::count_points() const;                                 \
  template std::array<double, 3>                                               \
                  PotentialContact<dim>::nodal_settle_measures();              \
  template void   PotentialContact<dim>::project_multipliers();                \
  template double PotentialContact<dim>::coulomb_excess_on_faces();            \
  template double PotentialContact<dim>::polish_on_faces(                      \
      const TrilinosWrappers::MPI::Vector &);                                  \
  template double PotentialContact<dim>::point_pressure(                       \
      const Point &, const TrilinosWrappers::MPI::Vector &) const;
  SOFTGRASP_INSTANTIATE(2)
  SOFTGRASP_INSTANTIATE(3)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
