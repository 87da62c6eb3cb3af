/* ---------------------------------------------------------------------------
 * Example: Hertz indentation of soft tissue by a rigid sphere
 *
 * The classic check of a contact code. A rigid sphere of radius R is
 * pressed a depth d into an elastic half-space (Young's modulus E,
 * Poisson's ratio nu). Hertz (1882) gives the force and the radius of the
 * circular contact patch,
 *     F = 4/3 E/(1 - nu^2) sqrt(R) d^(3/2),     a = sqrt(R d),
 * and an elliptical pressure p(r) = p0 sqrt(1 - r^2/a^2).
 *
 * Everything is set up in hertz_indentation.prm; the program is only the
 * driver. The .prm shows how a user declares, without writing code,
 *  - a rigid body ("Rigid bodies"): a sphere geom on a body that moves down
 *    along a pose trajectory "t: x, y, z, qw, qx, qy, qz; ...";
 *  - the contact surface of the tissue ("Contact/Slave boundary ids") and
 *    the friction coefficient (0 here, as in Hertz's theory);
 *  - a block mesh graded towards the contact ("Mesh/Block/Grading"), so the
 *    50 mm block behaves as a half-space while the 1 mm contact patch is
 *    resolved.
 *
 * What the solver does. Contact is a mortar method with dual Lagrange
 * multipliers: at each node j of the contact surface the gap g_j to the
 * sphere and the contact force f_j satisfy g_j >= 0, n.f_j >= 0 and
 * g_j n.f_j = 0 (the KKT conditions). A semi-smooth Newton method finds the
 * set of touching nodes and the displacements together; the log ("Verbose
 * = true") shows per iteration how many nodes touch and how many changed.
 * See doc/contact.md.
 *
 * Output (hertz_output/): hertz.pvd with contact_pressure, contact_gap and
 * contact_status on the surface; hertz_contact.csv with the force on the
 * sphere per step (resultant, normal and lateral parts); hertz_history.csv.
 *
 * Run:   ./hertz_indentation [hertz_indentation.prm]
 *        mpirun -np 2 ./hertz_indentation
 * ------------------------------------------------------------------------- */

#include <cmath>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/solvers/simulation.h>
#include <softgrasp/solvers/solver_program.h>
#include <string>

namespace
{
  /// Why Hertz's formula does not apply to the run's set-up, or "".
  std::string hertz_mismatch(const softgrasp::Simulation<3> &solver)
  {
    const auto &bodies = solver.rigid_bodies().bodies();
    if (bodies.size() != 1 || bodies[0].geoms().size() != 1)
      return "it needs exactly one rigid body with one geom";
    if (bodies[0].geoms()[0].shape->type() != "sphere")
      return "the geom is a " + bodies[0].geoms()[0].shape->type() +
             ", not a sphere";
    if (solver.materials().material_ids().size() != 1)
      return "it needs one material (the file has " +
             std::to_string(solver.materials().material_ids().size()) + ")";
    if (solver.contact_force_history().size() < 2)
      return "fewer than two steps were recorded";
    return "";
  }

  /// Compare the force on the sphere with Hertz's, if the set-up is his.
  void report(const softgrasp::Simulation<3> &solver)
  {
    softgrasp::report_contact_forces(solver, "hertz_forces", std::cout);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const std::string mismatch = hertz_mismatch(solver);
    if (!mismatch.empty())
    {
      std::cout << "\nNo comparison with Hertz: " << mismatch << '.'
                << std::endl;
      return;
    }
    // Hertz's values from the problem's own parameters: the sphere's
    // radius, the depth from its trajectory (first to last sample), E and
    // nu from the material.
    const auto  &body       = solver.rigid_bodies().bodies()[0];
    const double R          = body.geoms()[0].shape->bounding_radius();
    const auto  &trajectory = body.trajectory();
    const double d = trajectory.pose(trajectory.times().front()).position[2] -
                     trajectory.pose(trajectory.times().back()).position[2];
    const auto &material =
        solver.materials().get(solver.materials().material_ids()[0]);
    const double mu    = material.initial_shear_modulus();
    const double kappa = material.bulk_modulus();
    const double E     = 9 * kappa * mu / (3 * kappa + mu);
    const double nu    = (3 * kappa - 2 * mu) / (2 * (3 * kappa + mu));
    const double F_hertz =
        4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R) * std::pow(d, 1.5);

    // hertz_indentation.prm models a quarter of the problem (symmetry planes
    // x = 0 and y = 0): 4 times the force on the ball.
    const double F =
        4 * solver.contact_force_history().back().forces[0][0].normal_force();
    std::cout << "\nIndentation d = " << d * 1e3 << " mm by R = " << R * 1e3
              << " mm: force " << F * 1e3 << " mN, Hertz " << F_hertz * 1e3
              << " mN (" << std::showpos << 100 * (F / F_hertz - 1)
              << std::noshowpos << " %); Hertz contact radius "
              << std::sqrt(R * d) * 1e3 << " mm." << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  softgrasp::SolverProgram program;
  program.default_parameter_file = "hertz_indentation.prm";
  program.name                   = "hertz_indentation";
  program.report_3d              = report;
  return program.run(argc, argv);
}
