// Where the incremental potential puts its contact terms and which penalty
// factor it uses, as each integrator resolves 'automatic'
// (ContactParameters::for_implicit(), for_explicit()):
//  - the defaults: the faces with factor 1000 on the implicit solvers, the
//    nodes with factor 100 on the explicit integrator (its face potential
//    runs on one MPI rank);
//  - 'nodes' and 'faces' hold on both, with the factor following them;
//  - a factor the user gives is kept whatever the integration;
//  - the raw values stay as parsed ('automatic', factor 0), so a run's
//    summary can say which were chosen;
//  - the slip length of a step: 'Slip tolerance' on the implicit solvers
//    whatever the step, scaled by the step over 'Time/Time step' on the
//    explicit integrator; with a 'Slip speed', that speed times the step
//    on both.
#include "../tests.h"

#include <softgrasp/contact/contact_parameters.h>

using namespace softgrasp;

namespace
{
  /// The Contact subsection parsed from @p entries (lines "set a = b").
  ContactParameters parsed(const std::string &entries)
  {
    dealii::ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Contact\n" + entries + "end\n");
    ContactParameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }

  /// One line of the log: where and with which factor each integrator
  /// puts the contact of @p given.
  void report(const std::string &name, const ContactParameters &given)
  {
    const auto implicit  = given.for_implicit();
    const auto explicit_ = given.for_explicit();
    dealii::deallog << name << ": implicit on the "
                    << (implicit.integrate_on_faces ? "faces" : "nodes")
                    << ", factor " << implicit.penalty_factor
                    << "; explicit on the "
                    << (explicit_.integrate_on_faces ? "faces" : "nodes")
                    << ", factor " << explicit_.penalty_factor << std::endl;
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();

  const auto defaults = parsed("");
  report("defaults", defaults);
  SG_CHECK(defaults.potential_integration == "automatic" &&
               defaults.penalty_factor == 0,
           "the parsed values stay 'automatic'");
  SG_CHECK(defaults.for_implicit().integrate_on_faces &&
               defaults.for_implicit().penalty_factor == 1000,
           "implicit default: faces, factor 1000");
  SG_CHECK(!defaults.for_explicit().integrate_on_faces &&
               defaults.for_explicit().penalty_factor == 100,
           "explicit default: nodes, factor 100");

  const auto nodes = parsed("set Potential integration = nodes\n");
  report("nodes", nodes);
  for (const auto &resolved : {nodes.for_implicit(), nodes.for_explicit()})
    SG_CHECK(!resolved.integrate_on_faces && resolved.penalty_factor == 100,
             "'nodes' on both integrators, factor 100");

  const auto faces = parsed("set Potential integration = faces\n");
  report("faces", faces);
  for (const auto &resolved : {faces.for_implicit(), faces.for_explicit()})
    SG_CHECK(resolved.integrate_on_faces && resolved.penalty_factor == 1000,
             "'faces' on both integrators, factor 1000");

  const auto given = parsed("set Penalty factor = 300\n");
  report("factor 300", given);
  SG_CHECK(given.for_implicit().penalty_factor == 300 &&
               given.for_explicit().penalty_factor == 300,
           "a given factor is kept");
  SG_CHECK(given.for_implicit().integrate_on_faces &&
               !given.for_explicit().integrate_on_faces,
           "a given factor does not move the contact");

  // the slip length of steps of 0.05 and 0.0125 s, the implicit solvers
  // passing their own step as the reference, the explicit integrator
  // 'Time/Time step' = 0.025 s
  for (const auto &[name, entries] :
       std::vector<std::pair<std::string, std::string>>{
           {"slip tolerance 1e-5 m", ""},
           {"slip speed 4e-4 m/s", "set Slip speed = 4e-4\n"}})
  {
    const auto p = parsed(entries);
    dealii::deallog << name << ": implicit " << p.slip_length(0.05, 0.05)
                    << ", " << p.slip_length(0.0125, 0.0125) << " m; explicit "
                    << p.slip_length(0.05, 0.025) << ", "
                    << p.slip_length(0.0125, 0.025) << " m" << std::endl;
    const bool speed = p.slip_speed > 0;
    SG_CHECK(
        std::abs(p.slip_length(0.05, 0.05) - (speed ? 2e-5 : 1e-5)) < 1e-20 &&
            std::abs(p.slip_length(0.0125, 0.0125) - (speed ? 5e-6 : 1e-5)) <
                1e-20,
        "implicit: the slip tolerance, or the speed times the step");
    SG_CHECK(std::abs(p.slip_length(0.05, 0.025) - 2e-5) < 1e-20 &&
                 std::abs(p.slip_length(0.0125, 0.025) - 5e-6) < 1e-20,
             "explicit: scaled with the step either way");
  }
}
