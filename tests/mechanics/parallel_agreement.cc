// One and two MPI ranks give the same answer to solver tolerance: a
// nearly incompressible (nu = 0.49) block under gravity, a follower
// pressure on its top, its base moved sideways, in 3D with the mixed Q2-P1
// formulation, solved with AMG-preconditioned GMRES (the follower load makes
// the tangent unsymmetric). The golden files for 1 and 2 ranks are the
// same numbers printed to 6 digits. Also checked: the total vertical
// reaction balances the weight and the pressure resultant in the reference
// configuration to within the change of the loaded area (follower load).
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);

  const std::string prm    = R"(
subsection Mesh
  set Type = block
  set Global refinements = 1
  subsection Block
    set Lower corner = 0, 0, 0
    set Upper corner = 0.02, 0.02, 0.01
    set Subdivisions = 2, 2, 1
  end
end
subsection Finite element
  set Polynomial degree = 2
  set Formulation = mixed u-p-J
end
subsection Materials
  set Material ids = 0
  subsection Material 0
    set Preset = subcutaneous fat
    subsection Volumetric
      set Poisson's ratio = 0.49
    end
  end
end
subsection Boundary conditions
  set Dirichlet boundary ids = 4
  set Pressure boundary ids = 5
  set Gravity = 0; 0; -9.81 * t
  subsection Dirichlet boundary 4
    set Components = x, y, z
    set Displacement = 0.002 * t; 0; 0
  end
  subsection Pressure boundary 5
    set Pressure = 50 * t
  end
end
subsection Time
  set End time = 1
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-10
end
subsection Linear solver
  set Type = iterative
  set Relative tolerance = 1e-10
end
subsection Output
  set Directory = output-parallel
  set Verbose = false
  set Monitor points = 0.02, 0.02, 0.01; 0.01, 0.01, 0.01
end
)";
  auto              solver = make_solver<3>(prm);
  solver->run();
  const auto       &history = solver->history();
  const std::size_t last    = history.rows.size() - 1;
  for (const std::string column : {"reaction_4_x",
                                   "reaction_4_y",
                                   "reaction_4_z",
                                   "u0_x",
                                   "u0_y",
                                   "u0_z",
                                   "u1_x",
                                   "u1_y",
                                   "u1_z"})
    dealii::deallog << column << " = " << history.value(last, column)
                    << std::endl;
  dealii::deallog << "dofs: " << solver->system().n_dofs() << std::endl;

  // Weight rho g V plus pressure resultant on the (reference) top area: the
  // support carries it; the top face tilts and stretches a little under the
  // shear, so allow 5 %.
  const double density  = solver->materials().get(0).density();
  const double weight   = density * 9.81 * 0.02 * 0.02 * 0.01;
  const double pressure = 50 * 0.02 * 0.02;
  const double rz       = history.value(last, "reaction_4_z");
  // f_int - f_ext at the support is the force the support exerts: upwards.
  SG_CHECK(close(rz, weight + pressure, 0.05),
           "vertical reaction balances weight and pressure");
}
