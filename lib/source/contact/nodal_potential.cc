#include <Eigen/Geometry>
#include <cmath>
#include <softgrasp/contact/nodal_potential.h>

namespace softgrasp
{
  NodalPotential evaluate_nodal_potential(const NodalPotentialInput &in)
  {
    NodalPotential out;
    const double   k   = in.penalty;
    const double   lam = in.multiplier;
    const double   t   = lam - k * in.gap; // the trial normal force
    out.normal_force   = std::max(0.0, t);
    out.energy = (out.normal_force * out.normal_force - lam * lam) / (2 * k);
    out.force  = out.normal_force * in.n;
    if (t > 0)
      out.hessian += k * in.n * in.n.transpose() - out.normal_force * in.H;

    // mu lambda^k (N), or mu lambda(x) against the current normal force
    const double bound =
        in.mu *
        (in.current_normal_force ? out.normal_force : in.lagged_normal_force);
    if (bound > 0)
    {
      const Eigen::Vector2d s   = in.T.transpose() * in.w;
      const double          r   = s.norm();
      const double          eps = in.slip_tolerance;
      out.slip                  = in.T * s;
      // IPC's f0 (f0' = f1 = 2 r/eps - r^2/eps^2 below eps, 1 above): the
      // potential is C2 at r = eps, so Newton sees no jump in stiffness
      // where a node passes from stick to slip
      const double          q    = std::min(r / eps, 1.0);
      const double          f1   = r < eps ? q * (2 - q) : 1.0;
      const double          df1  = r < eps ? 2 * (1 - q) / eps : 0.0;
      const double          f1_r = r < eps ? (2 - q) / eps : 1.0 / r;
      const Eigen::Vector2d s_hat =
          r > 0 ? Eigen::Vector2d(s / r) : Eigen::Vector2d::Zero();
      out.energy += bound * (r < eps ? r * q - r * q * q / 3 + eps / 3 : r);
      out.friction             = -bound * f1 * (in.T * s_hat);
      const Eigen::Matrix2d ss = s_hat * s_hat.transpose();
      const Eigen::Matrix2d K =
          df1 * ss + f1_r * (Eigen::Matrix2d::Identity() - ss);
      out.hessian += bound * in.T * K * in.T.transpose();
      out.status = r < eps ? ContactStatus::stick : ContactStatus::slip;
      out.force += out.friction;
      // d(-f_t)/dx through lambda(x) = lam - k g(x): (f_t / lambda) k n^T
      if (in.current_normal_force)
        out.hessian +=
            (in.penalty / out.normal_force) * out.friction * in.n.transpose();
    }
    else if (out.normal_force > 0)
      out.status = in.mu > 0 ? ContactStatus::stick : ContactStatus::slip;
    return out;
  }

  Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d &n,
                                            const unsigned int     dim)
  {
    Eigen::Matrix<double, 3, 2> T = Eigen::Matrix<double, 3, 2>::Zero();
    if (dim == 2)
    {
      T.col(0) = Eigen::Vector3d(-n[1], n[0], 0).normalized();
      return T;
    }
    // the coordinate axis least aligned with n, made orthogonal to it
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    unsigned int    a = 0;
    for (unsigned int c = 1; c < 3; ++c)
      if (std::abs(n[c]) < std::abs(n[a]))
        a = c;
    e[a]     = 1;
    T.col(0) = (e - n.dot(e) * n).normalized();
    T.col(1) = n.cross(T.col(0));
    return T;
  }
} // namespace softgrasp
