// Implicit dynamics ('Time/Integrator = implicit dynamic', backward Euler
// with the lumped mass) against exact solutions:
//  1. Free fall: a block held by nothing, under gravity from rest. Backward
//     Euler integrates a constant acceleration exactly in the velocity,
//     v_N = g N dt, and gives u_N = g dt^2 N (N + 1) / 2 (first order in
//     dt against g t^2 / 2): both must hold to round-off, with the kinetic
//     energy 1/2 rho V v_N^2 (the lumped mass sums to the body's mass).
//  2. Slow loading: a block stretched by 20 % over a time far longer than
//     its natural period ends where the quasi-static solver ends; the
//     difference is the inertia of the last steps, O(dt / T).
//  3. A velocity-free restart: resuming from a checkpoint written halfway
//     reproduces the uninterrupted free fall (the velocity is saved).
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  const double L = 0.01; // block edge (m)

  std::string block_prm(const std::string &integrator,
                        const std::string &loading,
                        const double       end_time,
                        const double       dt,
                        const std::string &directory,
                        const std::string &checkpoint = "")
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n set Type = block\n"
        << " subsection Block\n  set Lower corner = 0, 0, 0\n"
        << "  set Upper corner = " << L << ", " << L << ", " << L
        << "\n  set Subdivisions = 2, 2, 2\n end\nend\n"
        << "subsection Finite element\n set Formulation = mixed u-p-J\nend\n"
        << "subsection Materials\n set Material ids = 0\n"
        << " subsection Material 0\n  set Model = neo-Hookean\n"
        << "  set Density = 1000\n"
        << "  subsection neo-Hookean\n   set Shear modulus = 1e4\n  end\n"
        << "  subsection Volumetric\n   set Poisson's ratio = 0.45\n  end\n"
        << " end\nend\n"
        << loading << "subsection Time\n set Integrator = " << integrator
        << "\n set End time = " << end_time << "\n set Time step = " << dt
        << "\nend\n"
        << "subsection Newton\n set Relative tolerance = 1e-12\nend\n"
        << "subsection Linear solver\n set Type = direct\nend\n"
        << "subsection Output\n set Directory = " << directory
        << "\n set VTU interval = 0\n set Verbose = false\n"
        << " set Monitor points = 0, 0, 0\nend\n"
        << checkpoint;
    return prm.str();
  }

  const std::string gravity = "subsection Boundary conditions\n"
                              " set Gravity = 0; 0; -9.81\nend\n";

  void free_fall()
  {
    const double g = 9.81, dt = 0.01;
    const int    N = 10;
    auto         solver =
        make_solver<3>(block_prm("implicit dynamic", gravity, N * dt, dt,
                                 "output-free-fall"));
    solver->run();
    const auto  &history = solver->history();
    const size_t last    = history.rows.size() - 1;
    const double u       = history.value(last, "u0_z");
    const double exact   = -g * dt * dt * N * (N + 1) / 2;
    const double energy  = history.value(last, "kinetic_energy");
    const double v       = g * N * dt;
    const double exact_energy = 0.5 * 1000 * L * L * L * v * v;
    dealii::deallog << "free fall: " << history.rows.size() - 1
                    << " steps, u_z = " << u << " m (backward Euler "
                    << exact << " m, exact motion " << -g * 0.5 * 0.01
                    << " m), E_kin = " << energy << " J (exact "
                    << exact_energy << " J)" << std::endl;
    SG_CHECK(std::abs(u - exact) < 1e-10 * std::abs(exact),
             "free fall: backward Euler displacement");
    SG_CHECK(std::abs(energy - exact_energy) < 1e-10 * exact_energy,
             "free fall: kinetic energy of the lumped mass");
  }

  void slow_loading()
  {
    // x = 0 held in x, y = 0 in y, z = 0 in z; x = L moved by 0.2 L.
    const std::string stretch =
        "subsection Boundary conditions\n"
        " set Dirichlet boundary ids = 0, 1, 2, 4\n"
        " subsection Dirichlet boundary 0\n  set Components = x\n end\n"
        " subsection Dirichlet boundary 2\n  set Components = y\n end\n"
        " subsection Dirichlet boundary 4\n  set Components = z\n end\n"
        " subsection Dirichlet boundary 1\n  set Components = x\n"
        "  set Displacement = 0.002 * t; 0; 0\n end\nend\n";
    const double reference =
        run_and_get<3>(block_prm("quasi-static", stretch, 1, 0.1,
                                 "output-slow-static"),
                       "reaction_1_x");
    for (const double dt : {0.1, 0.05})
    {
      const double force = run_and_get<3>(
          block_prm("implicit dynamic", stretch, 1, dt, "output-slow"),
          "reaction_1_x");
      const double difference = std::abs(force / reference - 1);
      dealii::deallog << "slow stretch, dt = " << dt
                      << " s: F = " << force << " N, quasi-static "
                      << reference << " N, relative difference "
                      << difference << std::endl;
      SG_CHECK(difference < 1e-6, "slow loading: the quasi-static force");
    }
  }

  void restart()
  {
    const double dt = 0.01;
    run_and_get<3>(block_prm("implicit dynamic", gravity, 0.05, dt,
                             "output-fall-restart",
                             "subsection Checkpoint\n set Interval = 5\nend\n"),
                   "u0_z");
    const double resumed = run_and_get<3>(
        block_prm("implicit dynamic", gravity, 0.1, dt, "output-fall-restart",
                  "subsection Checkpoint\n set Resume = true\nend\n"),
        "u0_z");
    const double exact = -9.81 * dt * dt * 10 * 11 / 2;
    dealii::deallog << "free fall resumed at t = 0.05 s: u_z = " << resumed
                    << " m (uninterrupted " << exact << " m)" << std::endl;
    SG_CHECK(std::abs(resumed - exact) < 1e-10 * std::abs(exact),
             "restart: the velocity is restored");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);
  free_fall();
  slow_loading();
  restart();
}
