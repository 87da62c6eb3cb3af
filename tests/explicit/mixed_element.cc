// One element in both solvers: with 'Polynomial degree = 2' and 'mixed
// u-p-J', switching 'Time/Integrator' alone keeps the discretisation. A
// rigid sphere (R = 10 mm) is pressed d = 0.3 mm into a nearly
// incompressible neo-Hookean block (mu = 10 kPa, nu = 0.49; 10 mm quarter
// model, Q2) along a smooth ramp with zero speed at both ends, frictionless.
// The quasi-static and the explicit solver run the same .prm with the
// default pressure degree (Q2-P1) and with 'Pressure degree = 0' (Q2-P0).
// Checks: at the end of the loading the two solvers agree within 1 % for
// each element, while the two elements differ by more than the 1 % (so
// that the agreement would catch a solver running the other element).
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  std::string prm(const std::string &integrator, const std::string &pressure)
  {
    const double       depth = 3e-4, T = 0.25;
    std::ostringstream s;
    s << hertz_prm(4,
                   1.5,
                   0.01,
                   2,
                   10,
                   "output-mixed-" + integrator + "-" + pressure,
                   "direct",
                   0,
                   0.49)
      << "subsection Rigid bodies\n subsection Body indenter\n"
      << "  set Trajectory = " << cosine_ramp_trajectory(depth, T)
      << "\n end\nend\n"
      << "subsection Time\n set Integrator = " << integrator
      << "\n set End time = " << T << "\n set Time step = " << T / 10
      << "\nend\n"
      << "subsection Finite element\n set Formulation = mixed u-p-J\n"
      << " set Pressure degree = " << pressure << "\nend\n"
      << "subsection Explicit dynamics\n set Mass damping = 200\n"
      << " set Mass scaling time step = 4e-5\nend\n";
    return s.str();
  }

  /// The indentation force (N, full sphere) at the end of the loading.
  double end_force(const std::string &integrator, const std::string &pressure)
  {
    auto solver = make_solver<3>(prm(integrator, pressure));
    solver->run();
    const auto &history = solver->contact_history();
    return 4 *
           history.value(history.rows.size() - 1, "indenter/ball:normal_force");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  std::map<std::string, double> difference;
  std::map<std::string, double> implicit_force;
  for (const std::string pressure : {"k-1", "0"})
  {
    const double implicit    = end_force("quasi-static", pressure);
    const double explicit_   = end_force("explicit dynamic", pressure);
    implicit_force[pressure] = implicit;
    difference[pressure]     = std::abs(explicit_ / implicit - 1);
    const std::string name   = pressure == "0" ? "Q2-P0" : "Q2-P1";
    dealii::deallog << name << ": quasi-static " << implicit << " N, explicit "
                    << explicit_
                    << " N, within 1 %: " << (difference[pressure] < 0.01)
                    << std::endl;
    SG_CHECK(difference[pressure] < 0.01, "both solvers, one element");
  }
  const double elements =
      std::abs(implicit_force["0"] / implicit_force["k-1"] - 1);
  dealii::deallog << "Q2-P0 and Q2-P1 differ by more than 1 %: "
                  << (elements > 0.01) << std::endl;
  SG_CHECK(elements > 0.01, "the two elements are distinguishable");
}
