#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/contact/contact_parameters.h>
#include <softgrasp/contact/implicit_contact.h>
#include <string>

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
    prm.declare_entry(
        "Enforcement",
        "automatic",
        Patterns::Anything(),
        "How the implicit solvers (quasi-static, implicit dynamic) enforce "
        "contact. 'lagrange multipliers': dual mortar multipliers, the "
        "active set and stick or slip decided per Newton iteration by a "
        "semi-smooth Newton method (exact, fast; may cycle between stick "
        "and slip on a deep frictional drag and stop there). 'incremental "
        "potential': every step the minimisation of one potential (strain "
        "energy, inertia, an augmented Lagrangian on the gap, friction as a "
        "lagged, smoothed dissipation potential) by Newton with a line "
        "search on that potential, repeated in outer iterations until the "
        "normal forces and tangent frames settle (a step that does not "
        "settle is polished, 'Polish after'); it cannot cycle between stick "
        "and slip, and costs 2 to 8 times the multipliers' time where they "
        "finish. 'automatic' (the default): the incremental potential with "
        "friction ('Friction coefficient' > 0), the Lagrange multipliers "
        "without. The run's summary names the one in use. The explicit "
        "solver has its own enforcement. Valid names: automatic, " +
            ContactEnforcementRegistry<3>::names_separated_by(", ") + ".");
    prm.declare_entry(
        "Penalty factor",
        "automatic",
        Patterns::Anything(),
        "Incremental potential: the augmented Lagrangian's normal penalty k "
        "= factor * 2 mu_0 h (N/m; mu_0 the largest initial shear modulus, "
        "h the node's surface spacing). Larger values need fewer outer "
        "iterations and make the tangent stiffer. 'automatic' (the "
        "default): 1000 with the contact on the faces, 100 on the nodes "
        "('Potential integration'; at 100 on the faces the weighted "
        "penetration stays near 1e-3 of the spacing and steps are accepted "
        "unsettled, doc/contact.md). Unit: 1. Range: (0, inf) or "
        "automatic.");
    prm.declare_entry("Slip tolerance",
                      "1e-5",
                      Patterns::Double(1e-12),
                      "Incremental potential: the slip length eps (m) of the "
                      "smoothed Coulomb law (IPC's f1): below a slip of eps "
                      "per step the friction force grows smoothly from zero "
                      "with the slip (a sticking node creeps by less than "
                      "eps per step), "
                      "beyond it the force is mu times the normal force. "
                      "Unit: m. Range: (0, inf); small against the node "
                      "spacing and the slip per step.");
    prm.declare_entry("Settle tolerance",
                      "1e-3",
                      Patterns::Double(1e-12, 1),
                      "Incremental potential: a step's outer iterations end "
                      "when the nodes' normal forces change by at most this "
                      "fraction of the largest, their tangent frames by at "
                      "most this angle (rad), and the deepest penetration is "
                      "at most this fraction of the node spacing. Unit: 1. "
                      "Range: (0, 1].");
    prm.declare_entry("Maximum outer iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Incremental potential: the most outer iterations of "
                      "one step; a step that has not settled after them is "
                      "cut back. Unit: 1.");
    prm.declare_entry(
        "Maximum Newton iterations",
        "100",
        Patterns::Integer(1, 10000),
        "Incremental potential: the most Newton iterations of one "
        "minimisation (the larger of this and 'Newton/Maximum "
        "iterations'). Every iteration lowers the potential, so a long "
        "solve makes progress: where the rigid body moves into the tissue "
        "or nodes pass between stick and slip, the line search takes short "
        "steps (of the order of the slip length) for tens of iterations "
        "before Newton converges fast. Unit: 1.");
    prm.declare_entry(
        "Unsettled steps",
        "accept",
        Patterns::Selection("accept|cut back"),
        "Incremental potential: what happens to a step whose outer "
        "iterations have not settled after 'Maximum outer iterations' "
        "(its Newton solves converged, so it is an equilibrium with the "
        "lagged normal forces, but friction may exceed Coulomb's bound "
        "against the current ones; this happens where a contact patch "
        "passes from stick to slip). 'accept': keep it with a warning, its "
        "Coulomb excess in the history ('coulomb_excess', 'unsettled'); "
        "'cut back': retry with a smaller step, and stop the run when the "
        "cut-backs are used up.");
    prm.declare_entry(
        "Polish after",
        "10",
        Patterns::Integer(0, 1000),
        "Incremental potential with friction: after this many outer "
        "iterations without settling (and again after as many more) the "
        "step is finished another way, the polish: Newton's method with "
        "friction against the current normal forces (on the faces: the "
        "pressure projected from the points' current forces, its "
        "derivative left out of the tangent), so Coulomb's law holds "
        "exactly (the tangent is not symmetric, so the direct solver or "
        "GMRES; the line search backtracks on the residual), the "
        "multipliers updated between solves until they settle (at most "
        "'Maximum outer iterations' solves). If it fails, the lagged "
        "iterations go on from where they were. The log and the history "
        "('polished') show where it was used. 0: never. Unit: 1.");
    prm.declare_entry(
        "Potential integration",
        "automatic",
        Patterns::Selection("automatic|nodes|faces"),
        "Incremental potential: where the gap and the friction potential are "
        "evaluated on the slave surface. 'nodes': at each slave node, "
        "weighted by its area (node-to-surface; the rigid surface may pass "
        "between the nodes, and on a deep drag the nodes beside a rounded "
        "end are pushed until a surface cell folds, or snap from stick to "
        "slip). 'faces': at the Gauss points of each slave face (degree + 2 "
        "per direction), the position interpolated from the face's nodes, "
        "the multipliers on the nodes (a face-integrated gap, as CalculiX's "
        "surface-to-surface contact; no fold and no snap on the deep drags, "
        "doc/contact.md); about 9 to 16 times the points, the same "
        "unknowns. The explicit integrator reads it too: 'faces' puts its "
        "contact on the faces ('Explicit faces', one MPI rank), 'nodes' "
        "solves dual mortar multipliers node by node. 'automatic' (the "
        "default): faces for the implicit solvers, nodes for the explicit "
        "integrator. The run's summary names the one in use. Unit: none.");
    prm.declare_entry(
        "Slip speed",
        "0",
        Patterns::Double(0),
        "Incremental potential: if positive, the slip length eps of each "
        "step is this speed times the step's length dt (IPC's eps_v dt), "
        "and 'Slip tolerance' is not used. With a fixed slip length a "
        "sticking node creeps by up to eps per step, so that a run of "
        "smaller steps creeps more (and the friction built up in a press "
        "relaxes more); with a slip speed the creep does not depend on the "
        "step size, and a run converges as the steps shrink "
        "(doc/contact.md, 'Slip length or slip speed'). Keep it small "
        "against the sliding speed (the deep drag: 4e-4 m/s at a pull of "
        "0.02 m/s). Unit: m/s. Range: [0, inf); 0: off.");
    prm.declare_entry(
        "Explicit faces",
        "potential",
        Patterns::Selection("potential|dual mortar"),
        "The explicit integrator with 'Potential integration = faces': "
        "'potential': each step minimises the lumped-mass inertia of the "
        "slave nodes' correction plus the same face potential as the "
        "implicit solvers (penalty and multipliers at the Gauss points, "
        "friction lagged; the multipliers and lags updated once per step; "
        "the slip length scaled by the step over 'Time/Time step', so that "
        "it smooths the same slip speed), so the integrators share one "
        "discretization; one MPI rank. 'dual mortar': the weighted gaps "
        "int psi_k g dA >= 0 of dual mortar multipliers, solved node by "
        "node, friction node-wise (closer to converged forces on coarse "
        "meshes, but it folds where the nodes do; doc/contact.md). "
        "Unit: none.");
    prm.leave_subsection();
  }

  namespace
  {
    /// 'Contact/Penalty factor' (@p prm in "Contact"): a positive number,
    /// or 0 for 'automatic'.
    double parsed_penalty_factor(const ParameterHandler &prm)
    {
      if (Utilities::trim(prm.get("Penalty factor")) == "automatic")
        return 0;
      try
      {
        return CheckedSection(prm, "Contact")
            .get_positive("Penalty factor", "");
      }
      catch (const InputError &error)
      {
        throw InputError(std::string(error.what()) +
                         " Or give 'automatic': 1000 with the contact on "
                         "the faces, 100 on the nodes.");
      }
    }

    /// The parameters with the integration and the penalty factor set.
    ContactParameters with_integration(ContactParameters parameters,
                                       const bool        faces)
    {
      parameters.integrate_on_faces = faces;
      if (parameters.penalty_factor == 0)
        parameters.penalty_factor = faces ? 1000 : 100;
      return parameters;
    }
  } // namespace

  ContactParameters ContactParameters::for_implicit() const
  {
    return with_integration(*this, potential_integration != "nodes");
  }

  ContactParameters ContactParameters::for_explicit() const
  {
    return with_integration(*this, potential_integration == "faces");
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
    enforcement            = prm.get("Enforcement");
    if (enforcement != "automatic" &&
        ContactEnforcementRegistry<3>::all().count(enforcement) == 0)
      throw InputError("Parameter 'Contact/Enforcement' = '" + enforcement +
                       "' is not a contact enforcement. Valid names are: "
                       "automatic, " +
                       ContactEnforcementRegistry<3>::names_separated_by(", ") +
                       ". Fix: use one of them.");
    penalty_factor        = parsed_penalty_factor(prm);
    slip_tolerance        = prm.get_double("Slip tolerance");
    slip_speed            = prm.get_double("Slip speed");
    settle_tolerance      = prm.get_double("Settle tolerance");
    max_outer_iterations  = prm.get_integer("Maximum outer iterations");
    max_newton_iterations = prm.get_integer("Maximum Newton iterations");
    accept_unsettled      = prm.get("Unsettled steps") == "accept";
    polish_after          = prm.get_integer("Polish after");
    potential_integration = prm.get("Potential integration");
    explicit_dual_mortar  = prm.get("Explicit faces") == "dual mortar";
    prm.leave_subsection();
  }

  double ContactParameters::slip_length(const double step,
                                        const double reference_step) const
  {
    if (slip_speed > 0)
      return slip_speed * step;
    return slip_tolerance * (reference_step > 0 ? step / reference_step : 1.0);
  }

  std::string ContactParameters::implicit_enforcement() const
  {
    if (enforcement != "automatic")
      return enforcement;
    return friction_coefficient > 0 ? "incremental potential"
                                    : "lagrange multipliers";
  }
} // namespace softgrasp
