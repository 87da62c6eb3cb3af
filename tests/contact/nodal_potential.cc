// The incremental potential of one contact node (issues 61 and 62):
//  - its force is minus the gradient of its energy, and its Hessian the
//    Jacobian of that gradient, by central finite differences at open,
//    sticking and slipping states on a flat rigid surface in 2D and 3D, and
//    slipping on a sphere (the curvature term -lambda grad^2 g);
//  - on the flat surface the Hessian is positive semi-definite; the
//    friction force is at most mu times the lagged normal force;
//  - a two-degree-of-freedom system against its hand solution: a point
//    on a tangential spring (stiffness K_t, its end pulled by d) pressed by
//    a normal load P onto a rigid plane with friction mu, solved as the
//    minimisation of spring energy - P . x + the node's potential by
//    Newton with an Armijo line search on the potential, with outer
//    (Uzawa and friction lag) iterations: in stick the point creeps by
//    x_t < eps with K_t (d - x_t) = mu P f1(x_t), in slip it lags the
//    spring by
//    x_t = d - mu P / K_t; the normal force is P and the penetration
//    vanishes with the outer iterations.
#include "../tests.h"

#include <Eigen/Dense>
#include <softgrasp/contact/nodal_potential.h>

using namespace softgrasp;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{
  /// The rigid surface: the plane z = 0 (outward +z), or a sphere.
  struct Surface
  {
    bool     sphere = false;
    Vector3d centre = Vector3d(0.001, -0.002, -0.02);
    double   radius = 0.02;
  };

  NodalPotentialInput input_at(const Surface             &surface,
                               const Vector3d            &x,
                               const Vector3d            &x_old,
                               const NodalPotentialInput &base)
  {
    NodalPotentialInput in = base;
    if (surface.sphere)
    {
      const Vector3d r = x - surface.centre;
      in.gap           = r.norm() - surface.radius;
      in.n             = r.normalized();
      in.H = (Matrix3d::Identity() - in.n * in.n.transpose()) / r.norm();
    }
    else
    {
      in.gap = x[2];
      in.n   = Vector3d::UnitZ();
    }
    in.w = x - x_old;
    return in;
  }

  /// Largest relative errors of the force against -dE/dx and of the
  /// Hessian against -d force/dx (central differences of step h).
  std::pair<double, double> fd_errors(const Surface             &surface,
                                      const Vector3d            &x,
                                      const Vector3d            &x_old,
                                      const NodalPotentialInput &base,
                                      const unsigned int         dim)
  {
    const double h  = 1e-9;
    const auto   at = [&](const Vector3d &y)
    { return evaluate_nodal_potential(input_at(surface, y, x_old, base)); };
    const auto p = at(x);
    Vector3d   grad_fd;
    Matrix3d   hess_fd = Matrix3d::Zero();
    for (unsigned int c = 0; c < 3; ++c)
    {
      Vector3d e = Vector3d::Zero();
      e[c]       = c < dim ? h : 0;
      if (c >= dim)
      {
        grad_fd[c] = 0;
        continue;
      }
      const auto plus = at(x + e), minus = at(x - e);
      grad_fd[c]     = (plus.energy - minus.energy) / (2 * h);
      hess_fd.col(c) = -(plus.force - minus.force) / (2 * h);
    }
    const double f_scale = std::max(p.force.norm(), 1e-12);
    const double h_scale = std::max(p.hessian.norm(), 1e-12);
    return {(p.force + grad_fd).norm() / f_scale,
            (p.hessian - hess_fd).norm() / h_scale};
  }

  /// Friction against the current normal force (the polish of a step
  /// whose lag does not settle; no longer a potential): the Jacobian
  /// against central differences of the force, sticking and slipping on
  /// the plane and slipping on the sphere (at @p x, frame of @p base), and
  /// |f_t| <= mu lambda exactly.
  void check_polish(const Surface             &sphere,
                    const Vector3d            &x,
                    const NodalPotentialInput &base)
  {
    NodalPotentialInput in   = base;
    in.current_normal_force  = true;
    in.lagged_normal_force   = 0; // not used
    NodalPotentialInput flat = in;
    flat.T                   = tangent_basis(Vector3d::UnitZ(), 3);
    const Vector3d origin(0.001, 0.0005, 0);
    struct Case
    {
      std::string                name;
      Surface                    surface;
      Vector3d                   x, x_old;
      const NodalPotentialInput *input;
    };
    const std::vector<Case> cases = {
        {"stick on the plane",
         Surface(),
         origin + Vector3d(3e-6, 1.2e-6, -1e-6),
         origin,
         &flat},
        {"slip on the plane",
         Surface(),
         origin + Vector3d(2e-4, 8e-5, -2e-6),
         origin,
         &flat},
        {"slip on the sphere", sphere, x, x - Vector3d(2e-4, 0, 0), &in}};
    for (const auto &c : cases)
    {
      const auto errors = fd_errors(c.surface, c.x, c.x_old, *c.input, 3);
      const auto p =
          evaluate_nodal_potential(input_at(c.surface, c.x, c.x_old, *c.input));
      const double ratio = p.friction.norm() / (in.mu * p.normal_force);
      dealii::deallog << "3D, friction against the current normal force, "
                      << c.name << ": |friction| / (mu lambda) " << ratio
                      << ", Jacobian vs FD "
                      << (errors.second < 1e-5 ? "ok" : "WRONG") << std::endl;
      SG_CHECK(errors.second < 1e-5, c.name + ": the Jacobian of the force");
      SG_CHECK(p.normal_force > 0 && ratio <= 1 + 1e-12,
               c.name + ": Coulomb against the current normal force");
    }
  }

  void check_states(const unsigned int dim)
  {
    NodalPotentialInput base;
    base.penalty             = 2e4; // N/m
    base.multiplier          = 0.3; // N
    base.mu                  = 0.5;
    base.lagged_normal_force = 0.4;  // N
    base.slip_tolerance      = 1e-5; // m
    base.T                   = tangent_basis(Vector3d::UnitZ(), 3);
    if (dim == 2)
    {
      base.T       = Eigen::Matrix<double, 3, 2>::Zero();
      base.T(0, 0) = 1; // the plane y = 0 of a 2D problem, tangent x
    }
    const Vector3d x_old(0.001, 0.0005, 0.0);
    struct Case
    {
      std::string name;
      Vector3d    x;
    };
    // a plane in 3D, the line y = 0 in 2D: the gap is x[dim - 1]
    const unsigned int g     = dim - 1;
    auto               point = [&](const double t, const double gap)
    {
      Vector3d x = x_old;
      x[0] += t;
      if (dim == 3)
        x[1] += 0.4 * t;
      x[g] = gap;
      if (dim == 2)
        x[2] = 0;
      return x;
    };
    const std::vector<Case> cases = {{"open", point(2e-4, 1e-4)},
                                     {"stick", point(3e-6, -1e-6)},
                                     {"slip", point(2e-4, -2e-6)}};
    for (const auto &c : cases)
    {
      NodalPotentialInput in = base;
      if (c.name == "open")
        in.lagged_normal_force = 0; // a node that was open before
      auto evaluate2 = [&](const Vector3d &y)
      {
        NodalPotentialInput i = in;
        i.gap                 = y[g];
        i.n = dim == 2 ? Vector3d::UnitY() : Vector3d::UnitZ();
        i.w = y - x_old;
        if (dim == 2)
          i.w[2] = 0;
        return i;
      };
      // finite differences against the plane in the node's own plane
      const double h       = 1e-9;
      const auto   p       = evaluate_nodal_potential(evaluate2(c.x));
      Vector3d     grad_fd = Vector3d::Zero();
      Matrix3d     hess_fd = Matrix3d::Zero();
      for (unsigned int k = 0; k < dim; ++k)
      {
        Vector3d e       = Vector3d::Zero();
        e[k]             = h;
        const auto plus  = evaluate_nodal_potential(evaluate2(c.x + e));
        const auto minus = evaluate_nodal_potential(evaluate2(c.x - e));
        grad_fd[k]       = (plus.energy - minus.energy) / (2 * h);
        hess_fd.col(k)   = -(plus.force - minus.force) / (2 * h);
      }
      const double f_err =
          (p.force + grad_fd).norm() / std::max(p.force.norm(), 1e-12);
      const double h_err =
          (p.hessian - hess_fd).norm() / std::max(p.hessian.norm(), 1e-12);
      const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(p.hessian);
      // |friction| <= mu lambda^k; an open node (lambda^k = 0) carries none
      const double friction_ratio =
          in.lagged_normal_force > 0
              ? p.friction.norm() / (in.mu * in.lagged_normal_force)
              : p.friction.norm();
      const char *status[] = {"open", "stick", "slip"};
      dealii::deallog << dim << "D " << c.name << ": status "
                      << status[static_cast<int>(p.status)] << ", normal force "
                      << p.normal_force << " N, |friction| / (mu lambda^k) "
                      << friction_ratio << "; force vs -dE/dx "
                      << (f_err < 1e-5 ? "ok" : "WRONG") << ", Hessian vs FD "
                      << (h_err < 1e-5 ? "ok" : "WRONG") << std::endl;
      SG_CHECK(f_err < 1e-5, c.name + ": the force is -grad E");
      SG_CHECK(h_err < 1e-5, c.name + ": the Hessian is d(-force)/dx");
      SG_CHECK(eig.eigenvalues().minCoeff() >= -1e-9 * p.hessian.norm(),
               c.name + ": the Hessian is positive semi-definite");
      SG_CHECK(friction_ratio <= 1 + 1e-12, c.name + ": Coulomb");
      SG_CHECK(std::string(status[static_cast<int>(p.status)]) == c.name,
               c.name + ": the state");
    }

    // a curved surface: the curvature term of the Hessian
    if (dim == 3)
    {
      Surface sphere;
      sphere.sphere    = true;
      const Vector3d x = sphere.centre + Vector3d(0.3, 0.2, 1).normalized() *
                                             (sphere.radius - 2e-6);
      NodalPotentialInput in = base;
      in.T              = tangent_basis((x - sphere.centre).normalized(), 3);
      const auto errors = fd_errors(sphere, x, x - Vector3d(2e-4, 0, 0), in, 3);
      dealii::deallog << "3D slip on a sphere: force vs -dE/dx "
                      << (errors.first < 1e-5 ? "ok" : "WRONG")
                      << ", Hessian vs FD "
                      << (errors.second < 1e-5 ? "ok" : "WRONG") << std::endl;
      SG_CHECK(errors.first < 1e-5, "sphere: the force is -grad E");
      SG_CHECK(errors.second < 1e-5, "sphere: the Hessian is d(-force)/dx");
      check_polish(sphere, x, in);
    }
  }

  /// The two-dof system of the header; returns (x_t, lambda, penetration,
  /// outer iterations, energy increases).
  struct SpringResult
  {
    double       x_t = 0, normal = 0, penetration = 0;
    unsigned int outer = 0, newton = 0, increases = 0;
  };

  SpringResult spring_system(const double K_t,
                             const double d,
                             const double P,
                             const double mu,
                             const double eps)
  {
    // unknowns (x_t, x_n); potential E = K_t/2 (x_t - d)^2 - P' x with the
    // load P pressing into the plane (-z), + the node's C + D
    NodalPotentialInput base;
    base.penalty        = 1e3 * K_t;
    base.mu             = mu;
    base.slip_tolerance = eps;
    base.T              = tangent_basis(Vector3d::UnitZ(), 3);
    auto node_at        = [&](const Eigen::Vector2d &y)
    {
      NodalPotentialInput in = base;
      in.gap                 = y[1];
      in.n                   = Vector3d::UnitZ();
      in.w                   = Vector3d(y[0], 0, 0); // from x_old = 0
      return evaluate_nodal_potential(in);
    };
    auto energy = [&](const Eigen::Vector2d &y, NodalPotential &p)
    {
      p = node_at(y);
      return 0.5 * K_t * (y[0] - d) * (y[0] - d) + P * y[1] + p.energy;
    };
    SpringResult result;
    // the node has no normal stiffness of its own while open, so Newton
    // starts just inside the plane, where the penalty holds it
    Eigen::Vector2d y(0, -1e-9);
    for (result.outer = 1; result.outer <= 50; ++result.outer)
    {
      NodalPotential p;
      for (unsigned int it = 0; it < 100; ++it)
      {
        const double    E0 = energy(y, p);
        Eigen::Vector2d g(K_t * (y[0] - d) - p.force[0], P - p.force[2]);
        if (g.norm() < 1e-12 * P)
          break;
        Eigen::Matrix2d H;
        H << K_t + p.hessian(0, 0), p.hessian(0, 2), p.hessian(2, 0),
            p.hessian(2, 2);
        const Eigen::Vector2d dy    = -H.ldlt().solve(g);
        double                alpha = 1;
        NodalPotential        trial;
        while (energy(y + alpha * dy, trial) >
                   E0 + 1e-4 * alpha * g.dot(dy) + 1e-15 * std::abs(E0) &&
               alpha > 1e-8)
          alpha *= 0.5;
        if (energy(y + alpha * dy, trial) > E0 + 1e-15 * std::abs(E0))
          ++result.increases;
        y += alpha * dy;
        ++result.newton;
      }
      energy(y, p);
      const bool settled =
          std::abs(p.normal_force - base.lagged_normal_force) <= 1e-10 * P &&
          -y[1] <= 1e-10;
      if (settled)
        break;
      base.multiplier          = p.normal_force;
      base.lagged_normal_force = p.normal_force;
    }
    NodalPotential p;
    energy(y, p);
    result.x_t         = y[0];
    result.normal      = p.normal_force;
    result.penetration = std::max(0.0, -y[1]);
    return result;
  }

  void check_spring_system()
  {
    const double K_t = 100, P = 2, mu = 0.5, eps = 1e-5;
    // stick: K_t d = 0.5 N < mu P = 1 N
    {
      const double d = 0.005;
      const auto   r = spring_system(K_t, d, P, mu, eps);
      // K_t (d - x) = mu P f1(x), f1 = 2 x/eps - x^2/eps^2: the smaller
      // root of (b/eps^2) x^2 - (2 b/eps + K_t) x + K_t d = 0, b = mu P
      const double b = mu * P, a = b / (eps * eps), B = 2 * b / eps + K_t;
      const double x_hand =
          2 * K_t * d / (B + std::sqrt(B * B - 4 * a * K_t * d));
      dealii::deallog << "spring, stick: x_t = " << r.x_t << " m (hand "
                      << x_hand << " m), normal force " << r.normal
                      << " N (P = " << P << " N), penetration " << r.penetration
                      << " m, " << r.outer << " outer iterations" << std::endl;
      SG_CHECK_CLOSE(r.x_t, x_hand, 1e-6, 0, "stick: the creep");
      SG_CHECK(r.x_t < eps, "stick: the creep is below eps");
      SG_CHECK_CLOSE(r.normal, P, 1e-8, 0, "stick: the normal force");
      SG_CHECK(r.increases == 0, "stick: the potential never increased");
    }
    // slip: K_t d = 2 N > mu P = 1 N
    {
      const double d      = 0.02;
      const auto   r      = spring_system(K_t, d, P, mu, eps);
      const double x_hand = d - mu * P / K_t;
      dealii::deallog << "spring, slip: x_t = " << r.x_t << " m (hand "
                      << x_hand << " m), normal force " << r.normal
                      << " N, penetration " << r.penetration << " m, "
                      << r.outer << " outer iterations" << std::endl;
      SG_CHECK_CLOSE(r.x_t, x_hand, 1e-8, 0, "slip: the lag of the spring");
      SG_CHECK_CLOSE(r.normal, P, 1e-8, 0, "slip: the normal force");
      SG_CHECK(r.penetration < 1e-10, "slip: no penetration");
      SG_CHECK(r.increases == 0, "slip: the potential never increased");
    }
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog(4);
  check_states(2);
  check_states(3);
  check_spring_system();
}
