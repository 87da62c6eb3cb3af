// Benchmark of mortar contact (not a test): the Hertz indentation of
// tests/contact_factory.h (rigid sphere R = 10 mm, d = 0.1 mm, neo-Hookean
// mu = 10 kPa, nu = 0.45, quarter model, frictionless) on a graded block.
//
//   hertz_contact <n> <ratio> <size (m)> [degree] [steps] [direct|iterative]
//                 [global refinements] [nu] [depth (m)]
//                 [inexact linear solves: true|false]
//                 [block preconditioner: true|false] [reuse AMG: true|false]
//                 [contact enforcement, e.g. "incremental potential"]
//   mpirun -np 2 hertz_contact 8 1.5 0.05 2 4 iterative 1
//
// Prints the force and the contact radius against Hertz's values, Newton
// iterations and active-set changes per load step, and the wall time per
// phase (contact search and nodal conditions, assembly, linear solve).
#include "../tests/contact_factory.h"

#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/solvers/simulation.h>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm  = MPI_COMM_WORLD;
  const unsigned int               n     = argc > 1 ? std::stoi(argv[1]) : 12;
  const double                     ratio = argc > 2 ? std::stod(argv[2]) : 1.3;
  const double                     size  = argc > 3 ? std::stod(argv[3]) : 0.03;
  const unsigned int               degree = argc > 4 ? std::stoi(argv[4]) : 1;
  const unsigned int               steps  = argc > 5 ? std::stoi(argv[5]) : 4;
  const std::string                solver_type = argc > 6 ? argv[6] : "direct";
  const unsigned int refinements = argc > 7 ? std::stoi(argv[7]) : 0;
  const double       nu          = argc > 8 ? std::stod(argv[8]) : 0.45;
  const double       depth       = argc > 9 ? std::stod(argv[9]) : 1e-4;
  const std::string  inexact     = argc > 10 ? argv[10] : "true";
  const std::string  block       = argc > 11 ? argv[11] : "true";
  const std::string  reuse_amg   = argc > 12 ? argv[12] : "true";
  const std::string enforcement = argc > 13 ? argv[13] : "lagrange multipliers";

  ParameterHandler prm;
  softgrasp::Simulation<3>::declare_parameters(prm);
  softgrasp::ParameterReader reader;
  softgrasp::Simulation<3>::add_passes(reader);
  reader.read_string(
      prm,
      softgrasp_tests::hertz_prm(n,
                                 ratio,
                                 size,
                                 degree,
                                 steps,
                                 "hertz-benchmark",
                                 solver_type,
                                 refinements,
                                 nu,
                                 depth) +
          "subsection Newton\n set Inexact linear solves = " + inexact +
          "\nend\nsubsection Linear solver\n set Block "
          "preconditioner = " +
          block + "\n set Reuse AMG = " + reuse_amg +
          "\nend\nsubsection Contact\n set Enforcement = " + enforcement +
          // node-wise, as the multipliers and doc/benchmarks.md's table (the
          // implicit default since 2026-12-07 is the faces)
          "\n set Potential integration = nodes\nend\n",
      "benchmark");
  softgrasp::Simulation<3> solver(comm, softgrasp::SolverInputs<3>::parse(prm));
  solver.run();

  const auto   exact  = softgrasp_tests::hertz_solution(nu, depth);
  const auto   forces = solver.contact_output()->geom_forces(solver.system());
  const double force  = 4 * forces[0][0].force[2];
  const double radius = softgrasp_tests::edge_contact_radius(solver);
  auto times = solver.timer().get_summary_data(TimerOutput::total_wall_time);
  if (Utilities::MPI::this_mpi_process(comm) == 0)
  {
    const auto &history = solver.history();
    double      newton = 0, changes = 0, linear = 0, outer = 0;
    const bool  potential = enforcement == "incremental potential";
    for (std::size_t row = 1; row < history.rows.size(); ++row)
    {
      if (potential)
        outer += history.value(row, "outer_iterations");
      newton += history.value(row, "newton_iterations");
      linear += history.value(row, "linear_iterations");
      changes += history.value(row, "active_set_changes");
    }
    const double n_steps = history.rows.size() - 1;
    std::cout << "HERTZ n=" << n << " ratio=" << ratio << " size=" << size
              << " refinements=" << refinements << " Q" << degree
              << " dofs=" << solver.system().n_dofs()
              << " ranks=" << Utilities::MPI::n_mpi_processes(comm)
              << " enforcement=" << enforcement << "\n  force " << force
              << " N, error " << 100 * (force / exact.force - 1) << " %"
              << "\n  contact radius (gap edge) " << radius * 1e3
              << " mm, error " << 100 * (radius / exact.radius - 1) << " %"
              << "\n  Newton iterations per step " << newton / n_steps
              << ", active-set changes per step " << changes / n_steps
              << ", outer iterations per step "
              << (potential ? outer / n_steps : 1.0)
              << "\n  linear iterations per Newton step " << linear / newton
              << std::endl;
    const double steps_time = times["contact"] + times["assembly"] +
                              times["residual"] + times["linear solve"];
    std::cout << "  wall time: contact search and nodal conditions "
              << times["contact"] << " s ("
              << 100 * times["contact"] / steps_time
              << " % of the load steps), assembly " << times["assembly"]
              << " s, residual " << times["residual"] << " s, linear solve "
              << times["linear solve"] << " s, setup " << times["setup"]
              << " s, load steps and setup " << steps_time + times["setup"]
              << " s" << std::endl;
  }
}
