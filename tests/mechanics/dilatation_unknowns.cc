// The element pressure and dilatation of the mixed u-p-J formulation as
// Newton unknowns (DilatationState, doc/solver.md): the cube compressed
// 20 % between bonded platens (tests/solver_factory.h), Q2-P1,
// nu = 0.4999, in 10 load steps of 2 %.
//  - Direct solver: every step converges without a cut-back in at most 4
//    Newton iterations (with p~ projected from the trial displacement
//    each step took 6-8: p~ overshot by kappa times the second-order
//    volume change of the first trial state).
//  - The converged state does not depend on the path: the platen force
//    equals that of 40 steps of 0.5 % within 1e-7.
//  - Iterative solver with the block preconditioner: no step is cut back
//    (before, the second Newton iterate of every 2 % step made the
//    displacement block indefinite and the Krylov solve stagnated), and
//    the force is the direct solver's.
#include "../solver_factory.h"
#include "../tests.h"

#include <deal.II/base/logstream.h>
#include <algorithm>

using namespace softgrasp_tests;

namespace
{
  struct Run
  {
    double       force      = 0; ///< platen reaction at the end (N)
    double       max_newton = 0; ///< most Newton iterations of a step
    double       cut_backs  = 0; ///< over the run
    unsigned int steps      = 0;
  };

  Run compress(const std::string &solver, const bool block, const double dt)
  {
    std::string prm =
        compressed_block_prm(4, 2, 0.4999, solver, block, "dilatation_output");
    prm += "subsection Time\n set Time step = " + std::to_string(dt) +
           "\nend\n";
    auto s = make_solver<3>(prm);
    s->run();
    const auto &history = s->history();
    Run         run;
    run.steps = history.rows.size() - 1;
    run.force = history.value(run.steps, "reaction_5_z");
    for (std::size_t r = 1; r < history.rows.size(); ++r)
    {
      run.max_newton =
          std::max(run.max_newton, history.value(r, "newton_iterations"));
      run.cut_backs += history.value(r, "cut_backs");
    }
    return run;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const Run direct = compress("direct", false, 0.1);
  dealii::deallog << "direct, 10 steps: platen force " << direct.force
                  << " N, " << direct.cut_backs
                  << " cut-backs, at most " << direct.max_newton
                  << " Newton iterations per step" << std::endl;
  SG_CHECK(direct.cut_backs == 0 && direct.steps == 10,
           "a 2 % step of the nearly incompressible cube was cut back");
  SG_CHECK(direct.max_newton <= 4,
           "Newton needs more than 4 iterations for a 2 % step");

  const Run fine = compress("direct", false, 0.025);
  dealii::deallog << "direct, 40 steps: platen force " << fine.force << " N"
                  << std::endl;
  SG_CHECK(close(direct.force, fine.force, 1e-7),
           "the converged state depends on the load increment");

  const Run block = compress("iterative", true, 0.1);
  dealii::deallog << "block preconditioner, 10 steps: " << block.cut_backs
                  << " cut-backs, force as the direct solver's" << std::endl;
  SG_CHECK(block.cut_backs == 0,
           "the block-preconditioned solve stalled and a step was cut back");
  SG_CHECK(close(block.force, direct.force, 1e-6),
           "the block-preconditioned and the direct solver disagree");
}
