// Hertz indentation: a rigid sphere (R = 10 mm) pressed d = 0.1 mm into a
// neo-Hookean half-space (a 50 mm block, i.e. 50 contact radii, quarter
// model), frictionless, on a graded Q1 mesh (8 elements per direction,
// size ratio 1.5, refined once; AMG-GMRES). Hertz:
// F = (4/3) E/(1 - nu^2) sqrt(R) d^3/2, contact radius a = sqrt(R d).
// The force must be within 5 % and the contact radius within 10 %; the
// convergence study is benchmarks/hertz_contact (doc/benchmarks.md).
// Run on one and on two MPI ranks, with the same expected output.
// The run also checks the KKT conditions at every slave node.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);

  const auto exact  = hertz_solution();
  auto       solver = make_solver<3>(
      hertz_prm(8, 1.5, 0.05, 1, 4, "output-hertz", "iterative", 1));
  solver->run();

  const auto  &contact = *solver->contact();
  const auto   forces = solver->contact_output()->geom_forces(solver->system());
  const double force  = 4 * forces[0][0].force[2]; // quarter model
  const double radius = edge_contact_radius(*solver);

  // KKT at every node: no penetration, no tension, complementarity.
  double min_gap = 0, min_pressure = 0, max_product = 0;
  for (const auto &node : contact.nodes())
  {
    const double f_n = node.normal.dot(node.force);
    min_gap          = std::min(min_gap, node.gap);
    if (node.status != softgrasp::ContactStatus::inactive)
    {
      min_pressure = std::min(min_pressure, f_n);
      max_product  = std::max(max_product, std::abs(f_n * node.gap));
    }
  }
  min_gap      = dealii::Utilities::MPI::min(min_gap, MPI_COMM_WORLD);
  min_pressure = dealii::Utilities::MPI::min(min_pressure, MPI_COMM_WORLD);
  max_product  = dealii::Utilities::MPI::max(max_product, MPI_COMM_WORLD);

  const auto &history = solver->history();
  for (std::size_t row = 1; row < history.rows.size(); ++row)
    dealii::deallog << "step " << row << ": Newton "
                    << history.value(row, "newton_iterations")
                    << ", active-set changes "
                    << history.value(row, "active_set_changes") << std::endl;
  dealii::deallog << "force " << force << " N (Hertz " << exact.force
                  << " N, error " << 100 * (force / exact.force - 1) << " %)"
                  << std::endl;
  dealii::deallog << "contact radius " << radius * 1e3 << " mm (Hertz "
                  << exact.radius * 1e3 << " mm, error "
                  << 100 * (radius / exact.radius - 1) << " %)" << std::endl;
  dealii::deallog << "closed nodes " << contact.n_active() << std::endl;

  SG_CHECK_CLOSE(force, exact.force, 0.05, 0, "Hertz force within 5 %");
  SG_CHECK_CLOSE(radius, exact.radius, 0.10, 0, "contact radius within 10 %");
  SG_CHECK(min_gap > -1e-12, "no penetration");
  SG_CHECK(min_pressure > -1e-12 * exact.force, "no tensile contact force");
  SG_CHECK(max_product < 1e-16, "complementarity g f_n = 0");
}
