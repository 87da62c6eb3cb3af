// A frictional drag that the quasi-static solver cannot finish (issue 13):
// a rigid cylinder (R = 10 mm) pressed 5 mm into a soft plane-strain block
// (G = 17.2 kPa, nu = 0.45, bonded base, Q1 mixed u-p-J, 60 x 10 cells) and
// pulled 20 mm along it with mu = 0.5, 1 mm per step. Quasi-statically a
// node at the trailing edge of the contact has no continuation after 5 mm
// of pull (doc/contact.md); with 'Time/Integrator = implicit dynamic' the
// step that meets it is cut back until the inertia carries the node
// through. Checked:
//  - the run reaches the end of the pull;
//  - Coulomb at every contact node at the end: |f_t| <= mu f_n + 2e-3 mu
//    max f_n (the default enforcement with friction, the incremental
//    potential, here node-wise, lags the normal forces and frames within
//    its settle tolerance of 1e-3; the multipliers hold it exactly);
//  - the drag exceeds mu times the normal force once the contact slides
//    (the tissue heaped ahead of the cylinder pushes back: ploughing);
//  - balance: at the end the link force equals the base reaction (the
//    inertia has died out) and the kinetic energy is a negligible fraction
//    of the work of the press; the snaps release at most a few per cent of
//    it for a moment.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);
  const double      mu = 0.5;
  const std::string prm =
      frictional_drag_prm(mu) +
      "subsection Time\n set Integrator = implicit dynamic\n"
      " set End time = 1.5\n set Time step = 0.05\nend\n"
      "subsection Linear solver\n set Type = direct\nend\n"
      // Coulomb node by node (the faces hold it at their Gauss points:
      // contact/drag_faces_2d)
      "subsection Contact\n set Potential integration = nodes\nend\n"
      "subsection Output\n set Directory = output-drag\n"
      " set VTU interval = 0\n set Verbose = false\nend\n";
  auto solver = make_solver<2>(prm);
  solver->run();

  const auto  &history  = solver->history();
  const auto  &contact  = solver->contact_history();
  const size_t last     = history.rows.size() - 1;
  const double end_time = history.value(last, "time");
  SG_CHECK(std::abs(end_time - 1.5) < 1e-9, "the pull reaches its end");

  // Rows in contact: a normal force above a tenth of the largest one.
  double max_normal = 0;
  for (size_t r = 0; r < contact.rows.size(); ++r)
    max_normal =
        std::max(max_normal, contact.value(r, "finger/link:normal_force"));
  double       max_kinetic = 0, max_imbalance = 0;
  double       drag_sum = 0, normal_sum = 0;
  unsigned int n_sliding = 0;
  for (size_t r = 0; r < contact.rows.size(); ++r)
  {
    const double t      = contact.value(r, "time");
    const double normal = contact.value(r, "finger/link:normal_force");
    const bool   loaded = normal > 0.1 * max_normal;
    max_kinetic     = std::max(max_kinetic, history.value(r, "kinetic_energy"));
    const double fx = contact.value(r, "finger:F_x");
    const double fy = contact.value(r, "finger:F_y");
    const double rx = history.value(r, "reaction_2_x");
    const double ry = history.value(r, "reaction_2_y");
    if (loaded)
      max_imbalance = std::max(
          max_imbalance, std::hypot(fx - rx, fy - ry) / std::hypot(fx, fy));
    if (t >= 1.0 - 1e-9) // the last 10 mm of pull
    {
      drag_sum += std::abs(fx);
      normal_sum += std::abs(fy);
      ++n_sliding;
    }
  }
  const double end_imbalance =
      std::hypot(contact.value(last, "finger:F_x") -
                     history.value(last, "reaction_2_x"),
                 contact.value(last, "finger:F_y") -
                     history.value(last, "reaction_2_y")) /
      std::hypot(contact.value(last, "finger:F_x"),
                 contact.value(last, "finger:F_y"));
  const double end_kinetic = history.value(last, "kinetic_energy");

  // Coulomb's law node by node (the link's friction-only force is a vector
  // sum over a curved patch and may exceed mu times the force along the
  // patch's mean normal).
  double       max_excess = -1e300, node_normal = 0; // N/m
  unsigned int n_stick = 0, n_slip = 0;
  for (const auto &node : solver->contact()->nodes())
  {
    if (node.status == softgrasp::ContactStatus::inactive)
      continue;
    const double f_n = node.normal.dot(node.force);
    const double f_t = (node.force - f_n * node.normal).norm();
    max_excess       = std::max(max_excess, f_t - mu * f_n);
    node_normal      = std::max(node_normal, f_n);
    (node.status == softgrasp::ContactStatus::slip ? n_slip : n_stick) += 1;
  }
  // |f_t| - mu f_n at its largest, of mu times the largest normal force
  const double excess = max_excess / (mu * node_normal);
  const double drag   = drag_sum / n_sliding;
  const double normal = normal_sum / n_sliding;
  // The work of the press: about 1/2 F_n d with d = 5 mm.
  const double press_work = 0.5 * normal * 0.005;
  dealii::deallog << "pull finished at t = " << end_time << " s in " << last
                  << " steps" << std::endl;
  dealii::deallog << "last 10 mm of pull: drag " << std::setprecision(3) << drag
                  << " N/m, normal " << normal << " N/m, ratio "
                  << drag / normal << " (mu = " << mu << ")" << std::endl;
  dealii::deallog << "end: " << n_stick << " nodes stick, " << n_slip
                  << " slip, largest |f_t| - mu f_n below 2e-3 mu max f_n "
                  << (excess <= 2e-3) << std::endl;
  std::cout << "largest (|f_t| - mu f_n) / (mu max f_n) = " << excess
            << std::endl;
  dealii::deallog << "kinetic energy / work of the press: at the end "
                  << std::setprecision(2) << end_kinetic / press_work
                  << ", largest " << max_kinetic / press_work
                  << "; |link force - base reaction| / |link force|: at the "
                     "end "
                  << end_imbalance << ", largest " << max_imbalance
                  << std::endl;
  SG_CHECK(n_slip + n_stick > 0 && excess <= 2e-3,
           "Coulomb at every contact node");
  SG_CHECK(drag / normal > mu, "ploughing: the drag exceeds mu N");
  SG_CHECK(end_kinetic < 1e-4 * press_work && max_kinetic < 0.1 * press_work,
           "the run is quasi-static but at the snaps");
  SG_CHECK(end_imbalance < 0.01, "the link force balances the reaction");
}
