// An underactuated gripper closed by its one actuator (issue 54): the
// two-finger gripper of parameter-files/mjcf/underactuated_gripper.xml
// (four hinges, one position actuator on a fixed tendon over all four, an
// equality mirroring the proximal joints, springs on the distal joints; no
// C++ of its own) grasps the free sphere through the .prm alone ('Closing
// actuators = grip', 'Finger joints' empty):
//  - the run reports the hand it found: the actuator and the four joints
//    its tendon moves;
//  - the proximal phalanges stop on the sphere, the distal ones curl under
//    it and press it into the palm: at the equilibrium grasp the palm and
//    the two distal phalanges hold it, each with more than 1 N, and their
//    forces on the free, weightless sphere balance within 1 % of the
//    largest;
//  - the indentation closes the tendon by 'Extra joint angle' = 0.1 rad
//    with the object's forces held (the loaded hand): the recorded joint
//    angles grow by 0.1 rad in sum (the tendon's length, 2e-3 rad), the
//    proximal joints stay mirror images (1e-3 rad), and the sprung distal
//    joints keep their balance (under a tenth of the proximal closure).
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

namespace
{
  /// The change of joint @p name's recorded angle over the indentation.
  double angle_change(const KinematicsData &data, const std::string &name)
  {
    const auto &phase = data.phase("indentation");
    for (const auto &joint : data.joints)
      if (joint.name == name)
      {
        double start = 0, end = 0;
        for (std::size_t i = 0; i < data.time.size(); ++i)
        {
          if (data.time[i] == phase.start_time)
            start = joint.angle[i];
          if (data.time[i] == phase.end_time)
            end = joint.angle[i];
        }
        return end - start;
      }
    AssertThrow(false, dealii::ExcMessage("no joint " + name));
    return 0;
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const std::vector<std::string> rigid = {"Rigid environment"};
  set(prm, rigid, "Scene file", "mjcf/underactuated_sphere_scene.xml");
  set(prm, rigid, "Base position", "0, 0, 0.05");
  set(prm, rigid, "Finger joints", "");
  set(prm, rigid, "Closing actuators", "grip");
  set(prm, rigid, "Contact links", "left_distal_link, right_distal_link");
  set(prm, rigid, "Closing speed", "1");
  set(prm, rigid, "Grip", "0.1");
  set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", "0.1");
  set(prm, {"Rigid environment", "Indentation"}, "Samples", "4");
  const auto         parameters = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;
  GraspSimulation    simulation(parameters, log);
  try
  {
    write_kinematics_file(simulation.run(), "kinematics.h5");
  }
  catch (...)
  {
    std::cout << log.str() << std::flush;
    throw;
  }
  const KinematicsData data = read_kinematics_file("kinematics.h5");
  SG_CHECK(log.str().find("actuator 'grip' (joints left_proximal_joint "
                          "left_distal_joint right_proximal_joint "
                          "right_distal_joint)") != std::string::npos,
           "the run reports the actuator and its joints");
  dealii::deallog << "reported: the hand closes by actuator 'grip' and its "
                     "four joints: 1"
                  << std::endl;

  const auto balance = softgrasp_tests::equilibrium_balance(data);
  SG_CHECK(balance.links == 3 && balance.smallest > 1,
           "the palm and the two distal phalanges hold the sphere");
  SG_CHECK(balance.sum < 0.01 * balance.largest, "the forces balance");
  dealii::deallog << "the distal phalanges wrap the sphere into the palm, "
                     "each pressing more than 1 N, forces balanced within "
                     "1 %: 1"
                  << std::endl;

  const double lp = angle_change(data, "left_proximal_joint");
  const double rp = angle_change(data, "right_proximal_joint");
  const double ld = angle_change(data, "left_distal_joint");
  const double rd = angle_change(data, "right_distal_joint");
  SG_CHECK(std::abs(lp + rp + ld + rd - 0.1) < 0.002,
           "the tendon closes by 0.1 rad");
  SG_CHECK(std::abs(lp - rp) < 1e-3, "mirror images");
  SG_CHECK(std::abs(ld) < 0.1 * lp && std::abs(rd) < 0.1 * rp,
           "the sprung distal joints keep their balance");
  dealii::deallog << "indentation: the joints close 0.1 rad in sum, the "
                     "proximal ones alike, the sprung distal ones by less "
                     "than a tenth of them: 1"
                  << std::endl;
}
