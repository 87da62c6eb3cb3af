// Benchmark of the quasi-static solver (not a test): a nearly incompressible
// neo-Hookean block (mu = 10 kPa, nu = 0.49) compressed by 20 % between
// bonded platens in 10 load steps, mixed u-p-J formulation, AMG-CG.
//
//   solver_scaling <cells per edge> [degree] [nu] [block: true|false]
//                  [reuse AMG: true|false] [augmentation]
//   mpirun -np 2 solver_scaling 31
//
// Prints one line: DoFs, ranks, wall time per phase (TimerOutput), Newton
// and linear iterations per step, and peak resident memory (sum over ranks).
// Q1 DoFs = 3 (n+1)^3: n = 14 -> 10k, 31 -> 98k, 46 -> 311k.
// Q2 DoFs = 3 (2n+1)^3: n = 7 -> 10k, 16 -> 108k, 23 -> 311k.
// 'block' selects 'Linear solver/Block preconditioner' (default true),
// 'augmentation' sets 'Linear solver/Block preconditioner augmentation'
// (default: the parameter's default).
#include "../tests/solver_factory.h"

#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>
#include <sys/resource.h>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm   = MPI_COMM_WORLD;
  const unsigned                   n      = argc > 1 ? std::stoi(argv[1]) : 14;
  const unsigned                   degree = argc > 2 ? std::stoi(argv[2]) : 1;
  const double                     nu = argc > 3 ? std::stod(argv[3]) : 0.49;

  const bool block     = argc > 4 ? std::string(argv[4]) != "false" : true;
  const bool reuse_amg = argc > 5 ? std::string(argv[5]) != "false" : true;
  const std::string prm =
      softgrasp_tests::compressed_block_prm(n,
                                            degree,
                                            nu,
                                            "iterative",
                                            block,
                                            "solver_scaling_output",
                                            reuse_amg,
                                            argc > 6 ? argv[6] : "");

  ParameterHandler prm_handler;
  softgrasp::Simulation<3>::declare_parameters(prm_handler);
  softgrasp::ParameterReader reader;
  softgrasp::Simulation<3>::add_passes(reader);
  reader.read_string(prm_handler, prm, "solver_scaling");
  softgrasp::Simulation<3> solver(
      comm, softgrasp::SolverInputs<3>::parse(prm_handler));
  solver.run();

  const auto times =
      solver.timer().get_summary_data(TimerOutput::total_wall_time);
  const auto get = [&](const std::string &name)
  {
    const auto it = times.find(name);
    return it == times.end() ? 0.0 : Utilities::MPI::max(it->second, comm);
  };
  // Collective reductions: evaluate on every rank, print on rank 0.
  const double t_setup = get("setup"), t_assembly = get("assembly"),
               t_residual = get("residual"), t_solve = get("linear solve"),
               t_output = get("output");
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double memory_mb =
      Utilities::MPI::sum(usage.ru_maxrss / 1024.0, comm); // kB -> MB

  const auto        &history = solver.history();
  std::ostringstream newton, linear;
  double             total_newton = 0, total_linear = 0;
  for (std::size_t r = 1; r < history.rows.size(); ++r)
  {
    const double ni = history.value(r, "newton_iterations");
    const double li = history.value(r, "linear_iterations");
    newton << (r > 1 ? "," : "") << ni;
    linear << (r > 1 ? "," : "") << (ni > 0 ? li / ni : 0);
    total_newton += ni;
    total_linear += li;
  }
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::cout << std::fixed << std::setprecision(2) << "\nRESULT dofs "
              << solver.system().n_dofs() << " ranks "
              << Utilities::MPI::n_mpi_processes(comm) << " setup " << t_setup
              << " s assembly " << t_assembly << " s residual " << t_residual
              << " s linear_solve " << t_solve << " s output " << t_output
              << " s total "
              << history.value(history.rows.size() - 1, "wall_time")
              << " s newton_total " << total_newton << " linear_per_newton "
              << total_linear / std::max(1.0, total_newton)
              << " peak_memory_MB " << memory_mb << "\nnewton_per_step "
              << newton.str() << "\nlinear_per_newton_per_step " << linear.str()
              << std::endl;
}
