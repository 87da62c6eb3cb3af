// The explicit solver's contact on the slave faces with the implicit
// solvers' face potential ('Contact/Explicit faces = potential'): each step
// minimises the slave nodes' lumped-mass inertia plus the potential of the
// faces' Gauss points (ExplicitContact).

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/explicit/explicit_contact.h>
#include <unordered_map>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void
  ExplicitContact<dim>::setup_face_potential(const SolidSystem<dim> &system)
  {
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
          "'Contact/Explicit faces = potential' solves the slave surface's "
          "correction with a direct solver on one MPI rank, and this run has " +
          std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
          ". Fix: run the explicit integrator on one rank, or use "
          "'Explicit faces = dual mortar' or 'Potential integration = nodes' "
          "(or 'automatic'), which run on any number of ranks.");
    degree = std::max(1u, system.fe().degree);
    // the columns of the Newton system: the free dofs of the slave nodes
    std::unordered_map<types::global_dof_index, int> column_of;
    n_columns = 0;
    node_column.assign(node_list.size(), {{-1, -1, -1}});
    for (unsigned int j = 0; j < node_list.size(); ++j)
      for (unsigned int c = 0; c < dim; ++c)
        if (node_list[j].free[c])
        {
          node_column[j][c]               = n_columns;
          column_of[node_list[j].dofs[c]] = n_columns++;
        }
    force_scale      = 0;
    smallest_spacing = gap_cap;
    for (auto &contact_face : faces)
    {
      const auto &face = contact_face.face;
      for (const auto dof : face.dofs)
      {
        const auto found = column_of.find(dof);
        contact_face.column.push_back(found == column_of.end() ? -1
                                                               : found->second);
      }
      double area = 0;
      for (const double w : face.weight)
        area += w;
      // k = factor 2 mu_0 w / h, h the spacing of the face's nodes (as the
      // implicit solvers' face points)
      const double spacing = std::pow(area, 1.0 / (dim - 1.0)) / degree;
      smallest_spacing     = std::min(smallest_spacing, spacing);
      contact_face.points.assign(face.weight.size(), FacePoint());
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        FacePoint &point = contact_face.points[q];
        point.penalty    = parameters.penalty_factor * 2 * shear_modulus *
                        face.weight[q] / spacing;
        point.last  = face.position[q];
        force_scale = std::max(force_scale, point.penalty * spacing);
      }
    }
    correction.setZero(n_columns);
  }

  template <int dim>
  double ExplicitContact<dim>::face_potential(
      const VectorType                    &u,
      const double                         eps,
      Eigen::VectorXd                     *gradient,
      std::vector<Eigen::Triplet<double>> *hessian)
  {
    double energy = 0;
    for (auto &contact_face : faces)
    {
      const auto        &face = contact_face.face;
      const unsigned int n    = face.dofs.size() / dim;
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        const auto     &N     = face.shape[q];
        FacePoint      &point = contact_face.points[q];
        Eigen::Vector3d x     = face.position[q];
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < dim; ++c)
            x[c] += N[k] * u(face.dofs[k * dim + c]);
        const Proximity     p = this->nearest(x);
        NodalPotentialInput in;
        in.gap            = p.body >= 0 ? p.gap : 1e300;
        in.n              = p.body >= 0 ? p.normal : Eigen::Vector3d::UnitZ();
        in.multiplier     = point.multiplier;
        in.penalty        = point.penalty;
        in.mu             = parameters.friction_coefficient;
        in.slip_tolerance = eps;
        in.lagged_normal_force = point.normal_force;
        if (point.body >= 0 && point.normal_force > 0)
        {
          in.T = tangent_basis(point.lag_normal, dim);
          // the motion relative to the rigid material point of t^n
          const Pose &now = poses_now[point.body][point.geom];
          const Pose &old = poses_old[point.body][point.geom];
          in.w            = x - now.to_world(old.to_local(point.last));
          if (dim == 2)
            in.w[2] = 0;
        }
        point.potential     = evaluate_nodal_potential(in);
        point.x             = x;
        point.near_body     = p.body;
        point.near_geom     = p.geom;
        contact_face.gap[q] = p.body >= 0 ? std::min(p.gap, gap_cap) : gap_cap;
        contact_face.normal[q] = in.n;
        energy += point.potential.energy;
        if (gradient == nullptr || (point.potential.hessian.isZero(0) &&
                                    point.potential.force.isZero(0)))
          continue;
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < dim; ++c)
          {
            const int row = contact_face.column[k * dim + c];
            if (row < 0)
              continue;
            (*gradient)[row] -= N[k] * point.potential.force[c];
            for (unsigned int l = 0; l < n; ++l)
              for (unsigned int d = 0; d < dim; ++d)
              {
                const int col = contact_face.column[l * dim + d];
                if (col >= 0 && point.potential.hessian(c, d) != 0)
                  hessian->emplace_back(
                      row, col, N[k] * N[l] * point.potential.hessian(c, d));
              }
          }
      }
    }
    return energy;
  }

  template <int dim>
  void ExplicitContact<dim>::write_columns(const Eigen::VectorXd &x,
                                           VectorType            &u) const
  {
    for (unsigned int j = 0; j < node_list.size(); ++j)
      for (unsigned int c = 0; c < dim; ++c)
        if (node_column[j][c] >= 0)
          u(node_list[j].dofs[c]) = x[node_column[j][c]];
  }

  template <int dim>
  Eigen::VectorXd
  ExplicitContact<dim>::minimise_step(const Eigen::VectorXd &a,
                                      const Eigen::VectorXd &predicted,
                                      const double           eps,
                                      VectorType            &u)
  {
    const auto inertia = [&](const Eigen::VectorXd &x)
    { return 0.5 * (a.array() * (x - predicted).array().square()).sum(); };
    // start from the last step's correction: the contact forces change
    // little from step to step
    Eigen::VectorXd x = predicted + correction;
    write_columns(x, u);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    std::vector<Eigen::Triplet<double>>                triplets;
    // converged: the force residual within 1e-8 of the largest k h, or the
    // step (the line search's last) within 1e-9 of the smallest spacing
    const double tolerance = 1e-8 * force_scale;
    for (newton_iterations = 0; newton_iterations < 50; ++newton_iterations)
    {
      Eigen::VectorXd gradient = (a.array() * (x - predicted).array()).matrix();
      triplets.clear();
      for (unsigned int i = 0; i < n_columns; ++i)
        triplets.emplace_back(i, i, a[i]);
      const double energy =
          inertia(x) + face_potential(u, eps, &gradient, &triplets);
      if (gradient.lpNorm<Eigen::Infinity>() <= tolerance)
        break;
      Eigen::SparseMatrix<double> H(n_columns, n_columns);
      H.setFromTriplets(triplets.begin(), triplets.end());
      solver.compute(H);
      Eigen::VectorXd step  = solver.solve(-gradient);
      double          slope = gradient.dot(step);
      if (solver.info() != Eigen::Success || !(slope < 0))
      {
        step  = -(gradient.array() / a.array()).matrix(); // steepest descent
        slope = gradient.dot(step);
      }
      // backtracking on the step's energy (Armijo)
      double alpha = 1;
      for (unsigned int cut = 0; cut < 30; ++cut, alpha *= 0.5)
      {
        const Eigen::VectorXd trial = x + alpha * step;
        write_columns(trial, u);
        if (inertia(trial) + face_potential(u, eps, nullptr, nullptr) <=
            energy + 1e-4 * alpha * slope)
          break;
      }
      x += alpha * step;
      write_columns(x, u);
      if (alpha * step.lpNorm<Eigen::Infinity>() <= 1e-9 * smallest_spacing)
        break;
    }
    return x;
  }

  template <int dim>
  void ExplicitContact<dim>::enforce_face_potential(const double      dt,
                                                    const double      h,
                                                    const VectorType &mass,
                                                    VectorType       &u)
  {
    // a = m / (dt h) and the prediction, by column
    Eigen::VectorXd a(n_columns), predicted(n_columns);
    for (unsigned int j = 0; j < node_list.size(); ++j)
      for (unsigned int c = 0; c < dim; ++c)
        if (node_column[j][c] >= 0)
        {
          a[node_column[j][c]]         = mass(node_list[j].dofs[c]) / (dt * h);
          predicted[node_column[j][c]] = u(node_list[j].dofs[c]);
        }
    // the same slip speed as an implicit step of 'Time/Time step'
    const double eps = parameters.slip_length(dt, reference_step);
    correction       = minimise_step(a, predicted, eps, u) - predicted;
    // the nodes' forces: the correction's M du / (dt h)
    for (unsigned int j = 0; j < node_list.size(); ++j)
    {
      node_list[j].force.setZero();
      for (unsigned int c = 0; c < dim; ++c)
        if (node_column[j][c] >= 0)
          node_list[j].force[c] =
              a[node_column[j][c]] * correction[node_column[j][c]];
    }
    face_potential(u, eps, nullptr, nullptr); // the points at x
    update_face_lags(u);
  }

  template <int dim>
  void ExplicitContact<dim>::update_face_lags(const VectorType &u)
  {
    // sum_q N_k lambda_q, sum_q N_k w_q g_q and the pressed and slipping
    // weights of each node (by its x dof, in weighted_gap's layout)
    std::unordered_map<types::global_dof_index, std::array<double, 4>> sums;
    for (const auto &contact_face : faces)
    {
      const auto        &face = contact_face.face;
      const unsigned int n    = face.dofs.size() / dim;
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        const auto &potential = contact_face.points[q].potential;
        const bool  pressed   = potential.normal_force > 0;
        for (unsigned int k = 0; k < n; ++k)
        {
          auto        &s = sums[face.dofs[k * dim]];
          const double N = face.shape[q][k], w = face.weight[q];
          s[0] += N * potential.normal_force;
          s[1] += N * w * contact_face.gap[q];
          s[2] += pressed ? N * w : 0;
          s[3] +=
              pressed && potential.status == ContactStatus::slip ? N * w : 0;
        }
      }
    }
    std::unordered_map<types::global_dof_index, double> pressure;
    unsigned int active = 0, slipping = 0;
    double       worst = 0;
    for (auto &node : node_list)
    {
      const auto  &s         = sums[node.dofs[0]];
      const double D         = node.reference_area;
      const double lam       = std::max(0.0, s[0] / D); // Pa
      pressure[node.dofs[0]] = lam;
      node.gap               = s[1] / D;
      report_nearest(node, u);
      node.status = lam > 0 ? (s[3] > 0.5 * s[2] ? ContactStatus::slip
                                                 : ContactStatus::stick)
                            : ContactStatus::inactive;
      active += node.status != ContactStatus::inactive;
      slipping += node.status == ContactStatus::slip;
    }
    // each point: multiplier and lagged normal force w_q sum_k N_k Lambda_k,
    // the frame at its current normal, its position
    for (auto &contact_face : faces)
    {
      const auto        &face = contact_face.face;
      const unsigned int n    = face.dofs.size() / dim;
      for (unsigned int q = 0; q < face.weight.size(); ++q)
      {
        FacePoint &point = contact_face.points[q];
        double     p     = 0;
        for (unsigned int k = 0; k < n; ++k)
          p += face.shape[q][k] * pressure[face.dofs[k * dim]];
        point.multiplier   = std::max(0.0, p) * face.weight[q];
        point.normal_force = point.near_body >= 0 ? point.multiplier : 0;
        point.lag_normal   = contact_face.normal[q];
        point.body         = point.near_body;
        point.geom         = point.near_geom;
        point.last         = point.x;
      }
    }
    // the penetration: the deepest Gauss point's (the nodes' weighted gaps
    // stay positive where the penalty holds the faces' points out)
    for (const auto &contact_face : faces)
      for (const double g : contact_face.gap)
        worst = std::max(worst, -g);
    this->active_count = active;
    this->slip_count   = slipping;
    penetration        = worst;
  }

#define SOFTGRASP_INSTANTIATE(dim)                                             \
  template void ExplicitContact<dim>::setup_face_potential(                    \
      const SolidSystem<dim> &);                                               \
  template double ExplicitContact<dim>::face_potential(                        \
      const VectorType &,                                                      \
      const double,                                                            \
      Eigen::VectorXd *,                                                       \
      std::vector<Eigen::Triplet<double>> *);                                  \
  template void ExplicitContact<dim>::enforce_face_potential(                  \
      const double, const double, const VectorType &, VectorType &);           \
  template void ExplicitContact<dim>::write_columns(const Eigen::VectorXd &,   \
                                                    VectorType &) const;       \
  template Eigen::VectorXd ExplicitContact<dim>::minimise_step(                \
      const Eigen::VectorXd &,                                                 \
      const Eigen::VectorXd &,                                                 \
      const double,                                                            \
      VectorType &);                                                           \
  template void ExplicitContact<dim>::update_face_lags(const VectorType &);
  SOFTGRASP_INSTANTIATE(2)
  SOFTGRASP_INSTANTIATE(3)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
