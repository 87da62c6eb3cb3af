// Build a solver (Simulation::create: 'Time/Integrator') from the text of
// a parameter file, and the parameter files of the benchmark problems used by
// several tests.
#ifndef softgrasp_tests_solver_factory_h
#define softgrasp_tests_solver_factory_h

#include <memory>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>
#include <string>

namespace softgrasp_tests
{
  template <int dim>
  std::unique_ptr<softgrasp::Simulation<dim>>
  make_solver(const std::string &text)
  {
    dealii::ParameterHandler prm;
    softgrasp::Simulation<dim>::declare_parameters(prm);
    softgrasp::ParameterReader reader;
    softgrasp::Simulation<dim>::add_passes(reader);
    reader.read_string(prm, text, "test parameters");
    return softgrasp::Simulation<dim>::create(MPI_COMM_WORLD, prm);
  }

  /// Run a solver and return the last value of history column @p column.
  template <int dim>
  double run_and_get(const std::string &text, const std::string &column)
  {
    auto solver = make_solver<dim>(text);
    solver->run();
    const auto &history = solver->history();
    return history.value(history.rows.size() - 1, column);
  }

  /**
   * A neo-Hookean cube of edge @p L (m; mu = 10 kPa, nu = 0.45, density
   * 1000 kg/m^3, mixed u-p-J on 2 x 2 x 2 cells) on the symmetry planes x,
   * y, z = 0 (boundary ids 0, 2, 4), stretched along x by the face x = L
   * (id 1) moving by @p displacement (m, an expression in t); @p time: the
   * entries of subsection Time; direct solves to 1e-12; output into
   * @p directory, no VTU.
   */
  inline std::string stretched_cube_prm(const double       L,
                                        const std::string &displacement,
                                        const std::string &time,
                                        const std::string &directory)
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n set Type = block\n"
        << " subsection Block\n  set Upper corner = " << L << ", " << L << ", "
        << L << "\n  set Subdivisions = 2, 2, 2\n end\nend\n"
        << "subsection Finite element\n set Formulation = mixed u-p-J\nend\n"
        << "subsection Materials\n set Material ids = 0\n"
        << " subsection Material 0\n  set Model = neo-Hookean\n"
        << "  set Density = 1000\n"
        << "  subsection neo-Hookean\n   set Shear modulus = 1e4\n  end\n"
        << "  subsection Volumetric\n   set Poisson's ratio = 0.45\n  end\n"
        << " end\nend\n"
        << "subsection Boundary conditions\n"
        << " set Dirichlet boundary ids = 0, 1, 2, 4\n"
        << " subsection Dirichlet boundary 0\n  set Components = x\n end\n"
        << " subsection Dirichlet boundary 1\n  set Components = x\n"
        << "  set Displacement = " << displacement << "; 0; 0\n end\n"
        << " subsection Dirichlet boundary 2\n  set Components = y\n end\n"
        << " subsection Dirichlet boundary 4\n  set Components = z\n end\n"
        << "end\n"
        << "subsection Time\n"
        << time << "end\n"
        << "subsection Newton\n set Relative tolerance = 1e-12\nend\n"
        << "subsection Linear solver\n set Type = direct\nend\n"
        << "subsection Output\n set Directory = " << directory
        << "\n set VTU interval = 0\n set Verbose = false\nend\n";
    return prm.str();
  }

  /**
   * Cook's membrane with a neo-Hookean material (mu = 422.5 kPa, Simo-Taylor
   * volumetric energy) and 1 N on the right edge; the corner (48, 60) mm is
   * monitor point 0. In 3D: 1 mm thick, one element layer, front and back
   * faces free; in 2D: plane strain.
   */
  inline std::string cook_membrane_prm(const unsigned int dim,
                                       const unsigned int degree,
                                       const unsigned int n,
                                       const std::string &formulation,
                                       const double       nu,
                                       const std::string &linear_solver,
                                       const std::string &directory)
  {
    const std::string  zero = dim == 2 ? "0; 0" : "0; 0; 0";
    std::ostringstream s;
    s << "subsection Mesh\n set Type = Cook's membrane\n"
      << " subsection Cook's membrane\n  set Elements per edge = " << n
      << "\n  set Thickness = 0.001\n end\nend\n"
      << "subsection Finite element\n set Polynomial degree = " << degree
      << "\n set Formulation = " << formulation << "\nend\n"
      << "subsection Materials\n set Material ids = 0\n"
      << " subsection Material 0\n  set Model = neo-Hookean\n"
      << "  set Density = 1000\n"
      << "  subsection neo-Hookean\n   set Shear modulus = 422.5e3\n  end\n"
      << "  subsection Volumetric\n   set Energy = Simo-Taylor\n"
      << "   set Poisson's ratio = " << nu << "\n  end\n end\nend\n"
      << "subsection Boundary conditions\n set Dirichlet boundary ids = 0\n"
      << " set Traction boundary ids = 1\n"
      << " subsection Dirichlet boundary 0\n  set Components = "
      << (dim == 2 ? "x, y" : "x, y, z") << "\n  set Displacement = " << zero
      << "\n end\n subsection Traction boundary 1\n  set Traction = 0; "
      << "62.5e3 * t" << (dim == 3 ? "; 0" : "") << "\n end\nend\n"
      << "subsection Time\n set End time = 1\n set Time step = 0.25\nend\n"
      << "subsection Linear solver\n set Type = " << linear_solver << "\nend\n"
      << "subsection Output\n set Directory = " << directory
      << "\n set VTU interval = 0\n set Verbose = false\n"
      << " set Monitor points = 0.048, 0.060" << (dim == 3 ? ", 0.001" : "")
      << "\nend\n";
    return s.str();
  }
  /**
   * A neo-Hookean cube (20 mm, mu = 10 kPa, Poisson's ratio @p nu) compressed
   * by 20 % between bonded platens (boundary ids 4 and 5) in 10 load steps,
   * mixed u-p-J formulation, @p n cells per edge of degree @p degree; the
   * iterative solver with or without the block preconditioner
   * (@p linear_solver: direct, iterative). The classic test of a solver for
   * nearly incompressible solids. A non-empty @p augmentation sets 'Block
   * preconditioner augmentation' (else its default).
   */
  inline std::string compressed_block_prm(const unsigned int n,
                                          const unsigned int degree,
                                          const double       nu,
                                          const std::string &linear_solver,
                                          const bool         block,
                                          const std::string &directory,
                                          const bool         reuse_amg = false,
                                          const std::string &augmentation = "")
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n set Type = block\n subsection Block\n"
        << "  set Upper corner = 0.02, 0.02, 0.02\n  set Subdivisions = " << n
        << ", " << n << ", " << n << "\n end\nend\n"
        << "subsection Finite element\n set Polynomial degree = " << degree
        << "\n set Formulation = mixed u-p-J\nend\n"
        << "subsection Materials\n set Material ids = 0\n"
        << " subsection Material 0\n"
        << "  set Model = neo-Hookean\n  set Density = 1000\n"
        << "  subsection neo-Hookean\n   set Shear modulus = 1e4\n  end\n"
        << "  subsection Volumetric\n   set Poisson's ratio = " << nu
        << "\n  end\n end\nend\n"
        << "subsection Boundary conditions\n"
        << " set Dirichlet boundary ids = 4, 5\n"
        << " subsection Dirichlet boundary 5\n"
        << "  set Displacement = 0; 0; -0.004 * t\n end\nend\n"
        << "subsection Time\n set Time step = 0.1\nend\n"
        << "subsection Newton\n set Relative tolerance = 1e-8\nend\n"
        << "subsection Linear solver\n set Type = " << linear_solver
        << "\n set Relative tolerance = 1e-6\n"
        << " set Block preconditioner = " << (block ? "true" : "false")
        << "\n set Reuse AMG = " << (reuse_amg ? "true" : "false") << "\n"
        << (augmentation.empty() ? std::string()
                                 : " set Block preconditioner augmentation = " +
                                       augmentation + "\n")
        << "end\n"
        << "subsection Output\n set Directory = " << directory
        << "\n set VTU interval = 0\n set Verbose = false\nend\n";
    return prm.str();
  }
} // namespace softgrasp_tests

#endif
