// softgrasp's analytic capsule equals MuJoCo's capsule: a small probe sphere
// (radius rho) is placed at points around a rotated capsule, and MuJoCo's
// collision (with a large margin, so that separated pairs are reported too)
// gives the signed distance dist = d(x) - rho; softgrasp's CapsuleShape with
// the capsule's MuJoCo size and pose gives d(x) directly. Also checked: the
// contact normal (MuJoCo's frame row 0, from the capsule to the probe) is
// softgrasp's outward normal.
#include "../tests.h"

#include <fstream>
#include <random>
#include <softgrasp/mujoco/mujoco_model.h>
#include <softgrasp/rigid/capsule_shape.h>
#include <softgrasp/rigid/pose.h>

using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog();
  const double radius = 0.01, half_length = 0.025, rho = 0.002;
  std::ofstream("capsule.xml")
      << "<mujoco><option gravity='0 0 0'/><worldbody>"
         "<body name='link' pos='0.01 -0.02 0.03' "
         "quat='0.9 0.2 -0.3 0.25'>"
         "<geom name='capsule' type='capsule' size='"
      << radius << ' ' << half_length
      << "' margin='1'/></body>"
         "<body name='probe'><freejoint/><geom name='probe' type='sphere' "
         "size='"
      << rho << "' margin='1'/></body></worldbody></mujoco>";
  const MujocoModel mujoco("capsule.xml");
  const mjModel    *m = mujoco.model();
  mjData           *d = mujoco.data();
  mj_forward(m, d);
  const int  capsule = mujoco.id(mjOBJ_GEOM, "capsule", "geom");
  const Pose pose{
      {d->geom_xpos[3 * capsule],
       d->geom_xpos[3 * capsule + 1],
       d->geom_xpos[3 * capsule + 2]},
      Eigen::Quaterniond(
          m->body_quat[4], m->body_quat[5], m->body_quat[6], m->body_quat[7])
          .normalized()};
  const CapsuleShape shape(m->geom_size[3 * capsule],
                           m->geom_size[3 * capsule + 1]);

  std::mt19937                           random(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  double worst_distance = 0, worst_normal = 0, nearest = 1, farthest = -1;
  for (unsigned int i = 0; i < 200; ++i)
  {
    const Eigen::Vector3d x =
        pose.position + Eigen::Vector3d(u(random), u(random), u(random));
    const auto q = shape.query(pose.to_local(x));
    if (q.distance < rho) // MuJoCo measures sphere-sphere-like pairs outside
      continue;
    for (int k = 0; k < 3; ++k)
      d->qpos[k] = x[k];
    d->qpos[3] = 1;
    d->qpos[4] = d->qpos[5] = d->qpos[6] = 0;
    mj_forward(m, d);
    SG_CHECK(d->ncon == 1, "one contact (margin 1 m)");
    const mjContact      &c    = d->contact[0];
    const double          sign = (c.geom1 == capsule) ? 1.0 : -1.0;
    const Eigen::Vector3d n =
        sign * Eigen::Vector3d(c.frame[0], c.frame[1], c.frame[2]);
    worst_distance =
        std::max(worst_distance, std::abs(c.dist - (q.distance - rho)));
    worst_normal =
        std::max(worst_normal, (n - pose.rotate_to_world(q.normal)).norm());
    nearest  = std::min(nearest, q.distance);
    farthest = std::max(farthest, q.distance);
  }
  dealii::deallog << "probe distances from below 5 mm to above 30 mm: "
                  << (nearest < 0.005 && farthest > 0.03) << std::endl;
  dealii::deallog << "signed distance equals MuJoCo's within 1e-12 m: "
                  << (worst_distance < 1e-12) << std::endl;
  dealii::deallog << "normal equals MuJoCo's contact normal within 1e-9: "
                  << (worst_normal < 1e-9) << std::endl;
  SG_CHECK(worst_distance < 1e-12, "capsule signed distance");
  SG_CHECK(worst_normal < 1e-9, "capsule normal");
}
