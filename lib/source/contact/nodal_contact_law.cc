#include <softgrasp/contact/nodal_contact_law.h>

namespace softgrasp
{
  NodalContactLinearization evaluate_nodal_contact(const NodalContactInput &in)
  {
    using Eigen::Matrix3d;
    using Eigen::Vector3d;
    NodalContactLinearization out;
    const Vector3d           &n   = in.n;
    const Matrix3d            I   = Matrix3d::Identity();
    const Matrix3d            P_t = I - n * n.transpose();
    const double              f_n = n.dot(in.f);
    out.normal                    = f_n;
    out.slip                      = P_t * in.w;

    const double trial_normal = f_n - in.c * in.gap;
    if (trial_normal <= 0)
    {
      out.status = ContactStatus::inactive;
      out.phi    = in.f;
      out.A      = I;
      out.B.setZero();
      return out;
    }

    // Pieces shared by the closed states (H is symmetric, H n = 0):
    //   d(g n)     = (n n^T + g H) du
    //   d(P_t f)   = P_t df + M1 du,  M1 = -(n . f) H - n (H f)^T
    //   d(P_t w)   = S du,            S  = P_t - (n . w) H - n (H w)^T
    const Matrix3d gap_rows = n * n.transpose() + in.gap * in.H;
    const Matrix3d M1       = -f_n * in.H - n * (in.H * in.f).transpose();
    const Matrix3d S = P_t - n.dot(in.w) * in.H - n * (in.H * in.w).transpose();
    const Vector3d f_t   = P_t * in.f;
    const double   c_t   = in.c_t;
    const Vector3d trial = f_t - c_t * out.slip;

    if (in.mu > 0 && trial.norm() <= in.mu * trial_normal)
    {
      out.status = ContactStatus::stick;
      out.phi    = in.c * in.gap * n + c_t * out.slip;
      out.A.setZero();
      out.B = in.c * gap_rows + c_t * S;
      return out;
    }

    out.status = ContactStatus::slip;
    if (in.mu == 0)
    {
      out.phi = in.c * in.gap * n + f_t;
      out.A   = P_t;
      out.B   = in.c * gap_rows + M1;
      return out;
    }
    const double   length = trial.norm();
    const Vector3d t_hat  = trial / length;
    const Matrix3d N_hat  = (I - t_hat * t_hat.transpose()) / length;
    out.phi               = in.c * in.gap * n + f_t - in.mu * f_n * t_hat;
    out.A = P_t - in.mu * t_hat * n.transpose() - in.mu * f_n * N_hat * P_t;
    out.B = in.c * gap_rows + M1 - in.mu * t_hat * (in.H * in.f).transpose() -
            in.mu * f_n * N_hat * (M1 - c_t * S);
    return out;
  }
} // namespace softgrasp
