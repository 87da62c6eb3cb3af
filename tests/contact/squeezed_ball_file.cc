// A rubber ball squeezed by a plate (the shipped squeezed_ball.prm, an
// octant model) on meshes read from Gmsh files, as a user's mesher writes
// them: straight-sided cells with their vertices on the sphere. Without
// manifolds the quadratic elements see a polyhedron and the plate force is
// low; with 'Mesh/File/Manifolds' the geometry is the true sphere, and a
// coarser file refined once by softgrasp gives the generated curved mesh's
// plate force within 0.1 % (the surfaces are the same; the transfinite
// interior blends over the file's smaller coarse cells, so interior nodes
// differ slightly). The files are written here from the ball
// generator's octant, refined once (32 cells) or twice (256 cells, four
// cells per 45 degrees).
#include "../solver_factory.h"
#include "../tests.h"
#include "problem_file.h"

using namespace softgrasp_tests;

namespace
{
  /// The plate force (N) at the end of the squeeze with @p mesh entries.
  double plate_force(const std::string &mesh, const std::string &directory)
  {
    // a file mesh: the ball generator's entries would be refused
    const std::string base =
        mesh.empty()
            ? problem("squeezed_ball.prm", "")
            : without_subsection(problem("squeezed_ball.prm", ""), "Ball");
    auto solver =
        make_solver<3>(base + "subsection Mesh\n" + mesh +
                       "end\nsubsection Output\n set Directory = " + directory +
                       "\n set VTU interval = 0\n set Verbose = false\nend\n");
    solver->run();
    return solver->contact_force_history().back().forces[0][0].normal_force();
  }

} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    write_ball_octant(1, "octant_32.msh");
    write_ball_octant(2, "octant_256.msh");
  }
  MPI_Barrier(MPI_COMM_WORLD);

  // The shipped file: the generated octant refined twice (256 cells).
  const double generated = plate_force("", "out-generated");
  const double refined   = plate_force(
      ball_octant_file_mesh("octant_32.msh", 1, true), "out-curved");
  const double flat = plate_force(
      ball_octant_file_mesh("octant_256.msh", 0, false), "out-flat");
  dealii::deallog << "plate force: generated curved mesh " << generated
                  << " N; 32-cell file with manifolds, refined once " << refined
                  << " N; 256-cell file without manifolds " << flat << " N ("
                  << 100 * (flat / generated - 1) << " %)" << std::endl;
  dealii::deallog << "file with manifolds within 0.1 % of the generated mesh: "
                  << (std::abs(refined / generated - 1) < 1e-3)
                  << "; file without manifolds more than 2 % low: "
                  << (flat < 0.98 * generated) << std::endl;
  SG_CHECK(std::abs(refined / generated - 1) < 1e-3,
           "a file mesh with manifolds refines into the generated mesh");
  SG_CHECK(flat < 0.98 * generated,
           "without manifolds the polyhedron is softer by more than 2 %");
}
