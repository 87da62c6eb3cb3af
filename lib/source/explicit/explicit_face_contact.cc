// The explicit solver's contact on the slave faces ('Contact/Potential
// integration = faces'): dual mortar weighted gaps, nodal pressures by
// projected Jacobi sweeps, node-wise Coulomb friction (ExplicitContact).

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector_operation.h>
#include <softgrasp/explicit/explicit_contact.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void ExplicitContact<dim>::report_nearest(Node             &node,
                                            const VectorType &u) const
  {
    Eigen::Vector3d x = node.reference_position;
    for (unsigned int c = 0; c < dim; ++c)
      x[c] += u(node.dofs[c]);
    const Proximity p = this->nearest(x);
    node.body         = p.body;
    node.geom         = p.geom;
    node.normal       = p.body >= 0 ? p.normal : Eigen::Vector3d::Zero();
  }

  template <int dim>
  void ExplicitContact<dim>::weighted_gaps(const VectorType &u)
  {
    weighted_gap = 0;
    for (auto &dual_face : faces)
    {
      const auto        &face = dual_face.face;
      const unsigned int n    = face.dofs.size() / dim;
      // b_l = sum_q w_q N_l g_q, then G_k = sum_l A_kl b_l
      std::vector<double> b(n, 0.0);
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        Eigen::Vector3d x = face.position[q];
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < dim; ++c)
            x[c] += face.shape[q][k] * u(face.dofs[k * dim + c]);
        const Proximity p = this->nearest(x);
        // far points (or none near) count as a gap of the body's size
        dual_face.gap[q]    = p.body >= 0 ? std::min(p.gap, gap_cap) : gap_cap;
        dual_face.normal[q] = p.body >= 0 ? p.normal : Eigen::Vector3d::Zero();
        for (unsigned int k = 0; k < n; ++k)
          b[k] += face.weight[q] * face.shape[q][k] * dual_face.gap[q];
      }
      for (unsigned int k = 0; k < n; ++k)
      {
        double g = 0;
        for (unsigned int l = 0; l < n; ++l)
          g += dual_face.dual(k, l) * b[l];
        weighted_gap(face.dofs[k * dim]) += g;
      }
    }
    weighted_gap.compress(VectorOperation::add);
  }

  template <int dim> void ExplicitContact<dim>::normal_forces()
  {
    face_force = 0;
    for (const auto &dual_face : faces)
    {
      const auto        &face = dual_face.face;
      const unsigned int n    = face.dofs.size() / dim;
      // the traction t_q = sum_k psi_k(q) Lambda_k = sum_l N_l (A^T Lambda)_l
      std::vector<double> s(n, 0.0);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = 0; l < n; ++l)
          s[l] += dual_face.dual(k, l) * multiplier(face.dofs[k * dim]);
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        double t = 0;
        for (unsigned int l = 0; l < n; ++l)
          t += face.shape[q][l] * s[l];
        if (t == 0)
          continue;
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < dim; ++c)
            face_force(face.dofs[k * dim + c]) +=
                face.weight[q] * face.shape[q][k] * t * dual_face.normal[q][c];
      }
    }
    face_force.compress(VectorOperation::add);
  }

  template <int dim>
  typename ExplicitContact<dim>::FaceStep
  ExplicitContact<dim>::begin_face_step(const double      dt,
                                        const double      h,
                                        const VectorType &mass,
                                        const VectorType &u_old,
                                        const double      left,
                                        const VectorType &u)
  {
    const unsigned int n = node_list.size();
    FaceStep           step;
    step.x_pred.assign(n, Eigen::Vector3d::Zero());
    step.mask.assign(n, Eigen::Vector3d::Zero());
    step.compliance.assign(n, 0.0);
    step.target.assign(n, 0.0);
    step.near.assign(n, Proximity());
    for (unsigned int j = 0; j < n; ++j)
    {
      auto &node     = node_list[j];
      step.x_pred[j] = node.last_converged = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
      {
        step.x_pred[j][c] += u(node.dofs[c]);
        node.last_converged[c] += u_old(node.dofs[c]);
        if (node.free[c])
        {
          step.mask[j][c]    = 1;
          step.compliance[j] = dt * h / mass(node.dofs[c]);
        }
      }
      // G_k >= -(allowed overlap) D_k
      step.target[j] = -(allowance.empty() ? 0.0 : left * allowance[j]) *
                       node.reference_area;
      node.status = ContactStatus::inactive;
      node.force.setZero();
      node.slip.setZero();
    }
    return step;
  }

  template <int dim>
  bool ExplicitContact<dim>::pressures_settled(const FaceStep &step) const
  {
    // the complementarity residual (m): |G_k - target| / D_k where
    // pressed, the overlap beyond the target where not
    double residual = 0, pressed = 0;
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const auto  &node = node_list[j];
      const double g    = weighted_gap(node.dofs[0]) - step.target[j];
      const double lam  = multiplier(node.dofs[0]);
      residual          = std::max(residual,
                          (lam > 0 ? std::abs(g) : std::max(0.0, -g)) /
                              node.reference_area);
      pressed           = std::max(pressed, lam);
    }
    residual = Utilities::MPI::max(residual, comm);
    pressed  = Utilities::MPI::max(pressed, comm);
    return residual <= 1e-9 * gap_cap && (sweeps > 0 || pressed == 0);
  }

  template <int dim>
  void ExplicitContact<dim>::update_pressures(FaceStep         &step,
                                              const VectorType &u)
  {
    // the Jacobi update: dG_k/dLambda_k = D_k^2 (dt h / m_k) (n.n)_free
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      const auto     &node = node_list[j];
      Eigen::Vector3d x    = node.reference_position;
      for (unsigned int c = 0; c < dim; ++c)
        x[c] += u(node.dofs[c]);
      const Proximity &near = step.near[j] = this->nearest(x);
      const double     along =
          near.normal.dot(near.normal.cwiseProduct(step.mask[j]));
      double &lam = multiplier(node.dofs[0]);
      if (near.body < 0 || step.compliance[j] == 0 || along < 1e-6)
      {
        lam = 0;
        continue;
      }
      const double D = node.reference_area;
      lam            = std::max(0.0,
                     lam - (weighted_gap(node.dofs[0]) - step.target[j]) /
                               (step.compliance[j] * D * D * along));
    }
    multiplier.update_ghost_values();
  }

  template <int dim>
  void ExplicitContact<dim>::move_face_nodes(const FaceStep &step,
                                             VectorType     &u)
  {
    // the normal forces, then Coulomb friction that holds each node at the
    // surface point of t^n, carried by the body
    const double mu = parameters.friction_coefficient;
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      auto           &node = node_list[j];
      const auto     &near = step.near[j];
      Eigen::Vector3d f_n  = Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < dim; ++c)
        f_n[c] = step.mask[j][c] * face_force(node.dofs[c]);
      const double    c_j = step.compliance[j];
      Eigen::Vector3d x   = step.x_pred[j] + c_j * f_n;
      Eigen::Vector3d d   = Eigen::Vector3d::Zero();
      node.status         = ContactStatus::inactive;
      if (near.body >= 0 && c_j > 0 && f_n.norm() > 0)
      {
        const Pose &now = poses_now[near.body][near.geom];
        const Pose &old = poses_old[near.body][near.geom];
        node.slip       = x - now.to_world(old.to_local(node.last_converged));
        const Eigen::Vector3d &normal = near.normal;
        d = -(node.slip - normal * normal.dot(node.slip))
                 .cwiseProduct(step.mask[j]);
        node.status = ContactStatus::stick;
        if (mu == 0)
        {
          d.setZero();
          node.status = ContactStatus::slip;
        }
        else if (d.norm() > mu * f_n.norm() * c_j)
        {
          d *= mu * f_n.norm() * c_j / d.norm();
          node.status = ContactStatus::slip;
        }
        x += d;
        node.slip += d;
        node.slip -= normal * normal.dot(node.slip);
      }
      node.force = c_j > 0 ? Eigen::Vector3d(f_n + d / c_j) : f_n;
      for (unsigned int c = 0; c < dim; ++c)
        if (node.free[c])
          u(node.dofs[c]) = x[c] - node.reference_position[c];
    }
    u.update_ghost_values();
  }

  template <int dim>
  void ExplicitContact<dim>::enforce_on_faces(const double      dt,
                                              const double      h,
                                              const VectorType &mass,
                                              const VectorType &u_old,
                                              const double      left,
                                              VectorType       &u)
  {
    if (weighted_gap.size() != u.size())
    {
      for (auto *v : {&weighted_gap, &multiplier, &face_force})
        v->reinit(u);
      multiplier = 0; // later steps start from the last step's pressures
    }
    FaceStep step = begin_face_step(dt, h, mass, u_old, left, u);
    // the faces read the nodes of other ranks; the integrator's vector
    // leaves in the ghost state it came in (its matrix-free loops trust
    // ghost values of a ghosted vector)
    const bool was_ghosted = u.has_ghost_elements();
    u.update_ghost_values();
    for (sweeps = 0;; ++sweeps)
    {
      weighted_gaps(u);
      if (pressures_settled(step) || sweeps == max_sweeps)
        break;
      update_pressures(step, u);
      normal_forces();
      move_face_nodes(step, u);
    }
    // the nodes' report: weighted gap, nearest geom and normal, counts
    unsigned int active = 0, slipping = 0;
    double       worst = 0;
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      auto &node = node_list[j];
      report_nearest(node, u);
      node.gap = weighted_gap(node.dofs[0]) / node.reference_area;
      worst    = std::max(worst,
                       (step.target[j] - weighted_gap(node.dofs[0])) /
                           node.reference_area);
      if (!(multiplier(node.dofs[0]) > 0))
        node.status = ContactStatus::inactive;
      active += node.status != ContactStatus::inactive;
      slipping += node.status == ContactStatus::slip;
    }
    if (!was_ghosted)
      u.zero_out_ghost_values();
    double counts[2] = {double(active), double(slipping)};
    Utilities::MPI::sum(counts, comm, counts);
    this->active_count = static_cast<unsigned int>(counts[0]);
    this->slip_count   = static_cast<unsigned int>(counts[1]);
    penetration        = Utilities::MPI::max(worst, comm);
  }

#define SOFTGRASP_INSTANTIATE(dim)                                             \
  template void ExplicitContact<dim>::weighted_gaps(const VectorType &);       \
  template void ExplicitContact<dim>::normal_forces();                         \
  template void ExplicitContact<dim>::report_nearest(                          \
      Node &, const VectorType &) const;                                       \
  template typename ExplicitContact<dim>::FaceStep                             \
                ExplicitContact<dim>::begin_face_step(const double,            \
                                        const double,            \
                                        const VectorType &,      \
                                        const VectorType &,      \
                                        const double,            \
                                        const VectorType &);     \
  template bool ExplicitContact<dim>::pressures_settled(const FaceStep &)      \
      const;                                                                   \
  template void ExplicitContact<dim>::update_pressures(FaceStep &,             \
                                                       const VectorType &);    \
  template void ExplicitContact<dim>::move_face_nodes(const FaceStep &,        \
                                                      VectorType &);           \
  template void ExplicitContact<dim>::enforce_on_faces(const double,           \
                                                       const double,           \
                                                       const VectorType &,     \
                                                       const VectorType &,     \
                                                       const double,           \
                                                       VectorType &);
  SOFTGRASP_INSTANTIATE(2)
  SOFTGRASP_INSTANTIATE(3)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
