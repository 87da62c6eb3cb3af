// The shipped 3D deep drag, examples/frictional_drag/deep_drag_3d.prm (a
// capsule pressed 10 mm into a thick block and dragged 20 mm with mu = 0.5
// on the incremental potential), read from its file: its first 2 mm of
// press (the whole run takes about 10 minutes) with friction on the
// potential against the Lagrange multipliers on the same file (both
// node-wise: the multipliers have no face mode):
//  - the file parses and runs, the capsule presses (closed nodes, a normal
//    force), every step settles with Coulomb's law against the current
//    normal forces (excess at most 1e-3) and the potential never rose;
//  - the normal force and the force along the pull equal the multipliers'
//    within 1 % of the normal force.
#include "../solver_factory.h"
#include "../tests.h"
#include "problem_file.h"

using namespace softgrasp_tests;

namespace
{
  Eigen::Vector3d press(const std::string &enforcement)
  {
    auto run = make_solver<3>(problem_text(
        EXAMPLE_DIR "/frictional_drag/deep_drag_3d.prm",
        "subsection Contact\n set Enforcement = " + enforcement +
            "\n set Potential integration = nodes\n set Penalty factor = 100"
            "\nend\n"
            "subsection Time\n set End time = 0.1\n set Time step = 0.05\n"
            "end\n"
            "subsection Output\n set Directory = output-deep-drag\n"
            " set VTU interval = 0\n set Verbose = false\nend\n"));
    run->run();
    const auto &history = run->history();
    const auto  last    = history.rows.size() - 1;
    SG_CHECK(history.value(last, "contact_active_nodes") > 0,
             "the capsule presses the block");
    if (enforcement == "incremental potential")
      for (std::size_t row = 1; row <= last; ++row)
      {
        SG_CHECK(history.value(row, "unsettled") == 0, "every step settled");
        SG_CHECK(history.value(row, "coulomb_excess") <= 1e-3,
                 "Coulomb's law against the current normal forces");
        SG_CHECK(history.value(row, "energy_increases") == 0,
                 "the potential never rose");
      }
    return run->contact_force_history().back().forces[0][0].force;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  const Eigen::Vector3d lm     = press("lagrange multipliers");
  const Eigen::Vector3d ip     = press("incremental potential");
  const double          normal = std::abs(lm[2]);
  dealii::deallog << "deep_drag_3d.prm, 2 mm of press: normal force within "
                  << "1 % of the multipliers' "
                  << (std::abs(ip[2] - lm[2]) <= 0.01 * normal)
                  << ", force along the pull within 1 % of it "
                  << (std::abs(ip[0] - lm[0]) <= 0.01 * normal) << std::endl;
  std::cout << "normal force " << ip[2] << " N (multipliers " << lm[2]
            << " N), along the pull " << ip[0] << " N (multipliers " << lm[0]
            << " N)" << std::endl;
  SG_CHECK(normal > 0, "a normal force");
  SG_CHECK(std::abs(ip[2] - lm[2]) <= 0.01 * normal, "the normal force");
  SG_CHECK(std::abs(ip[0] - lm[0]) <= 0.01 * normal, "the force along x");
}
