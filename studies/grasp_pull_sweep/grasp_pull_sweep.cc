/* ---------------------------------------------------------------------------
 * Study: the grasp-and-pull sweep (the source paper's second case study).
 * At grip levels from the equilibrium grip to the indented-state grip (a
 * normal force on the thumb's proximal link), the three-finger hand pulls
 * 2 cm along the upper arm; the lateral force it meets, against the grip,
 * in the rigid simulator (MuJoCo) and on the finite element arm.
 *
 * Run:   ./grasp_pull_sweep [grasp_pull_sweep.prm]
 * See doc/studies.md.
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <softgrasp/mujoco/grasp_pull_sweep.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return softgrasp::GraspPullSweep::main(argc, argv);
}
