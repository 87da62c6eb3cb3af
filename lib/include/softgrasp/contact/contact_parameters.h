#ifndef softgrasp_contact_contact_parameters_h
#define softgrasp_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /// The subsection "Contact" of a .prm file.
  struct ContactParameters
  {
    /// Boundary ids of the deformable body's contact (slave) surface; empty
    /// means no contact.
    std::vector<dealii::types::boundary_id> slave_boundary_ids;
    double friction_coefficient = 0; ///< Coulomb mu (1), >= 0
    /// Complementarity parameter c as a multiple of 2 mu_0 h (N/m; mu_0
    /// the largest initial shear modulus, h the node's surface spacing).
    /// It steers only the active-set prediction, not the converged answer.
    double complementarity_factor = 0.1; ///< (1)
    /// How the implicit solvers enforce contact: a registered
    /// ContactEnforcement ("lagrange multipliers", "incremental potential")
    /// or "automatic" (implicit_enforcement()).
    std::string enforcement = "automatic";
    /// The registered enforcement the implicit solvers use: 'enforcement',
    /// or for "automatic" the incremental potential with friction and the
    /// Lagrange multipliers without.
    std::string implicit_enforcement() const;
    /// Incremental potential: the normal penalty k = factor * 2 mu_0 h of
    /// the augmented Lagrangian, as the complementarity parameter (1). Its
    /// value for the integration in use (for_implicit(), for_explicit());
    /// as parsed, 0 where 'Penalty factor = automatic'.
    double penalty_factor = 0;
    /// Incremental potential: the slip length eps of the smoothed Coulomb
    /// law (m): a node creeps by at most eps per step while it sticks.
    double slip_tolerance = 1e-5;
    /// Incremental potential: if positive, the slip length of each step is
    /// this speed times the step's length (IPC's eps_v dt), so that a
    /// sticking node creeps at most this fast whatever the step, and
    /// slip_tolerance is not used (m/s); 0: off.
    double slip_speed = 0;
    /// The slip length eps (m) of a step of length @p step (s): slip_speed
    /// times @p step if it is set, else slip_tolerance times @p step over
    /// @p reference_step (the explicit integrator's steps, against the
    /// implicit step 'Time/Time step' that slip_tolerance is meant for;
    /// the implicit solvers pass their own step, so that it is
    /// slip_tolerance).
    double slip_length(const double step, const double reference_step) const;
    /// Incremental potential: the outer iterations of a step stop when
    /// the normal forces change by at most this fraction of the largest
    /// (1) and the penetration is at most this fraction of the node
    /// spacing.
    double settle_tolerance = 1e-3;
    /// Incremental potential: the most outer iterations of a step before
    /// it is cut back.
    unsigned int max_outer_iterations = 30;
    /// Incremental potential: the most Newton iterations of one solve (at
    /// least 'Newton/Maximum iterations').
    unsigned int max_newton_iterations = 100;
    /// Incremental potential: keep a step whose outer iterations have not
    /// settled (true) or cut it back (false).
    bool accept_unsettled = true;
    /// Incremental potential: after this many unsettled outer iterations
    /// (and again after as many more) the step is polished: Newton with
    /// friction against the current normal forces; 0: never.
    unsigned int polish_after = 10;
    /// 'Potential integration' as given: "automatic", "nodes" or "faces".
    std::string potential_integration = "automatic";
    /// Incremental potential: where its contact terms are evaluated on the
    /// slave surface: at the nodes, each weighted by its area (false), or
    /// at the Gauss points of each slave face, the gap interpolated
    /// between the nodes (true). The explicit integrator's contact then
    /// acts on the faces too. Set only by for_implicit() and
    /// for_explicit(), for the integrator in use.
    bool integrate_on_faces = false;
    /// The explicit integrator on faces: the implicit solvers' face
    /// potential per step (false) or dual mortar weighted gaps (true;
    /// 'Explicit faces = dual mortar').
    bool explicit_dual_mortar = false;

    /// These parameters with 'automatic' resolved for the implicit
    /// solvers: the contact terms on the faces, penalty factor 1000 (100
    /// on the nodes).
    ContactParameters for_implicit() const;
    /// These parameters with 'automatic' resolved for the explicit
    /// integrator: node-wise dual mortar contact (it runs on any number of
    /// MPI ranks), penalty factor 100 (1000 on the faces).
    ContactParameters for_explicit() const;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace softgrasp

#endif
