// The softgrasp program: runs any problem a .prm file describes and reports
// the contact forces on every rigid body and geom. See doc/softgrasp.md.

#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/solvers/simulation.h>
#include <softgrasp/solvers/solver_program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  softgrasp::SolverProgram program;
  program.name = "softgrasp";
  // any problem a .prm describes: the solver examples' files too
  program.reads_files_of = {"block_compression",
                            "cook_membrane",
                            "frictional_drag",
                            "hertz_indentation",
                            "ironing"};
  program.report_2d      = [](const softgrasp::Simulation<2> &solver)
  { softgrasp::report_contact_forces(solver, "contact_forces", std::cout); };
  program.report_3d = [](const softgrasp::Simulation<3> &solver)
  { softgrasp::report_contact_forces(solver, "contact_forces", std::cout); };
  return program.run(argc, argv);
}
