/* ---------------------------------------------------------------------------
 * mujoco_grasp: the rigid-environment program.
 *
 * MuJoCo 2.2 closes the three-finger hand of a scene around the object to
 * the equilibrium grasp and records the indentation (and pull) phases into
 * the kinematics file (doc/kinematics_file.md) that the finite element
 * studies read. It reads the same .prm as the studies ("Rigid environment"
 * and "Indentation study/Kinematics file"); everything else in it is
 * checked but not used.
 *
 * Run:   ./mujoco_grasp [sphere_squeeze.prm]
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <softgrasp/mujoco/grasp_study_program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp::GraspStudyProgram             program;
  program.default_parameter_file = "sphere_squeeze.prm";
  program.name                   = "mujoco_grasp";
  // it runs the rigid stage of sphere_squeeze's files (the arm studies
  // build their scene from 'Arm scene', which only they read)
  program.reads_files_of = {"sphere_squeeze"};
  program.rigid_only     = true;
  return program.run(argc, argv);
}
