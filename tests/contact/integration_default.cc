// Where the incremental potential puts its contact terms and which penalty
// factor it uses, as each integrator resolves 'automatic'
// (ContactParameters::for_implicit(), for_explicit()):
//  - the defaults: the faces with factor 1000 on the implicit solvers, the
//    nodes with factor 100 on the explicit integrator (its face potential
//    runs on one MPI rank);
//  - 'nodes' and 'faces' hold on both, with the factor following them;
//  - a factor the user gives is kept whatever the integration;
//  - the raw values stay as parsed ('automatic', factor 0), so a run's
//    summary can say which were chosen.
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
}
