// Benchmark: whole explicit steps of ExplicitSolver (central difference,
// matrix-free internal forces, forward-increment contact with a rigid
// sphere pressed into the top of a neo-Hookean block, mass damping), for Q1
// and Q2 at about 20k, 200k and 1M displacement DoFs.
//
// Reports per case: DoFs, cells, steps, time per step, DoF-steps per second
// (in total over all ranks), time per element per step, the share of the
// step spent in contact, and the peak resident memory per DoF. The step
// time is the solver's "time steps" timer (the integrator's steps with
// their contact treatment; set-up, stable-step estimates and records are
// left out). The matrix-based comparison of the force kernel is
// internal_force_throughput. Results in doc/benchmarks.md.
//
// Run: ./explicit_step [max DoFs, default 1.2e6]: every case in one process
//      (the peak memory column is then the running maximum), or
//      ./explicit_step <degree> <Q1 elements per edge: 18, 40 or 68>
//      [vectorized|reference]: one case with the given force kernel
//      (default vectorized), with its own peak memory
//      (benchmarks/explicit_step.sh runs every case this way, with both
//      kernels, on 1 and 2 ranks).
#include "peak_memory.h"

#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>

using namespace dealii;

namespace
{
  /// A 20 mm cube block, a sphere (R = 10 mm) pressed 0.2 mm into its top
  /// over the run; about @p steps steps of the stable size.
  std::string prm(const unsigned int n,
                  const unsigned int degree,
                  const unsigned int steps,
                  const std::string &kernel)
  {
    const double L = 0.02, mu = 10e3, nu = 0.45, rho = 1000;
    const double c = std::sqrt(2 * mu * (1 - nu) / (1 - 2 * nu) / rho);
    // Q1: critical step about h / (c sqrt 3); Q2 about half that.
    const double dt = 0.8 * L / n / degree / (c * std::sqrt(3.0)) / degree;
    const double T  = steps * dt;
    std::ostringstream s;
    s << "subsection Mesh\n set Type = block\n subsection Block\n"
      << "  set Lower corner = 0, 0, -0.02\n  set Upper corner = 0.02, 0.02, "
         "0\n"
      << "  set Subdivisions = " << n << ", " << n << ", " << n
      << "\n end\nend\n"
      << "subsection Finite element\n set Polynomial degree = " << degree
      << "\n set Formulation = displacement\nend\n"
      << "subsection Materials\n set Material ids = 0\n subsection Material 0\n"
      << "  set Model = neo-Hookean\n  set Density = " << rho
      << "\n  subsection neo-Hookean\n   set Shear modulus = " << mu
      << "\n  end\n  subsection Volumetric\n   set Poisson's ratio = " << nu
      << "\n  end\n end\nend\n"
      << "subsection Boundary conditions\n set Dirichlet boundary ids = 4\n"
      << " subsection Dirichlet boundary 4\n  set Components = x, y, z\n end\n"
      << "end\n"
      << "subsection Contact\n set Slave boundary ids = 5\n"
      << " set Friction coefficient = 0.3\nend\n"
      << "subsection Rigid bodies\n set Names = indenter\n"
      << " subsection Body indenter\n  set Geom names = ball\n"
      << "  set Trajectory = 0: 0.01, 0.01, 0.01, 1, 0, 0, 0; " << T
      << ": 0.01, 0.01, 0.0098, 1, 0, 0, 0\n"
      << "  subsection Geom ball\n   set Type = sphere\n   set Size = 0.01\n"
      << "  end\n end\nend\n"
      << "subsection Time\n set Integrator = explicit dynamic\n"
      << " set End time = " << T << "\n set Time step = " << T / 4 << "\nend\n"
      << "subsection Explicit dynamics\n set Mass damping = 100\n"
      << " set Stable step interval = 1000\n set Force kernel = " << kernel
      << "\nend\n"
      << "subsection Output\n set Directory = explicit-step-output\n"
      << " set VTU interval = 0\n set Verbose = false\nend\n";
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool   root     = Utilities::MPI::this_mpi_process(comm) == 0;
  const bool   single   = argc > 2;
  const double max_dofs = argc == 2 ? std::stod(argv[1]) : 1.2e6;
  if (root && !single)
    std::cout << "kernel,element,dofs,cells,steps,ms_per_step,dof_steps_per_s,"
                 "us_per_cell_step,contact_share,peak_kB_per_dof\n";
  std::vector<unsigned int> degrees = {1, 2}, sizes = {18, 40, 68};
  std::string               kernel = "vectorized";
  if (single)
  {
    degrees = {static_cast<unsigned int>(std::stoi(argv[1]))};
    sizes   = {static_cast<unsigned int>(std::stoi(argv[2]))};
    if (argc > 3)
      kernel = argv[3];
  }
  for (const unsigned int degree : degrees)
    for (const unsigned int n_q1 : sizes)
    {
      const unsigned int n    = n_q1 / degree;
      const double       dofs = 3.0 * std::pow(degree * n + 1, 3);
      if (dofs > max_dofs)
        continue;
      const unsigned int steps = dofs > 5e5 ? 100 : 400;
      ParameterHandler   handler;
      softgrasp::Simulation<3>::declare_parameters(handler);
      softgrasp::ParameterReader reader;
      softgrasp::Simulation<3>::add_passes(reader);
      reader.read_string(handler, prm(n, degree, steps, kernel), "benchmark");
      auto            solver = softgrasp::Simulation<3>::create(comm, handler);
      std::streambuf *silenced = std::cout.rdbuf(nullptr);
      solver->run();
      std::cout.rdbuf(silenced);
      const auto       &h     = solver->history();
      const std::size_t last  = h.rows.size() - 1;
      const double      taken = h.value(last, "time_steps");
      const auto        times =
          solver->timer().get_summary_data(TimerOutput::total_wall_time);
      const double per_step = times.at("time steps") / taken;
      const double contact  = times.at("contact") / taken;
      const double memory = Utilities::MPI::sum(peak_memory_mb(), comm) * 1024 /
                            solver->system().n_dofs();
      if (root)
        std::cout << kernel << ",Q" << degree << ","
                  << solver->system().n_dofs() << ","
                  << solver->system()
                         .dof_handler()
                         .get_triangulation()
                         .n_global_active_cells()
                  << "," << taken << "," << 1e3 * per_step << ","
                  << solver->system().n_dofs() / per_step << ","
                  << 1e6 * per_step /
                         solver->system()
                             .dof_handler()
                             .get_triangulation()
                             .n_global_active_cells() *
                         Utilities::MPI::n_mpi_processes(comm)
                  << "," << contact / per_step << "," << memory << std::endl;
    }
}
