// Hands closed by naming their actuators (issue 54), from the MJCF alone:
//  - the parallel-jaw gripper rewritten as real ones are built: ONE servo
//    on the left jaw, the right jaw following it through an <equality
//    joint=...>. 'Closing actuators = left_jaw_servo' finds both joints
//    (reported), both pads touch and balance (1 %), and the indentation's
//    1 mm closure moves both pads 1 mm (the coupled jaw through the
//    loaded hand, 1e-5 m); with both jaws' servos geared 2:1 the same
//    closure (in actuator length) moves each jaw 0.5 mm;
//  - the underactuated gripper closed by naming a <keyframe> of the closed
//    hand instead of its actuator: the keyframe's ctrl names 'grip';
//  - the errors a new user meets, each naming the MJCF element and the
//    fix: nothing named to close the hand, an unknown keyframe or
//    actuator (valid ones listed), an actuator that
//    is not a position servo (a <motor>), both 'Finger joints' and 'Closing
//    actuators' given, a closing sign that opens the gripper (the other
//    sign proposed), a hand too far from the object to touch, a pad mesh
//    file MuJoCo cannot read, and a pad mesh that is not closed (found
//    before the rigid stage runs).
#include "../tests.h"
#include "grasp_helpers.h"

#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

namespace
{
  /// The text of parameter-files/mjcf/@p name.
  std::string shipped(const std::string &name)
  {
    std::ifstream      in(std::string(PARAMETER_FILES) + "/mjcf/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// @p text with @p from replaced by @p to (which must be there).
  std::string
  edited(std::string text, const std::string &from, const std::string &to)
  {
    const auto at = text.find(from);
    AssertThrow(at != std::string::npos, dealii::ExcMessage(from));
    return text.replace(at, from.size(), to);
  }

  /**
   * Write @p hand_text as <name>.xml and the shipped scene of the shipped
   * hand @p hand including it as <name>_scene.xml (the parallel-jaw
   * gripper's gripper_sphere_scene.xml or the underactuated gripper's
   * underactuated_sphere_scene.xml); returns the scene's file name.
   */
  std::string variant(const std::string &name,
                      const std::string &hand_text,
                      const std::string &hand)
  {
    const std::string scene = hand == "parallel_jaw_gripper.xml"
                                  ? "gripper_sphere_scene.xml"
                                  : "underactuated_sphere_scene.xml";
    std::ofstream(name + ".xml") << hand_text;
    std::ofstream(name + "_scene.xml")
        << edited(shipped(scene), hand, name + ".xml");
    return name + "_scene.xml";
  }

  /// Run the rigid stage of @p p; its kinematics data.
  KinematicsData run(const GraspParameters &p, std::ostream &log)
  {
    GraspSimulation simulation(p, log);
    return simulation.run();
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const auto         base = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;

  // The jaw gripper on one servo: the right jaw follows by an equality.
  const std::string jaw_hand = "parallel_jaw_gripper.xml";
  auto              jaw      = base;
  jaw.scene_file             = variant(
      "one_servo",
      edited(edited(shipped(jaw_hand),
                    "<position name=\"right_jaw_servo\" class=\"jaw\" "
                                "joint=\"right_jaw_joint\"/>",
                    ""),
             "<actuator>",
             "<equality><joint joint1=\"right_jaw_joint\" "
                         "joint2=\"left_jaw_joint\" solref=\"0.004 1\"/></equality>\n"
                         "  <actuator>"),
      jaw_hand);
  jaw.finger_joints                  = {};
  jaw.closing_actuators              = {"left_jaw_servo"};
  jaw.contact_links                  = {"left_pad", "right_pad"};
  jaw.closing_speed                  = 0.05;
  jaw.grip                           = 0.002;
  jaw.indentation.extra_angle        = 0.001;
  jaw.indentation.samples            = 4;
  const KinematicsData data          = run(jaw, log);
  const auto           reported_hand = log.str().find(
      "actuator 'left_jaw_servo' (joints left_jaw_joint right_jaw_joint)");
  SG_CHECK(reported_hand != std::string::npos, "the hand reported");
  dealii::deallog << "reported: actuator 'left_jaw_servo' moves both jaws: 1"
                  << std::endl;
  const auto balance = softgrasp_tests::equilibrium_balance(data);
  SG_CHECK(balance.links == 2 && balance.smallest > 1,
           "both pads pressed by more than 1 N");
  SG_CHECK(balance.sum < 0.01 * balance.largest, "the pads' forces balance");
  dealii::deallog << "both pads touch with more than 1 N, balanced within "
                     "1 %: 1"
                  << std::endl;
  unsigned int pads  = 0;
  const double error = softgrasp_tests::indentation_travel_error(
      data, {"left_pad", "right_pad"}, 0.001, pads);
  SG_CHECK(pads == 2 && error < 1e-5, "both pads close 1 mm");
  dealii::deallog << "indentation of 1 mm: the servo's jaw and the coupled "
                     "jaw both move 1 mm (1e-5 m): 1"
                  << std::endl;

  // Both servos with gear 2: an actuator's length is twice its jaw's
  // travel, so the 1 mm closure of the actuators moves each jaw 0.5 mm.
  std::string geared_text = shipped(jaw_hand);
  for (const std::string side : {"left", "right"})
    geared_text = edited(geared_text,
                         "<position name=\"" + side +
                             "_jaw_servo\" class=\"jaw\" joint=\"" + side +
                             "_jaw_joint\"/>",
                         "<position name=\"" + side +
                             "_jaw_servo\" class=\"jaw\" joint=\"" + side +
                             "_jaw_joint\" gear=\"2\" ctrlrange=\"-0.01 "
                             "0.12\"/>");
  auto geared               = jaw;
  geared.scene_file         = variant("geared", geared_text, jaw_hand);
  geared.closing_actuators  = {"left_jaw_servo", "right_jaw_servo"};
  geared.closing_speed      = 0.1;
  geared.grip               = 0.004;
  const auto   geared_data  = run(geared, log);
  const double geared_error = softgrasp_tests::indentation_travel_error(
      geared_data, {"left_pad", "right_pad"}, 0.0005, pads);
  SG_CHECK(pads == 2 && geared_error < 1e-5,
           "the geared jaws move half the closure");
  dealii::deallog << "gear 2: the 1 mm closure of the actuators moves each "
                     "jaw 0.5 mm (1e-5 m): 1"
                  << std::endl;

  // The underactuated gripper and its bad variants.
  auto ua                = softgrasp_tests::underactuated_sphere_grasp(base);
  ua.contact_links       = {};
  ua.indentation.samples = 2;

  // The same gripper closed by a keyframe of the closed hand: its ctrl
  // raises 'grip' (the pull servo stays), so 'grip' closes it.
  const std::string ua_hand = "underactuated_gripper.xml";
  auto              keyed   = ua;
  keyed.scene_file          = variant(
      "keyed",
      edited(shipped(ua_hand),
             "<actuator>",
             "<keyframe><key name=\"closed\" ctrl=\"2.5 0\"/></keyframe>\n"
                      "  <actuator>"),
      ua_hand);
  keyed.closing_actuators = {};
  keyed.closing_keyframe  = "closed";
  const auto keyed_data   = run(keyed, log);
  SG_CHECK(log.str().find("keyframe 'closed' closes the hand by grip\n") !=
                   std::string::npos &&
               softgrasp_tests::equilibrium_balance(keyed_data).links == 3,
           "the keyframe names the actuator");
  dealii::deallog << "keyframe 'closed': the hand closes by 'grip' and holds "
                     "the sphere: 1"
                  << std::endl;
  auto no_key             = keyed;
  no_key.closing_keyframe = "open";
  softgrasp_tests::expect_input_error(
      "an unknown keyframe",
      [&] { GraspSimulation simulation(no_key, log); },
      {"no keyframe 'open'", "closed"});

  auto nothing              = ua;
  nothing.closing_actuators = {};
  softgrasp_tests::expect_input_error(
      "nothing named to close the hand",
      [&] { GraspSimulation simulation(nothing, log); },
      {"Neither", "in 'Rigid environment/Closing actuators'"});

  auto unknown              = ua;
  unknown.closing_actuators = {"gripper_motor"};
  softgrasp_tests::expect_input_error(
      "unknown actuator",
      [&] { GraspSimulation simulation(unknown, log); },
      {"no actuator 'gripper_motor'", "grip, pull_servo"});

  auto motor = ua;
  motor.scene_file =
      variant("motor",
              edited(shipped(ua_hand),
                     "<position name=\"grip\" tendon=\"grip_tendon\" kp=\"2\"",
                     "<motor name=\"grip\" tendon=\"grip_tendon\""),
              ua_hand);
  softgrasp_tests::expect_input_error(
      "an actuator that is not a position servo",
      [&] { GraspSimulation simulation(motor, log); },
      {"Actuator 'grip'", "not a position servo", "<position>"});

  auto both          = ua;
  both.finger_joints = {"left_proximal_joint"};
  softgrasp_tests::expect_input_error(
      "finger joints and closing actuators both given",
      [&] { GraspSimulation simulation(both, log); },
      {"both given", "set Finger joints ="});

  auto opens              = ua;
  opens.closing_actuators = {"-grip"};
  softgrasp_tests::expect_input_error(
      "a closing sign that opens the gripper",
      [&] { run(opens, log); },
      {"actuator '-grip'",
       "the opposite target brings its links onto it",
       "the closing sign opens the hand",
       "write 'grip'"});

  auto far             = ua;
  far.base_position[2] = 0.3;
  softgrasp_tests::expect_input_error("a hand too far from the object",
                                      [&] { run(far, log); },
                                      {"actuator 'grip'",
                                       "neither does the opposite target",
                                       "the hand cannot reach the object",
                                       "'Rigid environment/Base position'"});

  // The jaw gripper with a pad MuJoCo cannot load, and with an open pad.
  const std::string pad_mesh =
      "          face=\"0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4\n"
      "                1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7\"/>";
  std::string text    = shipped(jaw_hand);
  const auto  start   = text.find("<mesh name=\"pad\"");
  const auto  end     = text.find("/>", start) + 2;
  auto        missing = jaw;
  missing.scene_file  = variant(
      "missing_pad",
      text.replace(
          start, end - start, "<mesh name=\"pad\" file=\"no_such_pad.stl\"/>"),
      jaw_hand);
  softgrasp_tests::expect_input_error(
      "a pad mesh file MuJoCo cannot read",
      [&] { GraspSimulation simulation(missing, log); },
      {"MuJoCo could not load", "no_such_pad.stl"});
  auto open       = jaw;
  open.scene_file = variant(
      "open_pad",
      edited(shipped(jaw_hand),
             pad_mesh,
             "          face=\"0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4\n"
             "                1 2 6  1 6 5  2 3 7  2 7 6  3 0 4\"/>"),
      jaw_hand);
  softgrasp_tests::expect_input_error(
      "an open pad mesh",
      [&] { GraspSimulation simulation(open, log); },
      {"hand geom 'left_pad'", "is not closed", "close the holes"});
}
