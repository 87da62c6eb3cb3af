// The nodal contact conditions and their linearisation: for inactive,
// frictionless, stick and slip states of a node near a rigid sphere, the
// matrices A = dPhi/df and B = dPhi/du equal central finite differences of
// Phi (so the semi-smooth Newton method converges quadratically once the
// active set is fixed), and Phi vanishes exactly at states that satisfy
// the KKT conditions and Coulomb's law.
#include "../tests.h"

#include <Eigen/Geometry>
#include <softgrasp/contact/nodal_contact_law.h>

using namespace softgrasp;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{
  const Vector3d centre(0.01, -0.02, 0.005);
  const double   radius = 0.01;
  const Vector3d target(0.0112, -0.0213, 0.0152); // slip reference point

  NodalContactInput
  input_at(const Vector3d &x, const Vector3d &f, const double mu)
  {
    NodalContactInput in;
    const Vector3d    r = x - centre;
    in.gap              = r.norm() - radius;
    in.n                = r.normalized();
    in.H  = (Matrix3d::Identity() - in.n * in.n.transpose()) / r.norm();
    in.w  = x - target;
    in.f  = f;
    in.mu = mu;
    in.c  = 50;
    in.c_t = 50;
    return in;
  }

  double check(const std::string  &name,
               const Vector3d     &x,
               const Vector3d     &f,
               const double        mu,
               const ContactStatus expected)
  {
    const auto lin = evaluate_nodal_contact(input_at(x, f, mu));
    SG_CHECK(lin.status == expected, name + ": status");
    const double h_f = 1e-6 * (1 + f.norm()), h_x = 1e-8;
    Matrix3d     A_fd, B_fd;
    for (unsigned int k = 0; k < 3; ++k)
    {
      Vector3d e  = Vector3d::Zero();
      e[k]        = h_f;
      A_fd.col(k) = (evaluate_nodal_contact(input_at(x, f + e, mu)).phi -
                     evaluate_nodal_contact(input_at(x, f - e, mu)).phi) /
                    (2 * h_f);
      e[k]        = h_x;
      B_fd.col(k) = (evaluate_nodal_contact(input_at(x + e, f, mu)).phi -
                     evaluate_nodal_contact(input_at(x - e, f, mu)).phi) /
                    (2 * h_x);
      e[k] = 0;
    }
    const double error_A = (A_fd - lin.A).norm() / std::max(1.0, lin.A.norm());
    const double error_B = (B_fd - lin.B).norm() / std::max(1.0, lin.B.norm());
    dealii::deallog << name << ": |A - A_fd|/|A| " << (error_A < 1e-6)
                    << ", |B - B_fd|/|B| " << (error_B < 1e-6) << std::endl;
    SG_CHECK(error_A < 1e-6, name + ": A is the derivative of Phi in f");
    SG_CHECK(error_B < 1e-6, name + ": B is the derivative of Phi in u");
    return lin.phi.norm();
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  // A point slightly inside the sphere, off its axes.
  const Vector3d dir = Vector3d(0.3, -0.5, 0.8).normalized();
  const Vector3d x   = centre + (radius - 2e-5) * dir;
  Vector3d       t1  = dir.cross(Vector3d(1, 0, 0)).normalized();
  const Vector3d far = centre + (radius + 1e-3) * dir;

  check("inactive", far, 0.01 * t1, 0.3, ContactStatus::inactive);
  check("frictionless", x, 2 * dir + 0.5 * t1, 0, ContactStatus::slip);
  check("stick", x, 2 * dir + 0.1 * t1, 0.3, ContactStatus::stick);
  check("slip", x, 2 * dir + 1.5 * t1, 0.3, ContactStatus::slip);

  // KKT states give Phi = 0: closed with pressure (frictionless), and a
  // sliding node whose friction force mu f_n opposes its slip.
  const Vector3d on         = centre + radius * dir;
  const Vector3d slid       = on;
  const auto frictionless   = evaluate_nodal_contact(input_at(on, 3 * dir, 0));
  NodalContactInput sliding = input_at(slid, 3 * dir - 0.9 * t1, 0.3);
  sliding.w                 = 1e-4 * t1; // moved along +t1 -> friction -t1
  const auto slip           = evaluate_nodal_contact(sliding);
  dealii::deallog << "KKT states: |Phi| frictionless "
                  << (frictionless.phi.norm() < 1e-14) << ", sliding "
                  << (slip.phi.norm() < 1e-14) << std::endl;
  SG_CHECK(frictionless.phi.norm() < 1e-14, "frictionless KKT state");
  SG_CHECK(slip.status == ContactStatus::slip && slip.phi.norm() < 1e-14,
           "Coulomb sliding state");
  // Tension is not allowed: a closed node pulled away opens.
  const auto pulled = evaluate_nodal_contact(input_at(on, -dir, 0.3));
  SG_CHECK(pulled.status == ContactStatus::inactive, "tension opens");
  dealii::deallog << "pulled node opens: 1" << std::endl;
}
