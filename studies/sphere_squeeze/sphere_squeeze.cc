/* ---------------------------------------------------------------------------
 * Study: a rubber sphere squeezed by the three-finger hand.
 *
 * The first study of the framework, end to end:
 *  1. MuJoCo (the rigid environment) closes the hand of
 *     parameter-files/mjcf/sphere_scene.xml around a free rigid sphere of
 *     radius 40 mm until the grasp is in equilibrium, then records the
 *     fingers closing further by an extra joint angle, through MuJoCo's
 *     forward kinematics, together with MuJoCo's own contact forces at the
 *     same actuator targets (the kinematics file);
 *  2. the finite element solver places a rubber sphere (a neo-Hookean or
 *     Mooney-Rivlin shell on a rigid core that holds it) where MuJoCo's
 *     sphere was at the equilibrium state and drives the same capsule
 *     links into it along the recorded poses, with mortar contact and
 *     Coulomb friction, until the extra angle is used up or a target normal
 *     force on a chosen link is reached (the indented state).
 *
 * Output (sphere_squeeze_output/): kinematics.h5; sphere.pvd with e_max on
 * the deformed sphere; sphere_links.csv with per-link normal, lateral and
 * friction-only forces from the finite elements next to MuJoCo's at the
 * same closure; sphere_contact.csv/.h5 with every geom's force;
 * sphere_picture.png (the indented sphere coloured by e_max with the finger
 * capsules) and sphere_forces.png (force against closure per link).
 *
 * Run:   ./sphere_squeeze [sphere_squeeze.prm]
 *        mpirun -np 2 ./sphere_squeeze
 * See doc/studies.md.
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <softgrasp/mujoco/grasp_study_program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp::GraspStudyProgram             program;
  program.default_parameter_file = "sphere_squeeze.prm";
  program.name                   = "sphere_squeeze";
  return program.run(argc, argv);
}
