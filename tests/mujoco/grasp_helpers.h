// Shared set-up of the MuJoCo bridge tests: the sphere scene's grasp
// parameters from parameter-files/sphere_squeeze.prm.
#ifndef softgrasp_tests_grasp_helpers_h
#define softgrasp_tests_grasp_helpers_h

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

  inline softgrasp::GraspParameters
  sphere_grasp_parameters(dealii::ParameterHandler &prm)
  {
    softgrasp::GraspParameters p;
    p.parse_parameters(prm, PARAMETER_FILES);
    return p;
  }
} // namespace softgrasp_tests

#endif
