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
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <map>

using namespace softgrasp_tests;

namespace
{
  const double t_press = 0.5, speed = 0.02; // s, m/s

  std::string drag_prm(const std::string &enforcement,
                       const std::string &integrator,
                       const double       dt)
  {
    std::ostringstream s;
    s << frictional_drag_prm(0.5)
      << "subsection Mesh\n subsection Block\n  set Subdivisions = 40, 8\n"
      << " end\nend\n"
      << "subsection Rigid bodies\n subsection Body finger\n"
      << "  set Trajectory = 0: -0.01, 0.0305, 0, 1, 0, 0, 0; "
      << "0.5: -0.01, 0.0205, 0, 1, 0, 0, 0; 1.5: 0.01, 0.0205, 0, 1, 0, 0, 0"
      << "\n end\nend\n"
      << "subsection Contact\n set Enforcement = " << enforcement << "\nend\n"
      << "subsection Time\n set Integrator = " << integrator
      << "\n set End time = 1.5\n set Time step = " << dt
      << "\n set Maximum cut-backs = 4\nend\n"
      << "subsection Output\n set Directory = output-drag\n"
      << " set VTU interval = 0\n set Verbose = false\nend\n";
    return s.str();
  }

  struct Drag
  {
    double                pulled = 0; ///< mm, at the last converged step
    std::map<int, double> ratio;      ///< drag/normal at each mm
    double       first_event = 1e9;   ///< pull at the first stick-slip (mm)
    unsigned int events = 0, unsettled = 0;
  };

  /// Run a drag; quasi-statically check the reactions; potential: the
  /// history's checks.
  Drag pull(const std::string &enforcement,
            const std::string &integrator,
            const double       dt)
  {
    auto run = make_solver<2>(drag_prm(enforcement, integrator, dt));
    try
    {
      run->run();
    }
    catch (const std::exception &)
    {
      // the semi-smooth path stops: its last converged state is recorded
    }
    Drag        drag;
    const auto &records   = run->contact_force_history();
    const auto &history   = run->history();
    const auto &table     = run->contact_history();
    const bool  potential = enforcement == "incremental potential";
    for (std::size_t k = 0; k < records.size(); ++k)
    {
      const auto  &f    = records[k].forces[0][0];
      const double t    = records[k].time;
      const double mm   = (t - t_press) * speed * 1e3;
      const double near = std::round(mm);
      if (t > t_press + 1e-9 && std::abs(mm - near) < 1e-6)
        drag.ratio[int(near)] = std::abs(f.force[0]) / f.normal_force();
      drag.pulled = std::max(drag.pulled, mm);
      if (table.value(k, "stick_slip_drop") > 0)
      {
        ++drag.events;
        drag.first_event = std::min(drag.first_event, mm);
      }
      if (integrator == "quasi-static" && k > 0)
        SG_CHECK((Eigen::Vector2d(history.value(k, "reaction_2_x"),
                                  history.value(k, "reaction_2_y")) -
                  f.force.head<2>())
                         .norm() <= 1e-6 * f.force.norm(),
                 "the support's reaction balances the contact force");
      if (!potential || k == 0)
        continue;
      SG_CHECK(history.value(k, "energy_increases") == 0,
               "the potential never rose along an update");
      const bool unsettled = history.value(k, "unsettled") > 0;
      drag.unsettled += unsettled;
      SG_CHECK(unsettled || history.value(k, "coulomb_excess") <= 1e-3,
               "Coulomb's law against the current normal forces");
    }
    return drag;
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
    double worst = 0;
    bool   agree = true;
    for (const auto &[mm, ratio] : base.ratio)
      if (mm < until - 0.5 && drag.ratio.count(mm))
      {
        worst = std::max(worst, std::abs(drag.ratio.at(mm) - ratio));
        agree = agree && close(drag.ratio.at(mm), ratio, rtol, atol);
      }
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
