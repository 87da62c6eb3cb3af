#include <filesystem>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/mujoco/grasp_parameters.h>

namespace softgrasp
{
  using namespace dealii;

  // Longer than 80 lines on purpose: one declare_entry after another, in
  // the order of the .prm and its documentation, reads as a table.
  void GraspParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid environment");
    {
      prm.declare_entry("Scene file",
                        "mjcf/sphere_scene.xml",
                        Patterns::FileName(),
                        "MuJoCo MJCF scene with the hand and the object; "
                        "relative to the parameter file's directory.");
      prm.declare_entry("Object body",
                        "object",
                        Patterns::Anything(),
                        "Body of the grasped object in the scene.");
      prm.declare_entry("Hand base body",
                        "hand_base",
                        Patterns::Anything(),
                        "Body of the hand's base (palm) in the scene.");
      prm.declare_entry("Base position",
                        "0, 0, 0.052",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "World position of the hand base. Unit: m.");
      prm.declare_entry("Base orientation",
                        "1, 0, 0, 0",
                        Patterns::List(Patterns::Double(), 4, 4),
                        "World orientation of the hand base as a quaternion "
                        "w, x, y, z (normalised on reading). Unit: 1.");
      prm.declare_entry(
          "Finger joints",
          "",
          Patterns::List(Patterns::Anything(), 0),
          "Joints that close the hand, each driven by its own position "
          "actuator whose positive target closes: hinges (a finger), or "
          "slide joints (a parallel jaw), all of one type. Leave empty when "
          "'Closing actuators' names the actuators instead.");
      prm.declare_entry(
          "Closing actuators",
          "",
          Patterns::List(Patterns::Anything(), 0),
          "Position actuators that close the hand, each with the joints it "
          "moves: its joint, or the joints of its <fixed> tendon, and every "
          "joint an <equality joint=...> couples to them (one actuator may "
          "close a whole underactuated gripper). Write '-name' for an "
          "actuator whose target closes the hand as it decreases. Each "
          "target ramps at the closing speed until every joint it moves has "
          "a link of its subtree on the object; closures are in the "
          "actuator's length (gear x joint coordinate, or tendon length). "
          "Empty: 'Finger joints' closes the hand.");
      prm.declare_entry(
          "Closing keyframe",
          "",
          Patterns::Anything(),
          "Name of a <keyframe> of the scene whose ctrl holds the closed "
          "hand's targets: every position servo (but the pull's) whose "
          "target there differs from its length at rest closes the hand, in "
          "the direction of that difference, as if named in 'Closing "
          "actuators'. Only the direction is used: each target ramps until "
          "touch as for 'Closing actuators'. Empty: not used.");
      prm.declare_entry(
          "Contact links",
          "",
          Patterns::List(Patterns::Anything(), 0),
          "Geoms that must touch the object at the equilibrium grasp; "
          "empty: none is required, and the run reports every geom of the "
          "hand that touches it.");
      prm.declare_entry("Closing speed",
                        "0.5",
                        Patterns::Double(0),
                        "Rate at which the actuator targets close until "
                        "each joint's link touches. Unit: rad/s (m/s for "
                        "slide finger joints).");
      prm.declare_entry("Grip",
                        "0.1",
                        Patterns::Double(0),
                        "Grip tightness: actuator target beyond the angle "
                        "of first touch. Unit: rad (m for slide finger "
                        "joints).");
      prm.declare_entry("Velocity tolerance",
                        "1e-3",
                        Patterns::Double(0),
                        "Equilibrium: every joint speed below this. Unit: "
                        "m/s for slide and free-joint translation, rad/s "
                        "for rotation.");
      prm.declare_entry("Force tolerance",
                        "1e-3",
                        Patterns::Double(0),
                        "Equilibrium: the link forces change by less than "
                        "this fraction of the largest over a window. Unit: "
                        "1.");
      prm.declare_entry("Settle window",
                        "0.05",
                        Patterns::Double(0),
                        "Window over which force changes are measured. "
                        "Unit: s.");
      prm.declare_entry("Maximum time",
                        "10",
                        Patterns::Double(0),
                        "Simulated time allowed to reach the equilibrium "
                        "grasp. Unit: s.");
      prm.declare_entry("Sample interval",
                        "0.01",
                        Patterns::Double(0),
                        "Time between recorded samples while closing. Unit: "
                        "s.");
      prm.enter_subsection("Indentation");
      {
        prm.declare_entry("Extra joint angle",
                          "0.2",
                          Patterns::Double(0),
                          "Closure beyond the equilibrium state added to "
                          "every finger joint. Unit: rad (m for slide "
                          "finger joints).");
        prm.declare_entry("Joint weights",
                          "",
                          Patterns::List(Patterns::Double(0)),
                          "Per finger joint (in the order of 'Finger "
                          "joints'), the fraction of the extra joint angle "
                          "it closes, e.g. 1, 0, 1, 0, 1, 0 to close the "
                          "proximal joints only; empty: 1 for every joint. "
                          "Unit: 1.");
        prm.declare_entry("Samples",
                          "10",
                          Patterns::Integer(1),
                          "Steps of the closure recorded. Unit: 1.");
        prm.declare_entry("Duration",
                          "1",
                          Patterns::Double(0),
                          "Pseudo-time of the phase in the file. Unit: s.");
        prm.declare_entry("Settle time",
                          "1",
                          Patterns::Double(0),
                          "MuJoCo time allowed per sample to settle the "
                          "rigid grasp at the new targets. Unit: s.");
      }
      prm.leave_subsection();
      prm.enter_subsection("Pull");
      {
        prm.declare_entry("Slide joint",
                          "pull",
                          Patterns::Anything(),
                          "Slide joint of the hand base with a position "
                          "actuator.");
        prm.declare_entry("Axis",
                          "1, 0, 0",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "World direction of the pull (normalised). Unit: "
                          "1.");
        prm.declare_entry("Distance",
                          "0",
                          Patterns::Double(0),
                          "Pull distance after the indentation; 0: no pull "
                          "phase. Unit: m.");
        prm.declare_entry(
            "Duration", "1", Patterns::Double(0), "Time of the pull. Unit: s.");
        prm.declare_entry("Samples",
                          "10",
                          Patterns::Integer(1),
                          "Samples recorded during the pull. Unit: 1.");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  namespace
  {
    std::vector<std::string> names(const std::string &list)
    {
      return Utilities::split_string_list(list, ',');
    }
  } // namespace

  void GraspParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &base_directory)
  {
    prm.enter_subsection("Rigid environment");
    const CheckedSection section(prm, "Rigid environment");
    scene_file = prm.get("Scene file");
    if (!scene_file.empty() && scene_file[0] != '/' && !base_directory.empty())
      scene_file =
          (std::filesystem::path(base_directory) / scene_file).string();
    RunManifest::protect_input(scene_file);
    object_body    = prm.get("Object body");
    base_body      = prm.get("Hand base body");
    const auto p   = section.get_number_list("Base position");
    base_position  = {p[0], p[1], p[2]};
    const auto q   = section.get_number_list("Base orientation");
    const auto raw = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    if (raw.norm() < 1e-12)
      throw InputError("'Rigid environment/Base orientation' is a zero "
                       "quaternion. Fix: give w, x, y, z of a rotation, e.g. "
                       "1, 0, 0, 0.");
    base_orientation   = raw.normalized();
    finger_joints      = names(prm.get("Finger joints"));
    closing_actuators  = names(prm.get("Closing actuators"));
    closing_keyframe   = prm.get("Closing keyframe");
    contact_links      = names(prm.get("Contact links"));
    closing_speed      = section.get_positive("Closing speed", "rad/s");
    grip               = section.get_positive("Grip", "rad", true);
    velocity_tolerance = section.get_positive("Velocity tolerance", "m/s");
    force_tolerance    = section.get_positive("Force tolerance", "1");
    settle_window      = section.get_positive("Settle window", "s");
    maximum_time       = section.get_positive("Maximum time", "s");
    sample_interval    = section.get_positive("Sample interval", "s");
    prm.enter_subsection("Indentation");
    {
      const CheckedSection s(prm, "Rigid environment/Indentation");
      indentation.extra_angle = s.get_positive("Extra joint angle", "rad");
      indentation.samples     = prm.get_integer("Samples");
      indentation.joint_weights.clear();
      for (const auto &w :
           Utilities::split_string_list(prm.get("Joint weights")))
        indentation.joint_weights.push_back(Utilities::string_to_double(w));
      const std::size_t drives = closing_actuators.empty()
                                     ? finger_joints.size()
                                     : closing_actuators.size();
      // (a keyframe's drives are known once the scene is loaded)
      if (!indentation.joint_weights.empty() && closing_keyframe.empty() &&
          indentation.joint_weights.size() != drives)
        throw InputError(
            "'Rigid environment/Indentation/Joint weights' has " +
            std::to_string(indentation.joint_weights.size()) + " values for " +
            std::to_string(drives) +
            " drives. Fix: give one weight per entry of 'Closing actuators' "
            "(or 'Finger joints' if that is empty), or none.");
      indentation.duration    = s.get_positive("Duration", "s");
      indentation.settle_time = s.get_positive("Settle time", "s");
    }
    prm.leave_subsection();
    prm.enter_subsection("Pull");
    {
      const CheckedSection s(prm, "Rigid environment/Pull");
      pull.slide_joint = prm.get("Slide joint");
      const auto a     = s.get_number_list("Axis");
      pull.axis        = {a[0], a[1], a[2]};
      if (pull.axis.norm() < 1e-12)
        throw InputError("'Rigid environment/Pull/Axis' is zero. Fix: give "
                         "the world direction of the pull, e.g. 1, 0, 0.");
      pull.axis.normalize();
      pull.distance = s.get_positive("Distance", "m", true);
      pull.duration = s.get_positive("Duration", "s");
      pull.samples  = prm.get_integer("Samples");
    }
    prm.leave_subsection();
    prm.leave_subsection();
  }
} // namespace softgrasp
