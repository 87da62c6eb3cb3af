// Explicit dynamics with Coulomb friction (forward-increment Lagrange
// multipliers): the elastic block of contact/coulomb_block (10 x 10 x 5 mm,
// neo-Hookean, mu = 0.3 on a rigid floor) is pressed down by its top face
// by 0.25 mm (t in [0, 0.1] s) and dragged 1 mm along x (t in [0.1,
// 0.2] s), with mass damping for the quasi-static loading. Checks, at
// every recorded state:
//  - the tangential force never exceeds mu N; once every contact node
//    slips (the block slides) it is above 0.95 mu N and from the next
//    record on within 1 % of mu N;
//  - the penetration after every step stays below 1e-12 m;
//  - the energy balance (kinetic + strain = work of the supports + contact
//    work - damping) holds within 1 %;
// and, node by node at the end, |f_t| = mu f_n for slipping nodes and
// f_n >= 0 for every closed node.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);
  const double       mu = 0.3;
  std::ostringstream prm;
  prm << block_on_floor(mu, "0.01 * max(t - 0.1, 0); 0; -0.0025 * min(t, 0.1)")
      << "subsection Time\n set Integrator = explicit dynamic\n"
      << " set End time = 0.2\n set Time step = 0.01\nend\n"
      << "subsection Explicit dynamics\n set Mass damping = 500\nend\n"
      << "subsection Output\n set Directory = output-block-drag\n"
      << " set VTU interval = 0\n set Verbose = false\nend\n";
  auto solver = make_solver<3>(prm.str());
  solver->run();

  const auto       &h             = solver->contact_history();
  const auto       &history       = solver->history();
  const std::string p             = "floor/plane:";
  bool              sliding_seen  = false;
  double            worst_balance = 0, worst_penetration = 0;
  for (std::size_t row = 1; row < h.rows.size(); ++row)
  {
    const double t        = h.value(row, "time");
    const double N        = h.value(row, p + "normal_force");
    const double F_t      = h.value(row, p + "lateral_force");
    const double active   = h.value(row, p + "active_nodes");
    const double slipping = h.value(row, p + "slip_nodes");
    const bool   sliding  = slipping == active && active > 0 && t > 0.1;
    // Before the drag the friction forces cancel (up to round-off).
    const double ratio = F_t / (mu * N) < 1e-10 ? 0 : F_t / (mu * N);
    dealii::deallog << "t = " << t << " s: N = " << N
                    << " N, F_t/(mu N) = " << ratio << ", slipping " << slipping
                    << " of " << active << " nodes" << std::endl;
    SG_CHECK(N > 0, "the floor is pressed");
    SG_CHECK(F_t <= mu * N * (1 + 1e-9), "F_t <= mu N");
    if (sliding)
    {
      // At the onset of sliding the nodes' slip directions are not yet
      // parallel, so |sum f_t| is a little below sum |f_t| = mu N; from
      // the next record on the block slides steadily.
      if (!sliding_seen)
        SG_CHECK(F_t >= 0.95 * mu * N, "slides only once F_t reaches mu N");
      else
        SG_CHECK_CLOSE(F_t, mu * N, 0.01, 0, "F_t = mu N while sliding");
      sliding_seen = true;
    }
    worst_balance =
        std::max(worst_balance, history.value(row, "energy_balance_error"));
    worst_penetration =
        std::max(worst_penetration, history.value(row, "max_penetration"));
  }
  SG_CHECK(sliding_seen, "the block slides in the end");
  const std::size_t last = history.rows.size() - 1;
  dealii::deallog << "energy balance error below 1 %: "
                  << (worst_balance < 0.01) << ", penetration below 1e-12 m: "
                  << (worst_penetration < 1e-12) << std::endl;
  SG_CHECK(worst_balance < 0.01, "energy balance within 1 %");
  SG_CHECK(worst_penetration < 1e-12, "no penetration after any step");
  SG_CHECK(history.value(last, "contact_work") < 0,
           "friction dissipates (negative contact work)");

  double worst_slip = 0, lowest_f_n = 1;
  for (const auto &node : solver->contact()->nodes())
  {
    if (node.status == softgrasp::ContactStatus::inactive)
      continue;
    const double f_n = node.normal.dot(node.force);
    const double f_t = (node.force - f_n * node.normal).norm();
    lowest_f_n       = std::min(lowest_f_n, f_n);
    if (node.status == softgrasp::ContactStatus::slip)
      worst_slip = std::max(worst_slip, std::abs(f_t - mu * f_n) / f_n);
  }
  worst_slip = dealii::Utilities::MPI::max(worst_slip, MPI_COMM_WORLD);
  lowest_f_n = dealii::Utilities::MPI::min(lowest_f_n, MPI_COMM_WORLD);
  SG_CHECK(worst_slip < 1e-10, "slipping nodes: |f_t| = mu f_n");
  SG_CHECK(lowest_f_n > 0, "closed nodes push (f_n > 0)");
  dealii::deallog << "node-wise Coulomb law holds" << std::endl;
}
