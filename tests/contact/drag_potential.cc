// The deep plane-strain frictional drag on the incremental potential
// ('Contact/Enforcement = incremental potential': lagged friction inside
// each step's minimisation): a rigid cylinder (R = 10 mm) pressed 10 mm
// into a 120 x 20 mm neo-Hookean block (E = 50 kPa, nu = 0.45, Q1 u-p-J,
// 40 x 8 cells, bonded base) and pulled 20 mm along it, mu = 0.5.
//  - The semi-smooth Newton method of the Lagrange multipliers stops in
//    the pull (quasi-static, 0.5 mm increments); the potential runs to the
//    end, quasi-statically at 0.5 and 1 mm increments and with implicit
//    dynamics at the pull speed (20 mm/s).
//  - Every accepted step: the potential never rose along a Newton update;
//    Coulomb's law holds against the current normal forces (friction at
//    most mu lambda + 1e-3 mu max lambda) unless the step is reported
//    unsettled; quasi-statically the support's reaction balances the
//    force on the cylinder.
//  - The drag/normal ratio at every millimetre up to the first stick-slip
//    event (a drop of the drag by more than 3 % in one step, which every
//    run reports in its contact history, 'stick_slip_drop', near 13 mm):
//    implicit dynamics within 3 % of quasi-statics at the same increment;
//    quasi-statics at 1 mm within 0.02 of 0.5 mm (the pull's path depends
//    on the increment: up to 4 % of the ratio, measured). Implicit
//    dynamics at 1 mm within 4 % (+ 0.003) of 0.5 mm over the pull,
//    through the event, up to 19 mm (measured: 1.7 % beyond the event,
//    3.6 % at 8 mm where it follows the quasi-static 1 mm path, 6 % at
//    20 mm).
//  Each step starts from the last converged state extrapolated in time
//  ('Newton/Predictor', the default): without it the first event comes
//  at 11 mm and the dynamic runs at 0.5 and 1 mm differ by 17 % at 18 mm.
#include "plane_drag.h"

using namespace softgrasp_tests;
using namespace softgrasp_tests::plane_drag;

namespace
{
  /// The drag on 40 x 8 cells, node-wise, with @p enforcement.
  Drag pull(const std::string &enforcement,
            const std::string &integrator,
            const double       dt)
  {
    return plane_drag::pull("40, 8",
                            " set Enforcement = " + enforcement +
                                "\n set Potential integration = nodes\n",
                            integrator,
                            dt);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);

  const Drag lm = pull("lagrange multipliers", "quasi-static", 0.025);
  dealii::deallog << "semi-smooth Newton, quasi-static, 0.5 mm: stops "
                  << "before 10 mm of the pull: " << (lm.pulled < 10)
                  << std::endl;
  std::cout << "semi-smooth Newton stopped at " << lm.pulled << " mm"
            << std::endl;
  SG_CHECK(lm.pulled < 20, "the semi-smooth path stops in the pull");

  const std::string potential = "incremental potential";
  const Drag        reference = pull(potential, "quasi-static", 0.025);
  // the same pull at the pull speed with inertia: the same curve within
  // 3 %; at twice the increment the curve differs by up to 0.014 in the
  // ratio (3 % of its value at 8 mm, 4 % at 1 mm, where it is 0.05): the
  // path of a frictional pull depends on the increment
  struct Variant
  {
    std::string name;
    Drag        drag;
    double      rtol, atol;
    /// compared with this run (default: the quasi-static reference) up to
    /// this pull (mm; default: the first event)
    const Drag *against = nullptr;
    double      until   = 0;
  };
  const Drag dynamic              = pull(potential, "implicit dynamic", 0.025);
  const std::vector<Variant> runs = {
      {"implicit dynamic, 0.5 mm", dynamic, 0.03, 0},
      {"quasi-static, 1 mm", pull(potential, "quasi-static", 0.05), 0, 0.02},
      {"implicit dynamic, 1 mm",
       pull(potential, "implicit dynamic", 0.05),
       0.04,
       0.003,
       &dynamic,
       19}};
  dealii::deallog << "potential, quasi-static, 0.5 mm: to the end "
                  << (reference.pulled > 20 - 1e-6)
                  << ", first stick-slip event near 13 mm "
                  << (std::abs(reference.first_event - 13) <= 1) << std::endl;
  std::cout << "potential, quasi-static, 0.5 mm: first event at "
            << reference.first_event << " mm, " << reference.events
            << " events, " << reference.unsettled << " unsettled steps"
            << std::endl;
  SG_CHECK(reference.pulled > 20 - 1e-6, "the potential runs to the end");
  SG_CHECK(reference.events > 0, "a stick-slip event is reported");
  for (const auto &[name, drag, rtol, atol, against, to] : runs)
  {
    const Drag  &base = against ? *against : reference;
    const double until =
        to > 0 ? to + 1 : std::min(base.first_event, drag.first_event);
    bool         agree = true;
    const double worst =
        largest_difference(drag, base, 1, until - 1, rtol, atol, agree);
    dealii::deallog << "potential, " << name << ": to the end "
                    << (drag.pulled > 20 - 1e-6) << ", a stick-slip event "
                    << (drag.events > 0) << ", drag/normal within "
                    << rtol * 100 << " % + " << atol
                    << (to > 0 ? " up to 19 mm " : " before it ") << agree
                    << std::endl;
    std::cout << name << ": first event at " << drag.first_event << " mm, "
              << drag.unsettled << " unsettled steps, largest ratio "
              << "difference " << worst << " before " << until << " mm"
              << std::endl;
    SG_CHECK(drag.pulled > 20 - 1e-6, "the potential runs to the end");
    SG_CHECK(drag.events > 0, "a stick-slip event is reported");
    SG_CHECK(agree, "the same drag/normal ratio before the event");
  }
}
