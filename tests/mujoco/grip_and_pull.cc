// Grip-tightness levels and the pull phase of the rigid environment, on the
// arm scene (an upper-arm proxy anchored at the shoulder, gravity on):
//  - a tighter grip (actuator targets further beyond first touch) gives a
//    larger equilibrium normal force on the thumb's proximal link;
//  - the pull phase moves the hand base along the requested world axis by
//    the requested distance (forward kinematics, exactly), and the joints
//    keep the indentation's closure.
#include "../tests.h"
#include "grasp_helpers.h"

#include <iomanip>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

namespace
{
  double thumb_normal(const KinematicsData &data)
  {
    for (const auto &f : data.equilibrium_forces)
      if (f.geom == "thumb_proximal_link")
        return std::abs(f.force.dot(f.normal));
    return 0;
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  auto parameters          = softgrasp_tests::sphere_grasp_parameters(prm);
  parameters.scene_file    = PARAMETER_FILES "/mjcf/arm_scene.xml";
  parameters.base_position = Eigen::Vector3d(0, 0, 0.057);
  std::ostringstream log;

  std::vector<double> forces;
  for (const double grip : {0.1, 0.15, 0.2})
  {
    parameters.grip = grip;
    GraspSimulation simulation(parameters, log);
    forces.push_back(thumb_normal(simulation.run()));
    std::ostringstream line;
    line << "grip " << grip << " rad: thumb proximal normal force "
         << std::lround(forces.back()) << " N";
    dealii::deallog << line.str() << std::endl;
  }
  SG_CHECK(forces[0] > 1 && forces[1] > forces[0] && forces[2] > forces[1],
           "a tighter grip presses harder");

  parameters.grip          = 0.1;
  parameters.pull.distance = 0.03;
  parameters.pull.axis     = Eigen::Vector3d(1, 1, 0).normalized();
  GraspSimulation      simulation(parameters, log);
  const KinematicsData data        = simulation.run();
  const auto          &pull        = data.phase("pull");
  const auto          &indentation = data.phase("indentation");
  SG_CHECK(pull.amount == 0.03 && pull.start_time == indentation.end_time,
           "pull phase after the indentation");
  const auto &base = data.bodies[0];
  SG_CHECK(base.name == "hand_base", "the base is the first body");
  const std::size_t last  = data.time.size() - 1;
  std::size_t       start = 0;
  while (data.time[start] < pull.start_time - 1e-12)
    ++start;
  const Eigen::Vector3d moved =
      base.poses[last].position - base.poses[start].position;
  const double error = (moved - 0.03 * parameters.pull.axis).norm();
  dealii::deallog << "base moved along the pull axis by 0.03 m to 1e-12 m: "
                  << (error < 1e-12) << std::endl;
  SG_CHECK(error < 1e-12, "pull distance and direction");
  bool closure_kept = true;
  for (const auto &joint : data.joints)
    if (joint.name != "pull")
      closure_kept = closure_kept &&
                     std::abs(joint.angle[last] - joint.angle[start]) < 1e-15;
  SG_CHECK(closure_kept, "the fingers keep their closure while pulling");
  dealii::deallog << "fingers keep the indentation closure: 1" << std::endl;
}
