#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/contact/contact_parameters.h>

namespace softgrasp
{
  using namespace dealii;

  void ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Slave boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundary ids of the deformable body's surface that "
                      "may touch the rigid bodies (the mortar slave side). "
                      "Empty: no contact.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0),
                      "Coulomb friction coefficient mu between the rigid "
                      "bodies and the tissue. Unit: 1. Range: [0, 3]; 0 is "
                      "frictionless.");
    prm.declare_entry("Complementarity parameter",
                      "0.1",
                      Patterns::Double(1e-12),
                      "Scale of the complementarity parameter c = factor * 2 "
                      "mu_0 h (N/m) of the semi-smooth Newton method. It "
                      "only changes how the active set is predicted during "
                      "the iterations, not the converged result. Large "
                      "values (>= 1) let the second-order gap error of "
                      "curved rigid surfaces flip nodes between open and "
                      "closed; small values decide by the contact force. "
                      "Unit: 1. Range: (0, inf).");
    prm.leave_subsection();
  }

  void ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    slave_boundary_ids.clear();
    for (const auto &item :
         Utilities::split_string_list(prm.get("Slave boundary ids"), ','))
      slave_boundary_ids.push_back(
          static_cast<types::boundary_id>(Utilities::string_to_int(item)));
    friction_coefficient = prm.get_double("Friction coefficient");
    if (friction_coefficient > 3)
      throw InputError(
          "Parameter 'Contact/Friction coefficient' = " +
          std::to_string(friction_coefficient) +
          " is far above measured values (skin on metal or rubber: about "
          "0.2-1.5). Fix: give a Coulomb coefficient between 0 and 3.");
    complementarity_factor = prm.get_double("Complementarity parameter");
    prm.leave_subsection();
  }
} // namespace softgrasp
