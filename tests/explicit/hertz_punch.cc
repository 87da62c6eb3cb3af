// Explicit against implicit on slow loading (the Hertz case): a rigid
// sphere (R = 10 mm) is pressed d = 0.2 mm into a neo-Hookean block
// (mu = 10 kPa, nu = 0.45; a 10 mm quarter model, graded Q1 mesh) along a
// smooth ramp d(t) = d (1 - cos(pi t / T)) / 2 (zero speed at both ends),
// frictionless. The same .prm runs with 'Time/Integrator = quasi-static'
// and '= explicit dynamic' (mass damping, mass scaling for the small
// elements under the sphere), both in the displacement formulation. The
// force-indentation curves must agree within 2 % from half the indentation on
// (where the force is well above the dynamic noise), the penetration after
// every explicit step stays below 1e-12 m, and the explicit energy balance
// holds within 1 %.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  std::string punch_prm(const std::string &integrator,
                        const std::string &variant = "nodes")
  {
    const double       depth = 2e-4, T = 0.25;
    std::ostringstream s;
    s << hertz_prm(8,
                   1.5,
                   0.01,
                   1,
                   10,
                   "output-punch-" + integrator + "-" + variant.substr(0, 4))
      << "subsection Rigid bodies\n subsection Body indenter\n"
      << "  set Trajectory = " << cosine_ramp_trajectory(depth, T)
      << "\n end\nend\n"
      << "subsection Time\n set Integrator = "
      << (integrator == "implicit" ? "quasi-static" : "explicit dynamic")
      << "\n set End time = " << T << "\n set Time step = " << T / 10
      << "\nend\n"
      << "subsection Finite element\n set Formulation = displacement\nend\n"
      << "subsection Explicit dynamics\n set Mass damping = 200\n"
      << " set Mass scaling time step = 4e-5\nend\n"
      << "subsection Contact\n set Potential integration = "
      << (variant == "nodes" ? "nodes" : "faces")
      << (variant == "nodes" ? ""
          : integrator == "implicit"
              ? "\n set Enforcement = incremental potential\n"
                " set Penalty factor = 1000"
              : "\n set Penalty factor = 1000\n"
                " set Explicit faces = " +
                    variant)
      << "\nend\n";
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  // node-wise (against the implicit Lagrange multipliers), then on the
  // faces (against the implicit face potential): the dual mortar weighted
  // gaps (their penetration within the sweeps' tolerance of 1e-9 of the
  // model's size) and, on one rank, the face potential (its penetration,
  // the deepest Gauss point's, the penalty's: below 1 % of the 0.2 mm
  // indentation, measured 7.8e-7 m)
  std::vector<std::string> variants = {"nodes", "dual mortar"};
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
    variants.push_back("potential");
  for (const std::string &integration : variants)
  {
    auto implicit_solver = make_solver<3>(punch_prm("implicit", integration));
    implicit_solver->run();
    const auto &hi       = implicit_solver->contact_history();
    auto explicit_solver = make_solver<3>(punch_prm("explicit", integration));
    explicit_solver->run();
    const auto       &he = explicit_solver->contact_history();
    const std::string F  = "indenter/ball:normal_force";
    SG_CHECK(hi.rows.size() == he.rows.size(), "the same recorded times");
    double worst = 0;
    for (std::size_t row = 1; row < hi.rows.size(); ++row)
    {
      const double t = hi.value(row, "time");
      SG_CHECK_CLOSE(he.value(row, "time"), t, 1e-12, 0, "same times");
      const double implicit_force = 4 * hi.value(row, F);
      const double explicit_force = 4 * he.value(row, F);
      const double difference     = explicit_force / implicit_force - 1;
      dealii::deallog << integration << ", t = " << t << " s: implicit "
                      << implicit_force << " N, explicit " << explicit_force
                      << " N" << std::endl;
      if (row >= hi.rows.size() / 2)
        worst = std::max(worst, std::abs(difference));
    }
    std::cout << integration << ": largest difference from d/2 on "
              << 100 * worst << " %" << std::endl;
    dealii::deallog << integration
                    << ": explicit within 2 % of implicit from d/2 on: "
                    << (worst < 0.02) << std::endl;
    SG_CHECK(worst < 0.02, "explicit and implicit agree within 2 %");

    const auto &history = explicit_solver->history();
    double      balance = 0, penetration = 0;
    for (std::size_t row = 1; row < history.rows.size(); ++row)
    {
      balance = std::max(balance, history.value(row, "energy_balance_error"));
      penetration =
          std::max(penetration, history.value(row, "max_penetration"));
    }
    const double      allowed = integration == "nodes"         ? 1e-12
                                : integration == "dual mortar" ? 1e-11
                                                               : 2e-6;
    const std::size_t last    = history.rows.size() - 1;
    dealii::deallog << "added mass "
                    << history.value(last, "added_mass_percent") << " %"
                    << ", energy balance within 1 %: " << (balance < 0.01)
                    << ", penetration below " << allowed
                    << " m: " << (penetration < allowed) << std::endl;
    SG_CHECK(balance < 0.01, "energy balance within 1 %");
    SG_CHECK(penetration < allowed, "no penetration after any step");
  }
}
