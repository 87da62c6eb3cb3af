// What happens to a step of the incremental potential whose outer
// iterations have not settled ('Contact/Unsettled steps'), on the deep
// plane-strain drag of contact/drag_potential (40 x 8 cells, mu = 0.5)
// pressed 10 mm and pulled 2 mm with at most 2 outer iterations per step,
// fewer than friction needs to settle:
//  - 'accept' (the default): the run ends; the steps kept unsettled are
//    flagged in the history ('unsettled') with their Coulomb excess
//    against the current normal forces ('coulomb_excess', above the
//    settle tolerance where they are);
//  - 'cut back': the same run stops with an error naming the outer
//    iterations, the setting and the fix, after its cut-backs.
// And the polish ('Contact/Polish after'): the same pull with up to 30
// outer iterations, every step polished after its first lagged solve
// (Newton with friction against the current normal forces) against the
// lagged iterations settled without it: the same forces on the cylinder
// at every step (within 1e-3 of the normal force, the settle tolerance),
// Coulomb's law exactly at the polished steps.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  std::string prm(const std::string &unsettled,
                  const unsigned int max_outer    = 2,
                  const unsigned int polish_after = 10)
  {
    return frictional_drag_prm(0.5) +
           "subsection Mesh\n subsection Block\n  set Subdivisions = 40, 8\n"
           " end\nend\n"
           "subsection Rigid bodies\n subsection Body finger\n"
           "  set Trajectory = 0: -0.01, 0.0305, 0, 1, 0, 0, 0; "
           "0.5: -0.01, 0.0205, 0, 1, 0, 0, 0; 0.6: -0.008, 0.0205, 0, 1, 0, "
           "0, 0\n end\nend\n"
           // the polish is node-wise (the implicit default is the faces)
           "subsection Contact\n set Enforcement = incremental potential\n"
           " set Potential integration = nodes\n"
           " set Maximum outer iterations = " +
           std::to_string(max_outer) +
           "\n set Polish after = " + std::to_string(polish_after) +
           "\n set Unsettled steps = " + unsettled +
           "\nend\n"
           "subsection Time\n set Integrator = quasi-static\n"
           " set End time = 0.6\n set Time step = 0.025\n"
           " set Maximum cut-backs = 2\nend\n"
           "subsection Output\n set Directory = output-unsettled\n"
           " set VTU interval = 0\n set Verbose = false\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);

  auto accept = make_solver<2>(prm("accept"));
  accept->run();
  const auto  &history   = accept->history();
  unsigned int unsettled = 0;
  double       excess    = 0; // the largest of the unsettled steps
  for (std::size_t row = 1; row < history.rows.size(); ++row)
  {
    const bool flagged = history.value(row, "unsettled") > 0;
    unsettled += flagged;
    if (flagged)
      excess = std::max(excess, history.value(row, "coulomb_excess"));
    SG_CHECK(history.value(row, "outer_iterations") <= 2,
             "at most the allowed outer iterations");
  }
  const double end = history.value(history.rows.size() - 1, "time");
  dealii::deallog << "accept: the run ends " << (end > 0.6 - 1e-9)
                  << ", steps kept unsettled and flagged " << (unsettled > 0)
                  << ", their Coulomb excess recorded above 1e-3 "
                  << (excess > 1e-3) << std::endl;
  std::cout << unsettled << " unsettled steps, largest excess " << excess
            << std::endl;
  SG_CHECK(end > 0.6 - 1e-9, "the run ends");
  SG_CHECK(unsettled > 0, "unsettled steps are flagged");
  SG_CHECK(excess > 1e-3, "with the excess that made them unsettled");

  std::string message;
  try
  {
    make_solver<2>(prm("cut back"))->run();
  }
  catch (const std::exception &e)
  {
    message = e.what();
  }
  const bool named =
      message.find("did not settle in 2") != std::string::npos &&
      message.find("'Contact/Maximum outer iterations'") != std::string::npos;
  dealii::deallog << "cut back: the run stops naming the outer iterations "
                  << "and the setting " << named << std::endl;
  std::cout << message.substr(0, 300) << std::endl;
  SG_CHECK(named, "the error names the outer iterations and the fix");

  // the polish at every step against the lagged iterations alone
  auto lagged = make_solver<2>(prm("cut back", 30, 0));
  lagged->run();
  auto polished = make_solver<2>(prm("cut back", 30, 1));
  polished->run();
  const auto  &a     = lagged->contact_force_history();
  const auto  &b     = polished->contact_force_history();
  const auto  &h     = polished->history();
  double       worst = 0, worst_excess = 0;
  unsigned int n_polished = 0;
  for (std::size_t row = 1; row < std::min(a.size(), b.size()); ++row)
  {
    const auto &fa = a[row].forces[0][0];
    const auto &fb = b[row].forces[0][0];
    worst = std::max(worst, (fa.force - fb.force).norm() / fa.normal_force());
    if (h.value(row, "polished") > 0)
    {
      ++n_polished;
      worst_excess = std::max(worst_excess, h.value(row, "coulomb_excess"));
    }
  }
  dealii::deallog << "polish: as many steps " << (a.size() == b.size())
                  << ", steps polished " << (n_polished > 0)
                  << ", the same forces within 1e-3 of the normal force "
                  << (worst <= 1e-3) << ", Coulomb exactly where polished "
                  << (worst_excess <= 1e-12) << std::endl;
  std::cout << n_polished << " of " << b.size() - 1
            << " steps polished; largest force difference " << worst
            << " of the normal force; Coulomb excess " << worst_excess
            << std::endl;
  SG_CHECK(a.size() == b.size(), "both runs take the same steps");
  SG_CHECK(n_polished > 0, "the polish finishes steps");
  SG_CHECK(worst <= 1e-3, "the polish finds the lagged iterations' state");
  SG_CHECK(worst_excess <= 1e-12, "Coulomb's law exactly where polished");
}
