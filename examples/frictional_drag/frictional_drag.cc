/* ---------------------------------------------------------------------------
 * Example: a finger dragged across soft tissue, with friction
 *
 * A rescue robot's finger that pulls on a limb presses into the tissue and
 * drags it along. This example presses a rigid cylinder (a finger link,
 * R = 10 mm) 5 mm into a soft block bonded to a rigid base (plane strain)
 * and pulls it 20 mm along the surface with Coulomb friction mu = 0.5.
 *
 * What it shows:
 *  - 'Time/Integrator = implicit dynamic': the quasi-static solver stops on
 *    this drag after 8.5 mm of pull, where a contact node at the trailing
 *    edge has to snap from stick to slip and no static state is near; with
 *    inertia (backward Euler) the step is cut back, the node moves through
 *    and the run goes on quasi-statically (doc/contact.md).
 *  - The contact force on every geom, split with the patch's mean normal n
 *    into the normal force and the lateral (drag) force, and the lateral
 *    force split again into friction alone and the rest: the pressure of
 *    tissue heaped ahead of the finger. The drag exceeds mu times the
 *    normal force although no node exceeds Coulomb's cone.
 *  - A picture of the forces over time (drag_forces.png) and the numbers
 *    (drag_forces.dat, and the solver's own CSV/HDF5 and VTU files).
 *
 * The report names whatever bodies and geoms the .prm defines, so the
 * program runs any drag (2D or 3D) set up in a .prm.
 *
 * Run:   ./frictional_drag [frictional_drag.prm]
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
  program.default_parameter_file = "frictional_drag.prm";
  program.name                   = "frictional_drag";
  program.report_2d              = [](const softgrasp::Simulation<2> &solver)
  { softgrasp::report_contact_forces(solver, "drag_forces", std::cout); };
  program.report_3d = [](const softgrasp::Simulation<3> &solver)
  { softgrasp::report_contact_forces(solver, "drag_forces", std::cout); };
  return program.run(argc, argv);
}
