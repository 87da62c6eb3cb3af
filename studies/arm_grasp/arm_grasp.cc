/* ---------------------------------------------------------------------------
 * Study: the three-finger hand grasps a human upper arm (the source paper's
 * first case study), on softgrasp's open layered arm.
 *
 *  1. MuJoCo closes the hand of parameter-files/mjcf/three_finger_hand.xml
 *     on a rigid arm made from the layered limb's own geometry (the
 *     equilibrium state) and records the fingers closing further;
 *  2. the finite element solver places the layered limb (skin, fat, fascia,
 *     muscle on the humerus) at the arm's recorded pose and drives the same
 *     finger links into it until a target normal force on the thumb's
 *     proximal link (the indented state).
 *
 * Run:   ./arm_grasp [arm_grasp.prm]
 *        mpirun -np 2 ./arm_grasp
 * See doc/studies.md.
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/mujoco/grasp_study_program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp::GraspStudyProgram             program;
  program.default_parameter_file = "arm_grasp.prm";
  program.name                   = "arm_grasp";
  program.declare_study_parameters =
      &softgrasp::ArmGraspStudy::declare_parameters;
  program.make_study = [](MPI_Comm comm, dealii::ParameterHandler &prm)
  {
    return std::unique_ptr<softgrasp::IndentationStudy>(
        std::make_unique<softgrasp::ArmGraspStudy>(comm, prm));
  };
  return program.run(argc, argv);
}
