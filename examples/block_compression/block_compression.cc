/* ---------------------------------------------------------------------------
 * Example: compression of a nearly incompressible block
 *
 * Soft tissue is nearly incompressible (nu close to 0.5). Pure displacement
 * elements then lock: the volume constraint J = 1 at every quadrature point
 * leaves almost no admissible deformations, and the mesh answers far too
 * stiffly. This example compresses a neo-Hookean block with nu = 0.4999 by
 * 30 % between two bonded platens with the mixed u-p-J formulation (Q2
 * displacement, element-wise linear discontinuous pressure and dilatation),
 * which stays free of locking. Its sides bulge out; the volume is
 * preserved.
 *
 * The .prm file shows
 *  - a generated block mesh with boundary ids 0..5 on its faces
 *    (x min/max, y min/max, z min/max);
 *  - Dirichlet conditions per boundary id, with time-dependent expressions;
 *  - the sparse direct solver ("Linear solver/Type"): the iterative AMG
 *    solver needs many iterations at nu = 0.4999 (see doc/solver.md);
 *  - checkpoints at every step: kill the run (Ctrl-C or SIGKILL) and restart
 *    it with "set Resume = true" in subsection Checkpoint; it continues from
 *    the last completed step and reaches the same final state.
 *
 * Output (block_compression_output/): block_history.csv with the platen
 * force and the side bulge per step, block.pvd/.vtu with the displacement,
 * principal strains and Cauchy stress on the deformed block.
 *
 * Run:   ./block_compression [block_compression.prm]
 *        mpirun -np 2 ./block_compression
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
  program.default_parameter_file = "block_compression.prm";
  program.name                   = "block_compression";
  program.report_3d              = [](const softgrasp::Simulation<3> &solver)
  {
    const auto       &history = solver.history();
    const std::size_t last    = history.rows.size() - 1;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "\nPlaten force at 30 % compression: "
                << -history.value(last, "reaction_5_z")
                << " N; bulge of the side face centre: "
                << history.value(last, "u0_x") * 1e3 << " mm." << std::endl;
  };
  return program.run(argc, argv);
}
