/* ---------------------------------------------------------------------------
 * Example: Cook's membrane
 *
 * A tapered plate clamped on its left edge and sheared by a traction on its
 * right edge: the classic bending-dominated test of finite-strain elements
 * (Cook 1974; here the compressible neo-Hookean version of the deal.II code
 * gallery entry "Quasi-Static Finite-Strain Compressible Elasticity").
 *
 * Everything the program does is configured in cook_membrane.prm:
 *  - "Mesh": the membrane with vertices (0,0), (48,44), (48,60), (0,44) mm
 *    (coordinates in metres, like every length in softgrasp), 1 mm thick
 *    with one element through the thickness;
 *  - "Materials": a neo-Hookean material, mu = 422.5 kPa, nu = 0.3, with
 *    the Simo-Taylor volumetric energy kappa/4 (J^2 - 1 - 2 ln J);
 *  - "Boundary conditions": boundary id 0 (left) clamped, id 1 (right)
 *    loaded by 62.5 kPa upwards, i.e. 1 N on a 16 mm x 1 mm face; the load
 *    grows linearly with the pseudo-time t;
 *  - "Output/Monitor points": the corner (48, 60, 1) mm, whose displacement
 *    goes into cook_membrane_output/cook_history.csv at every step.
 *
 * The published reference values belong to this 3D plate with traction-free
 * front and back faces (see the comment in cook_membrane.prm);
 * cook_membrane_plane_strain.prm runs the plane-strain (2D) variant.
 *
 * Run:   ./cook_membrane [cook_membrane.prm | cook_membrane_plane_strain.prm]
 *        mpirun -np 2 ./cook_membrane
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/solvers/simulation.h>
#include <softgrasp/solvers/solver_program.h>

// Print the vertical displacement of the monitored corner next to a
// reference value (m).
template <int dim>
void
report_tip_displacement(const softgrasp::Simulation<dim> &solver,
                        const double                      reference,
                        const std::string                &label)
{
  const auto  &history = solver.history();
  const double uy      = history.value(history.rows.size() - 1, "u0_y");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "\nVertical displacement of the corner (48, 60) mm: "
              << uy * 1e3 << " mm; " << label << ": " << reference * 1e3
              << " mm; difference " << 100 * (uy - reference) / reference
              << " %." << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // The library's program driver reads the .prm (every parameter is
  // documented: ./cook_membrane --print-parameters), runs the quasi-static
  // solver, and turns bad input or a failed run into a clear message.
  softgrasp::SolverProgram program;
  program.default_parameter_file = "cook_membrane.prm";
  program.name                   = "cook_membrane";

  // After the run: compare the tip deflection with the published values
  // (3D) or the plane-strain limit (2D).
  program.report_2d = [](const softgrasp::Simulation<2> &solver) {
    report_tip_displacement(solver, 13.77e-3, "converged plane-strain value");
  };
  program.report_3d = [](const softgrasp::Simulation<3> &solver)
  {
    report_tip_displacement(
        solver,
        solver.parameters().discretization.degree == 2 ? 14.33e-3 : 14.32e-3,
        "published converged value");
  };
  return program.run(argc, argv);
}
