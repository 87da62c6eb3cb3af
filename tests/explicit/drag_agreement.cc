// Both solvers on one frictional drag (issue 13, item 3; doc/contact.md):
// the plane-strain drag of examples/frictional_drag on 60 x 10 cells
// (cylinder R = 10 mm pressed 5 mm into a G = 17.2 kPa, nu = 0.45 block,
// pulled 20 mm at 20 mm/s), run by the implicit dynamic solver (0.5 mm of
// pull per step) and by the explicit solver with the stiffness damping
// advised for frictional sliding (0.3 of critical at the highest
// frequency; mass damping 50 1/s), both with node-wise contact. Checked:
//  - mu = 0.5: the normal force, the drag and the drag/normal ratio,
//    averaged over 8-20 mm of pull (where the contact slides), agree
//    within 2 %; the drag exceeds mu times the normal force in both
//    (ploughing);
//  - the explicit pull is quasi-static: its kinetic energy stays below 0.1 %
//    of its strain energy over the pull;
//  - mu = 0: the drag of both solvers is below 0.2 % of the normal force
//    (the frictionless drag along a uniform block is translation
//    invariant).
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  /// Means over 8-20 mm of pull, and the largest kinetic/strain energy
  /// ratio over the pull (explicit runs only).
  struct DragMeans
  {
    double normal       = 0; // N/m
    double drag         = 0; // N/m
    double kinetic      = 0; // largest E_kin / E_strain during the pull
    double kinetic_time = 0; // s, where it is largest
  };

  DragMeans run_drag(const double mu, const bool explicit_solver)
  {
    std::ostringstream prm;
    prm << frictional_drag_prm(mu) << "subsection Time\n set Integrator = "
        << (explicit_solver ? "explicit dynamic" : "implicit dynamic")
        << "\n set End time = 1.5\n set Time step = "
        << (explicit_solver ? "0.0125" : "0.025") << "\nend\n"
        << "subsection Explicit dynamics\n set Stiffness damping = 0.3\n"
        << " set Mass damping = 50\nend\n"
        << "subsection Linear solver\n set Type = direct\nend\n"
        // one discretisation for both: node-wise (the implicit default is
        // the faces, the explicit one the nodes)
        << "subsection Contact\n set Potential integration = nodes\nend\n"
        << "subsection Output\n set Directory = output-drag-"
        << (explicit_solver ? "explicit" : "implicit") << mu
        << "\n set VTU interval = 0\n set Verbose = false\nend\n";
    auto solver = make_solver<2>(prm.str());
    solver->run();
    const auto  &contact = solver->contact_history();
    const auto  &history = solver->history();
    DragMeans    means;
    unsigned int n = 0;
    for (std::size_t r = 0; r < contact.rows.size(); ++r)
    {
      const double t       = contact.value(r, "time");
      const double kinetic = explicit_solver && t > 0.5
                                 ? history.value(r, "kinetic_energy") /
                                       history.value(r, "internal_energy")
                                 : 0.0;
      if (kinetic > means.kinetic)
        means = {means.normal, means.drag, kinetic, t};
      if (t < 0.9 - 1e-9) // 8 mm of pull
        continue;
      means.normal += contact.value(r, "finger/link:normal_force");
      means.drag += contact.value(r, "finger/link:lateral_force");
      ++n;
    }
    SG_CHECK(n > 0 && std::abs(contact.value(contact.rows.size() - 1, "time") -
                               1.5) < 1e-9,
             "the pull reaches its end");
    means.normal /= n;
    means.drag /= n;
    return means;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  const double    mu        = 0.5;
  const DragMeans implicit  = run_drag(mu, false);
  const DragMeans explicit_ = run_drag(mu, true);
  const auto      relative  = [](const double a, const double b)
  { return std::abs(a / b - 1); };
  dealii::deallog << std::setprecision(4) << "mu = 0.5, 8-20 mm of pull: "
                  << "implicit normal " << implicit.normal << " N/m, drag "
                  << implicit.drag << " N/m; explicit normal "
                  << explicit_.normal << " N/m, drag " << explicit_.drag
                  << " N/m" << std::endl;
  const double d_normal = relative(explicit_.normal, implicit.normal);
  const double d_drag   = relative(explicit_.drag, implicit.drag);
  const double d_ratio  = relative(explicit_.drag / explicit_.normal,
                                  implicit.drag / implicit.normal);
  dealii::deallog << std::setprecision(2) << "differences: normal "
                  << 100 * d_normal << " %, drag " << 100 * d_drag
                  << " %, ratio " << 100 * d_ratio << " %" << std::endl;
  dealii::deallog << "explicit: largest kinetic / strain energy during the "
                  << "pull " << explicit_.kinetic
                  << " at t = " << explicit_.kinetic_time << " s" << std::endl;
  SG_CHECK(d_normal < 0.02 && d_drag < 0.02 && d_ratio < 0.02,
           "the two solvers agree within 2 %");
  SG_CHECK(implicit.drag > mu * implicit.normal &&
               explicit_.drag > mu * explicit_.normal,
           "ploughing: the drag exceeds mu N in both");
  SG_CHECK(explicit_.kinetic < 1e-3, "the explicit pull is quasi-static");

  const DragMeans smooth_implicit = run_drag(0, false);
  const DragMeans smooth_explicit = run_drag(0, true);
  const double    r_implicit =
      std::abs(smooth_implicit.drag) / smooth_implicit.normal;
  const double r_explicit =
      std::abs(smooth_explicit.drag) / smooth_explicit.normal;
  dealii::deallog << std::setprecision(1) << std::scientific
                  << "mu = 0: |drag| / normal: implicit " << r_implicit
                  << ", explicit " << r_explicit << std::endl;
  SG_CHECK(r_implicit < 5e-3 && r_explicit < 5e-3,
           "no drag without friction (translation invariance)");
}
