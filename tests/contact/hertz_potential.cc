// Frictionless Hertz indentation with each implicit step the minimisation
// of one potential ('Contact/Enforcement = incremental potential': strain
// energy, minus the external work, and an augmented Lagrangian on each
// contact node's gap, Uzawa outer iterations) against the exact
// Lagrange-multiplier answer of the default enforcement on the same mesh
// (the problem of contact/hertz: a rigid sphere R = 10 mm pressed 0.1 mm
// into a neo-Hookean block, quarter model, Q1, 4 load steps):
//  - the total force within 0.1 % of the multipliers' at every step, and
//    the number of closed nodes the same at the end;
//  - the penetration at most the settle tolerance (1e-3) times the node
//    spacing;
//  - the potential never rose along an accepted Newton update and every
//    direction descended (the history's counts, recorded by the solver,
//    not assumed);
//  - Hertz's force within 5 %, as contact/hertz;
//  - with 'Potential integration = faces' (the potential at the faces'
//    Gauss points, the multipliers projected onto the nodes), every step
//    settled, no rise of the potential, and Hertz's force within 8 %: on
//    this mesh the faces' Gauss points hold the nodes off the sphere and
//    the force is 6.7 % high (the nodes' gap is 3.2 % low); refined once
//    more it is 1.9 % high (contact/hertz_faces).
// Run on one and on two MPI ranks, with the same expected output.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <iomanip>
#include <softgrasp/contact/potential_contact.h>
#include <sstream>

using namespace softgrasp_tests;

namespace
{
  /// The indenter's force (quarter model times 4) at each step after
  /// t = 0 (N).
  std::vector<double> step_forces(const softgrasp::Simulation<3> &run)
  {
    std::vector<double> forces;
    for (const auto &record : run.contact_force_history())
      if (record.time > 0)
        forces.push_back(4 * record.forces[0][0].force[2]);
    return forces;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);

  const auto exact = hertz_solution();
  // node-wise, as the multipliers (the implicit default is the faces)
  const std::string enforcement =
      "subsection Contact\n set Enforcement = incremental potential\n"
      " set Potential integration = nodes\nend\n";
  auto multipliers = make_solver<3>(
      hertz_prm(8, 1.5, 0.05, 1, 4, "output-lm", "iterative", 1));
  multipliers->run();
  auto potential = make_solver<3>(
      hertz_prm(8, 1.5, 0.05, 1, 4, "output-ip", "iterative", 1) + enforcement);
  potential->run();

  const auto f_lm = step_forces(*multipliers);
  const auto f_ip = step_forces(*potential);
  SG_CHECK(f_lm.size() == 4 && f_ip.size() == 4, "four load steps each");

  const auto  &history   = potential->history();
  unsigned int increases = 0, non_descent = 0;
  for (std::size_t row = 1; row < history.rows.size(); ++row)
  {
    const double outer = history.value(row, "outer_iterations");
    increases += history.value(row, "energy_increases");
    non_descent += history.value(row, "non_descent_directions");
    // the difference itself is round-off (about 1e-3 %), different on
    // every machine: the log says only that it is within 0.01 %
    const double difference = f_ip[row - 1] / f_lm[row - 1] - 1;
    // four digits: the sixth differs between runs (threaded assembly)
    const auto digits = [](const double f)
    {
      std::ostringstream out;
      out << std::setprecision(4) << f;
      return out.str();
    };
    dealii::deallog << "step " << row << ": force " << digits(f_ip[row - 1])
                    << " N (multipliers " << digits(f_lm[row - 1])
                    << " N, within "
                    << (std::abs(difference) < 1e-4 ? "0.01 %" : "0.1 %")
                    << "), outer iterations " << outer << std::endl;
    SG_CHECK_CLOSE(f_ip[row - 1],
                   f_lm[row - 1],
                   1e-3,
                   0,
                   "the potential's force within 0.1 % of the multipliers'");
    SG_CHECK(outer >= 1, "at least one outer iteration per step");
  }
  dealii::deallog << "energy increases " << increases
                  << ", non-descent directions " << non_descent << std::endl;
  SG_CHECK(increases == 0, "the potential never rose along an update");
  SG_CHECK(non_descent == 0, "every Newton direction descended");

  // penetration against each node's spacing h = sqrt(its area)
  double penetration = 0;
  for (const auto &node : potential->contact()->nodes())
    if (node.body >= 0)
      penetration =
          std::max(penetration, -node.gap / std::sqrt(node.reference_area));
  penetration = dealii::Utilities::MPI::max(penetration, MPI_COMM_WORLD);
  SG_CHECK(penetration <= 1e-3, "penetration below 1e-3 of the node spacing");
  const unsigned int closed_lm = multipliers->contact()->n_active();
  const unsigned int closed_ip = potential->contact()->n_active();
  dealii::deallog << "closed nodes " << closed_ip << " (multipliers "
                  << closed_lm << ")" << std::endl;
  SG_CHECK(closed_ip == closed_lm, "the same closed nodes");
  SG_CHECK_CLOSE(f_ip.back(), exact.force, 0.05, 0, "Hertz force within 5 %");

  // the same potential at the Gauss points of the faces: its coarse-mesh
  // error (contact/hertz_faces shows it converging, at the same penalty
  // factor of 100; the default on faces, 1000, is 9.4 % high here)
  auto faces = make_solver<3>(
      hertz_prm(8, 1.5, 0.05, 1, 4, "output-ipf", "iterative", 1) +
      "subsection Contact\n set Enforcement = incremental potential\n"
      " set Potential integration = faces\n set Penalty factor = 100\nend\n");
  faces->run();
  const auto f_faces = step_forces(*faces);
  SG_CHECK(f_faces.size() == 4, "four load steps");
  unsigned int faces_increases = 0, unsettled = 0;
  for (std::size_t row = 1; row < faces->history().rows.size(); ++row)
  {
    faces_increases += faces->history().value(row, "energy_increases") +
                       faces->history().value(row, "non_descent_directions");
    unsettled += faces->history().value(row, "unsettled");
  }
  const double error = f_faces.back() / exact.force - 1;
  dealii::deallog << "on faces: force error within "
                  << (std::abs(error) < 0.07 ? "7 %" : "8 %")
                  << " of Hertz, energy increases and non-descent directions "
                  << faces_increases << ", unsettled steps " << unsettled
                  << std::endl;
  SG_CHECK(faces_increases == 0, "the face potential never rose");
  SG_CHECK(unsettled == 0, "every step settled");
  SG_CHECK_CLOSE(
      f_faces.back(), exact.force, 0.08, 0, "Hertz force within 8 % on faces");
}
