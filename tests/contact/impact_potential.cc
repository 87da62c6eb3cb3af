// An elastic impact with implicit dynamics (backward Euler, lumped mass):
// a neo-Hookean block (10 mm, mu = 10 kPa, nu = 0.3, 1 g) falls 1 mm under
// gravity onto a rigid floor, bounces and rises again, frictionless, with
// contact as part of each step's potential ('Contact/Enforcement =
// incremental potential') and with the Lagrange multipliers.
//
// The mechanical energy E = kinetic + strain energy - f_ext . u (gravity,
// a dead load) is conserved by the continuum. Backward Euler is not a
// conserving integrator: it damps the block's vibrations, and the lumped
// mass of the nodes that reach the floor stops there within one step
// (their kinetic energy is lost; Khenous, Laborde and Renard 2008); so
// the discrete impact loses a large part of E, the same with either
// enforcement. What the contact must not do is create energy or change
// the motion. Checked, with the energy at impact K = m g h as the scale:
//  - E never rises, from step to step or above its start, by more than
//    1e-3 K with either enforcement (the contact creates no energy);
//  - the loss falls when the time step is halved (the integrator's);
//  - the potential's E follows the multipliers' within 1 % of K at every
//    step, and its block leaves the floor at the same time (within one
//    step) with the same speed (within 1 %).
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  const double g = 9.81, h = 1e-3, m = 1e-3; // m/s^2, m, kg

  struct Run
  {
    std::vector<double> time, energy; ///< s, J
    double              lost    = 0;  ///< E(0) - E(end) (J)
    double              highest = 0;  ///< max E - E(0) (J)
    double              rise    = 0;  ///< largest rise in a step (J)
    double              leave   = 0;  ///< first time after the impact
                                      ///< with no closed node (s)
    double speed = 0;                 ///< mean upward speed then (m/s)
  };

  Run drop(const double dt, const bool potential)
  {
    std::ostringstream prm;
    prm << block("0, 0, 0.001", "0.01, 0.01, 0.011", "2, 2, 2")
        << "subsection Finite element\n set Formulation = mixed u-p-J\nend\n"
        << neo_hookean(10e3, 0.3)
        << "subsection Boundary conditions\n set Gravity = 0; 0; " << -g
        << "\nend\n"
        << contact("4", 0)
        << (potential ? "subsection Contact\n set Enforcement = incremental "
                        "potential\nend\n"
                      : "")
        << rigid_body("floor", "plane", "plane", "1", "0: 0, 0, 0, 1, 0, 0, 0")
        << "subsection Time\n set Integrator = implicit dynamic\n"
        << " set End time = 0.036\n set Time step = " << dt << "\nend\n"
        << "subsection Newton\n set Relative tolerance = 1e-10\nend\n"
        << "subsection Linear solver\n set Type = direct\nend\n"
        << "subsection Output\n set Directory = output-impact\n"
        << " set VTU interval = 0\n set Verbose = false\nend\n";
    auto run = make_solver<3>(prm.str());
    run->run();
    const auto &history = run->history();
    Run         r;
    bool        touched = false;
    for (std::size_t row = 0; row < history.rows.size(); ++row)
    {
      const double E = history.value(row, "kinetic_energy") +
                       history.value(row, "internal_energy") +
                       history.value(row, "load_potential");
      r.time.push_back(history.value(row, "time"));
      r.energy.push_back(E);
      r.highest = std::max(r.highest, E - r.energy[0]);
      if (row > 0)
        r.rise = std::max(r.rise, E - r.energy[row - 1]);
      const double closed = history.value(row, "contact_active_nodes");
      touched             = touched || closed > 0;
      if (touched && closed == 0 && r.leave == 0)
      {
        r.leave = r.time.back();
        r.speed = std::sqrt(2 * history.value(row, "kinetic_energy") / m);
      }
    }
    r.lost = r.energy.front() - r.energy.back();
    SG_CHECK(r.leave > 0, "the block left the floor again");
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  const double K = m * g * h; // energy at impact (J)

  Run fine[2]; // dt = 0.1 ms: multipliers, potential
  for (const bool potential : {false, true})
  {
    const Run coarse = drop(2e-4, potential);
    fine[potential]  = drop(1e-4, potential);
    const std::string name =
        potential ? "incremental potential" : "lagrange multipliers";
    const double highest = std::max({coarse.highest,
                                     fine[potential].highest,
                                     coarse.rise,
                                     fine[potential].rise});
    const auto   two = [](const double x) { return std::round(x * 100) / 100; };
    dealii::deallog << name << ": energy lost " << two(coarse.lost / K)
                    << " K at dt = 0.2 ms, " << two(fine[potential].lost / K)
                    << " K at dt = 0.1 ms; never rose by 1e-3 K: "
                    << (highest <= 1e-3 * K) << std::endl;
    std::cout << name << ": largest rise " << highest / K << " K" << std::endl;
    SG_CHECK(highest <= 1e-3 * K, "the contact creates no energy");
    SG_CHECK(fine[potential].lost < coarse.lost,
             "the loss falls with the time step");
  }

  const Run &lm = fine[0], &ip = fine[1];
  SG_CHECK(lm.time.size() == ip.time.size(), "the same steps");
  double difference = 0;
  for (std::size_t k = 0; k < lm.time.size(); ++k)
    difference = std::max(difference, std::abs(ip.energy[k] - lm.energy[k]));
  dealii::deallog << "the potential's energy within 1 % of K of the "
                  << "multipliers': " << (difference <= 0.01 * K)
                  << "; leaves the floor at t = " << ip.leave
                  << " s (multipliers " << lm.leave << " s) at "
                  << std::round(ip.speed * 1000) / 1000 << " m/s (multipliers "
                  << std::round(lm.speed * 1000) / 1000 << " m/s)" << std::endl;
  SG_CHECK(difference <= 0.01 * K, "the same energy history");
  SG_CHECK(std::abs(ip.leave - lm.leave) <= 1.01e-4, "leaves at one time");
  SG_CHECK_CLOSE(ip.speed, lm.speed, 0.01, 0, "with the same speed");
}
