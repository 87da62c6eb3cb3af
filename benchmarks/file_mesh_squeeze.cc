// Benchmark (not a test) of curved geometry for file meshes: the shipped
// squeezed_ball.prm (rubber ball R = 20 mm squeezed 2 mm by a plate, octant,
// Q2-P1) on the ball generator's octant written as Gmsh files (straight
// cells, vertices on the sphere: 32 or 256 cells) and read back with and
// without 'Mesh/File/Manifolds', under uniform refinement, next to the
// generated curved mesh. Prints the plate force of the octant, DoFs and
// wall time per case.
//
//   file_mesh_squeeze <path to squeezed_ball.prm> [max refinements of the
//   256-cell meshes, default 1]
#include "../tests/contact/problem_file.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_out.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>

using namespace dealii;

namespace
{
  void run(const std::string &base,
           const std::string &label,
           const std::string &mesh)
  {
    ParameterHandler prm;
    softgrasp::Simulation<3>::declare_parameters(prm);
    softgrasp::ParameterReader reader;
    softgrasp::Simulation<3>::add_passes(reader);
    reader.read_string(prm,
                       base + "subsection Mesh\n" + mesh +
                           "end\nsubsection Output\n set Directory = "
                           "file_mesh_squeeze_output\n set VTU interval = 0\n"
                           " set Verbose = false\n set Existing results = "
                           "replace\nend\n",
                       "benchmark parameters");
    Timer timer;
    auto  solver = softgrasp::Simulation<3>::create(MPI_COMM_WORLD, prm);
    solver->run();
    const double force =
        solver->contact_force_history().back().forces[0][0].normal_force();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "| " << label << " | " << solver->system().n_dofs() << " | "
                << std::fixed << std::setprecision(3) << force << " | "
                << std::setprecision(0) << timer.wall_time() << " s |"
                << std::endl;
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
  {
    std::cerr << "Usage: file_mesh_squeeze <squeezed_ball.prm> [refinements]"
              << std::endl;
    return 1;
  }
  const std::string  base = softgrasp_tests::problem_text(argv[1]);
  const unsigned int max  = argc > 2 ? std::stoi(argv[2]) : 1;
  // the file meshes without the ball generator's entries (refused)
  const std::string file_base =
      softgrasp_tests::without_subsection(base, "Ball");
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    softgrasp_tests::write_ball_octant(1, "octant_32.msh");
    softgrasp_tests::write_ball_octant(2, "octant_256.msh");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  std::cout << "| mesh | DoFs | plate force (N) | wall time |\n"
            << "|---|---:|---:|---:|" << std::endl;
  for (unsigned int r = 0; r <= max; ++r)
  {
    const std::string level = std::to_string(r);
    run(base,
        "generated curved, refinements " + std::to_string(r + 2),
        " set Global refinements = " + std::to_string(r + 2) + "\n");
    run(file_base,
        "256-cell file, flat, refinements " + level,
        softgrasp_tests::ball_octant_file_mesh("octant_256.msh", r, false));
    run(file_base,
        "256-cell file, manifolds, refinements " + level,
        softgrasp_tests::ball_octant_file_mesh("octant_256.msh", r, true));
    run(file_base,
        "32-cell file, manifolds, refinements " + std::to_string(r + 1),
        softgrasp_tests::ball_octant_file_mesh("octant_32.msh", r + 1, true));
  }
}
