/* ---------------------------------------------------------------------------
 * Example: ironing, a rigid cylinder dragged across soft tissue
 *
 * A finger that grips a limb and pulls does not only rub on the skin: it
 * indents the tissue and pushes a wave of it ahead. This 2D (plane strain)
 * example presses a rigid cylinder into a soft block and drags it along
 * the surface with Coulomb friction (mu = 0.3), the "ironing" benchmark of
 * contact mechanics.
 *
 * The .prm file shows
 *  - a 2D problem with a rigid geom (in 2D the plane z = 0 cuts the geoms:
 *    a cylinder along z is a circle);
 *  - a trajectory that first presses (t <= 0.2 s) and then drags;
 *  - friction: "Contact/Friction coefficient". Each contact node sticks or
 *    slips by Coulomb's law; slip is measured from the node's position at
 *    the end of the previous load step, so friction is path dependent.
 *
 * The contact force on the roller is written per step to
 * ironing_output/ironing_contact.csv. Besides the resultant F it holds its
 * split with the reference normal n (the mean normal of the contact patch):
 * the normal part (n n^T) F and the lateral part (I - n n^T) F, and, as a
 * separate column group, the integral of the frictional traction alone
 * (F_friction). The difference between the lateral part and the friction
 * part is the lateral force the tissue exerts through pressure on the
 * curved contact: what a rigid-body simulator cannot see.
 *
 * Run:   ./ironing [ironing.prm]
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/solvers/simulation.h>
#include <softgrasp/solvers/solver_program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  softgrasp::SolverProgram program;
  program.default_parameter_file = "ironing.prm";
  program.name                   = "ironing";
  program.report_2d              = [](const softgrasp::Simulation<2> &solver)
  { softgrasp::report_contact_forces(solver, "ironing_forces", std::cout); };
  program.report_3d = [](const softgrasp::Simulation<3> &solver)
  { softgrasp::report_contact_forces(solver, "ironing_forces", std::cout); };
  return program.run(argc, argv);
}
