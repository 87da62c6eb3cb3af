// A hand that closes on slide joints (issue 54): the parallel-jaw gripper
// of parameter-files/mjcf/parallel_jaw_gripper.xml (two jaws on slide
// joints with rubber pads, position actuators; no C++ of its own) grasps
// the free sphere of the sphere scene through the grasp program's rigid
// stage, set up by the .prm alone ('Finger joints' in metres):
//  - both pads touch at the equilibrium grasp, each pressed by more than
//    1 N, and their forces on the free, weightless sphere balance within
//    1 % of the larger;
//  - the indentation phase closes the jaws by 'Extra joint angle' = 1 mm,
//    which the kinematics file records, and the rigid bodies built from
//    the file move the pads 1 mm (each) towards the sphere;
//  - the log gives the closing in m/s and m.
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const std::vector<std::string> rigid = {"Rigid environment"};
  set(prm, rigid, "Scene file", "mjcf/gripper_sphere_scene.xml");
  set(prm, rigid, "Finger joints", "left_jaw_joint, right_jaw_joint");
  set(prm, rigid, "Contact links", "left_pad, right_pad");
  set(prm, rigid, "Closing speed", "0.05");
  set(prm, rigid, "Grip", "0.002");
  set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", "0.001");
  set(prm, {"Rigid environment", "Indentation"}, "Samples", "4");
  const auto         parameters = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;
  GraspSimulation    simulation(parameters, log);
  write_kinematics_file(simulation.run(), "kinematics.h5");
  const KinematicsData data = read_kinematics_file("kinematics.h5");

  const auto balance = softgrasp_tests::equilibrium_balance(data);
  SG_CHECK(balance.links == 2 && balance.smallest > 1,
           "both pads pressed by more than 1 N");
  SG_CHECK(balance.sum < 0.01 * balance.largest, "the pads' forces balance");
  dealii::deallog << "both pads touch at the equilibrium with more than 1 N "
                     "each, forces balanced within 1 %: 1"
                  << std::endl;

  const auto &phase = data.phase("indentation");
  SG_CHECK(std::abs(phase.amount - 0.001) < 1e-15, "closure recorded in m");
  unsigned int pads  = 0;
  const double moved = softgrasp_tests::indentation_travel_error(
      data, {"left_pad", "right_pad"}, 0.001, pads);
  SG_CHECK(pads == 2 && moved < 1e-9, "the pads close 1 mm each");
  dealii::deallog << "indentation of 1 mm recorded, both pads moved 1 mm: 1"
                  << std::endl;
  SG_CHECK(log.str().find(" m/s, grip 0.002 m beyond first touch") !=
               std::string::npos,
           "the log's units");
  dealii::deallog << "closing logged in m/s and m: 1" << std::endl;
}
