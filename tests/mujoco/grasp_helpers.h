// Shared set-up of the MuJoCo bridge tests: the sphere scene's grasp
// parameters from parameter-files/sphere_squeeze.prm, and the coarse arm of
// parameter-files/arm_grasp.prm.
#ifndef softgrasp_tests_grasp_helpers_h
#define softgrasp_tests_grasp_helpers_h

#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/mechanics/solver_program.h>
#include <softgrasp/mujoco/grasp_parameters.h>

namespace softgrasp_tests
{
  /// Declare a study's parameters and read the shipped sphere_squeeze.prm.
  inline void read_sphere_squeeze(dealii::ParameterHandler &prm)
  {
    softgrasp::GraspParameters::declare_parameters(prm);
    softgrasp::IndentationStudy::declare_parameters(prm);
    softgrasp::SolverProgram::read_parameters<3>(
        prm, PARAMETER_FILES "/sphere_squeeze.prm");
  }

  /// The shipped sphere_squeeze.prm one refinement coarser (1470
  /// displacement dofs), without pictures.
  inline void read_coarse_sphere_squeeze(dealii::ParameterHandler &prm)
  {
    read_sphere_squeeze(prm);
    prm.enter_subsection("Indentation study");
    prm.set("Pictures", false);
    prm.leave_subsection();
    prm.enter_subsection("Mesh");
    prm.set("Global refinements", "2");
    prm.leave_subsection();
  }

  /// Set @p entry of the subsection @p path (outermost first) of @p prm.
  inline void set(dealii::ParameterHandler       &prm,
                  const std::vector<std::string> &path,
                  const std::string              &entry,
                  const std::string              &value)
  {
    for (const auto &section : path)
      prm.enter_subsection(section);
    prm.set(entry, value);
    for (std::size_t i = 0; i < path.size(); ++i)
      prm.leave_subsection();
  }

  /// The shipped arm_grasp.prm on a coarse limb (16 cells around, no
  /// fascia: its thin cells set the explicit step), without pictures, a
  /// target force or VTU output, writing into @p directory.
  inline void read_coarse_arm(dealii::ParameterHandler &prm,
                              const std::string        &directory)
  {
    softgrasp::GraspParameters::declare_parameters(prm);
    softgrasp::ArmGraspStudy::declare_parameters(prm);
    softgrasp::SolverProgram::read_parameters<3>(
        prm, PARAMETER_FILES "/arm_grasp.prm");
    set(prm, {"Mesh", "Layered limb"}, "Circumferential cells", "16");
    set(prm, {"Mesh", "Layered limb"}, "Radial cells", "1, 1, 1, 2");
    set(prm, {"Mesh", "Layered limb"}, "Grasp zone cells", "4");
    set(prm, {"Mesh", "Layered limb"}, "Fascia thickness", "0");
    set(prm, {"Indentation study"}, "Pictures", "false");
    set(prm, {"Indentation study"}, "Target normal force", "0");
    set(prm, {"Output"}, "Directory", directory);
    set(prm, {"Output"}, "VTU interval", "0");
  }

  inline softgrasp::GraspParameters
  sphere_grasp_parameters(dealii::ParameterHandler &prm)
  {
    softgrasp::GraspParameters p;
    p.parse_parameters(prm, PARAMETER_FILES);
    return p;
  }
} // namespace softgrasp_tests

#endif
