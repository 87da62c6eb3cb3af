// Bad input to the MuJoCo bridge gives an InputError that names the cause
// and the fix: a missing or malformed MJCF scene, an unknown joint (listing
// the valid ones), a solref time constant MuJoCo 2.2 would clamp silently,
// finger joints of two types (a hinge and a slide), a jaw whose positive
// target opens it (it never touches; the message names the sign), and an
// actuator target outside its ctrlrange (clamped silently by MuJoCo).
#include "../tests.h"
#include "grasp_helpers.h"

#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

using softgrasp_tests::expect_input_error;

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const auto         good = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;

  expect_input_error("missing scene",
                     [] { MujocoModel model("no-such-scene.xml"); },
                     {"no-such-scene.xml", "Cannot open"});
  std::ofstream("malformed.xml") << "<mujoco><worldbody><body>\n</mujoco>\n";
  expect_input_error("malformed scene",
                     [] { MujocoModel model("malformed.xml"); },
                     {"malformed.xml", "MuJoCo could not load"});

  auto unknown          = good;
  unknown.finger_joints = {"thumb_proximal_joint", "index_joint"};
  expect_input_error("unknown joint",
                     [&] { GraspSimulation simulation(unknown, log); },
                     {"'index_joint'", "thumb_distal_joint"});

  std::ifstream      in(good.scene_file);
  std::ostringstream scene;
  scene << in.rdbuf();
  std::string text = scene.str();
  text.replace(text.find("timestep=\"0.001\""), 16, "timestep=\"0.005\"");
  auto coarse       = good;
  coarse.scene_file = "coarse_scene.xml";
  { // the scene includes the hand relative to its own directory
    std::ifstream      hand_in(std::string(PARAMETER_FILES) +
                          "/mjcf/three_finger_hand.xml");
    std::ostringstream hand;
    hand << hand_in.rdbuf();
    std::ofstream("three_finger_hand.xml") << hand.str();
    std::ofstream("coarse_scene.xml") << text;
  }
  expect_input_error("solref under two time steps",
                     [&] { GraspSimulation simulation(coarse, log); },
                     {"solref", "0.004"});

  // A hand mixing hinges and slide joints: refused with both names.
  auto mixed          = good;
  mixed.finger_joints = {"thumb_proximal_joint", "pull"};
  expect_input_error("hinge and slide finger joints",
                     [&] { GraspSimulation simulation(mixed, log); },
                     {"'thumb_proximal_joint' and 'pull'", "one type"});

  // A jaw whose positive target opens it (its axis flipped): it never
  // touches, and the message names the sign.
  {
    const std::string  mjcf = std::string(PARAMETER_FILES) + "/mjcf/";
    std::ifstream      gripper_in(mjcf + "parallel_jaw_gripper.xml");
    std::ostringstream gripper;
    gripper << gripper_in.rdbuf();
    std::string jaw = gripper.str();
    const auto  left =
        jaw.find("\"left_jaw_joint\" class=\"jaw\" axis=\"1 0 0\"");
    AssertThrow(left != std::string::npos, dealii::ExcMessage("jaw moved"));
    jaw.replace(left, 41, "\"left_jaw_joint\" class=\"jaw\" axis=\"-1 0 0\"");
    std::ofstream("parallel_jaw_gripper.xml") << jaw;
    std::ifstream      scene_in(mjcf + "gripper_sphere_scene.xml");
    std::ostringstream gripper_scene;
    gripper_scene << scene_in.rdbuf();
    std::ofstream("flipped_scene.xml") << gripper_scene.str();
  }
  auto flipped          = good;
  flipped.scene_file    = "flipped_scene.xml";
  flipped.finger_joints = {"left_jaw_joint", "right_jaw_joint"};
  flipped.contact_links = {"left_pad", "right_pad"};
  flipped.closing_speed = 0.05;
  flipped.grip          = 0.002;
  expect_input_error("a joint whose positive target opens it",
                     [&]
                     {
                       GraspSimulation simulation(flipped, log);
                       simulation.run();
                     },
                     {"'left_jaw_joint' reached the end of its ctrlrange",
                      "a positive target closes it"});

  auto tight = good;
  tight.grip = 2.0;
  expect_input_error("target outside ctrlrange",
                     [&]
                     {
                       GraspSimulation simulation(tight, log);
                       simulation.run();
                     },
                     {"ctrlrange", "'Grip'"});
}
