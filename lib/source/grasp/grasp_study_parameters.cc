#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/grasp/indentation_study.h>

namespace softgrasp
{
  using namespace dealii;

  void GraspStudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Indentation study");
    prm.declare_entry("Kinematics file",
                      "kinematics.h5",
                      Patterns::FileName(),
                      "HDF5 kinematics file of the rigid-body simulator "
                      "(doc/kinematics_file.md), relative to "
                      "'Output/Directory'.");
    prm.declare_entry("Rigid stage",
                      "run",
                      Patterns::Selection("run|read"),
                      "run: simulate the grasp with MuJoCo first and write "
                      "the kinematics file; read: use the kinematics file "
                      "as it is (no MuJoCo needed).");
    prm.declare_entry("Object body",
                      "object",
                      Patterns::Anything(),
                      "Body of the grasped object in the kinematics file; "
                      "the tissue mesh, given in that body's frame, is "
                      "placed at its recorded pose at the start of the "
                      "first phase.");
    prm.declare_entry("Tissue placement",
                      "pose",
                      Patterns::Selection("pose|position"),
                      "pose: the mesh follows the object body's position "
                      "and orientation; position: its position only (the "
                      "mesh keeps the world's axes, e.g. for a ball).");
    prm.declare_entry("Phases",
                      "indentation",
                      Patterns::List(Patterns::Anything(), 1),
                      "The recorded phases of the kinematics file to run, "
                      "in order (e.g. indentation, pull); each must follow "
                      "the one before. Time 0 of the run is the start of "
                      "the first.");
    prm.declare_entry("Target link",
                      "",
                      Patterns::Anything(),
                      "Link (body/geom, e.g. thumb_proximal/"
                      "thumb_proximal_link) whose normal force ends the "
                      "run at 'Target normal force'; empty: none.");
    prm.declare_entry("Target normal force",
                      "0",
                      Patterns::Double(0),
                      "Normal force on the target link that ends the run; "
                      "0: run the whole recorded phases. Unit: N.");
    prm.declare_entry("Pictures",
                      "true",
                      Patterns::Bool(),
                      "Write the PNG picture of the indented body and the "
                      "PNG force plot (needs gnuplot).");
    InjuryThresholds::declare_parameters(prm);
    prm.leave_subsection();
  }

  void GraspStudyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Indentation study");
    const CheckedSection section(prm, "Indentation study");
    kinematics_file = prm.get("Kinematics file");
    run_rigid_stage = prm.get("Rigid stage") == "run";
    if (!run_rigid_stage) // read, not written: an input of the run
      RunManifest::protect_input(kinematics_file);
    object_body = Utilities::trim(prm.get("Object body"));
    placement = prm.get("Tissue placement") == "position" ? Placement::position
                                                          : Placement::pose;
    phases    = Utilities::split_string_list(prm.get("Phases"));
    target_link  = Utilities::trim(prm.get("Target link"));
    target_force = section.get_positive("Target normal force", "N", true);
    pictures     = prm.get_bool("Pictures");
    injury.parse_parameters(prm, "Indentation study");
    prm.leave_subsection();
    if (target_force > 0 && target_link.empty())
      throw InputError("'Indentation study/Target normal force' is set but "
                       "'Target link' is empty. Fix: name the link as "
                       "body/geom, or set the force to 0.");
  }
} // namespace softgrasp

namespace
{
  // A file with this subsection given to another program names its program.
  // (The rigid stage's subsection is read by the same programs, and by
  // mujoco_grasp, which runs that stage alone.)
  [[maybe_unused]] const bool softgrasp_program_sections =
      softgrasp::ParameterReader::register_program_section(
          "Indentation study",
          "a grasp study (sphere_squeeze, arm_grasp or grasp_pull_sweep)") &&
      softgrasp::ParameterReader::register_program_section(
          "Rigid environment",
          "a grasp study (sphere_squeeze, arm_grasp, grasp_pull_sweep or "
          "mujoco_grasp)");
} // namespace
