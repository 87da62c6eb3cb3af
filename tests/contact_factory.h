// Parameter-file fragments shared by the contact tests.
#ifndef softgrasp_tests_contact_factory_h
#define softgrasp_tests_contact_factory_h

#include <cmath>
#include <sstream>
#include <string>

namespace softgrasp_tests
{
  /// A compressible neo-Hookean material 0 (mu in Pa).
  inline std::string neo_hookean(const double mu, const double nu)
  {
    std::ostringstream s;
    s << "subsection Materials\n set Material ids = 0\n"
      << " subsection Material 0\n  set Model = neo-Hookean\n"
      << "  set Density = 1000\n"
      << "  subsection neo-Hookean\n   set Shear modulus = " << mu
      << "\n  end\n  subsection Volumetric\n   set Poisson's ratio = " << nu
      << "\n  end\n end\nend\n";
    return s.str();
  }

  /// A block mesh from @p lower to @p upper (comma-separated, m).
  inline std::string block(const std::string &lower,
                           const std::string &upper,
                           const std::string &subdivisions,
                           const std::string &grading    = "1",
                           const double       distortion = 0)
  {
    std::ostringstream s;
    s << "subsection Mesh\n set Type = block\n set Distortion = " << distortion
      << "\n subsection Block\n  set Lower corner = " << lower
      << "\n  set Upper corner = " << upper
      << "\n  set Subdivisions = " << subdivisions
      << "\n  set Grading = " << grading << "\n end\nend\n";
    return s.str();
  }

  /// One rigid body with one geom.
  inline std::string rigid_body(const std::string &body,
                                const std::string &geom,
                                const std::string &type,
                                const std::string &size,
                                const std::string &trajectory,
                                const std::string &orientation = "1, 0, 0, 0")
  {
    std::ostringstream s;
    s << "subsection Rigid bodies\n set Names = " << body
      << "\n subsection Body " << body << "\n  set Geom names = " << geom
      << "\n  set Trajectory = " << trajectory << "\n  subsection Geom " << geom
      << "\n   set Type = " << type << "\n   set Size = " << size
      << "\n   set Orientation = " << orientation << "\n  end\n end\nend\n";
    return s.str();
  }

  /// Contact on the boundary ids @p slave with friction @p mu.
  inline std::string contact(const std::string &slave, const double mu)
  {
    std::ostringstream s;
    s << "subsection Contact\n set Slave boundary ids = " << slave
      << "\n set Friction coefficient = " << mu << "\nend\n";
    return s.str();
  }
  /**
   * The Coulomb block: a 10 x 10 x 5 mm neo-Hookean block (mu = 10 kPa,
   * nu = 0.3) on a rigid floor (plane geom, friction @p mu), its top face
   * (id 5) moved by @p top_displacement (a muParser vector expression of
   * t, m); the bottom (id 4) is the contact surface.
   */
  inline std::string block_on_floor(const double       mu,
                                    const std::string &top_displacement)
  {
    std::ostringstream s;
    s << block("0, 0, 0", "0.01, 0.01, 0.005", "4, 4, 2")
      << neo_hookean(10e3, 0.3) << "subsection Boundary conditions\n"
      << " set Dirichlet boundary ids = 5\n"
      << " subsection Dirichlet boundary 5\n  set Components = x, y, z\n"
      << "  set Displacement = " << top_displacement << "\n end\nend\n"
      << contact("4", mu)
      << rigid_body("floor", "plane", "plane", "1", "0: 0, 0, 0, 1, 0, 0, 0");
    return s.str();
  }

  /**
   * The contact patch test: a flat rigid plate (plane geom 'plate'/'face',
   * its normal down) compresses a randomly distorted neo-Hookean block
   * (10 mm, mu = 10 kPa, nu = 0.3, degree @p degree) by 10 % in 4 steps,
   * frictionless, on rollers at x = 0, y = 0 (and z = 0); contact on the
   * top face. Newton to 1e-12, direct solves; the caller adds 'Output'.
   */
  inline std::string plate_compression_prm(const unsigned int dim,
                                           const unsigned int degree)
  {
    std::ostringstream prm;
    prm << (dim == 3
                ? block(
                      "0, 0, 0", "0.01, 0.01, 0.01", "3, 3, 3", "1, 1, 1", 0.2)
                : block("0, 0", "0.01, 0.01", "4, 3", "1, 1", 0.2))
        << "subsection Finite element\n set Polynomial degree = " << degree
        << "\nend\n"
        << neo_hookean(10e3, 0.3) << "subsection Boundary conditions\n"
        << " set Dirichlet boundary ids = 0, 2" << (dim == 3 ? ", 4" : "")
        << "\n subsection Dirichlet boundary 0\n  set Components = x\n end\n"
        << " subsection Dirichlet boundary 2\n  set Components = y\n end\n"
        << (dim == 3 ? " subsection Dirichlet boundary 4\n  set Components = "
                       "z\n end\n"
                     : "")
        << "end\n"
        << contact(dim == 3 ? "5" : "3", 0)
        // the plane's normal (local z) points down: along -z in 3D, along
        // -y in 2D (the plane problem lies in x-y)
        << rigid_body(
               "plate",
               "face",
               "plane",
               "1",
               "0: " + std::string(dim == 3 ? "0, 0, 0.01" : "0, 0.01, 0") +
                   ", 1, 0, 0, 0; 1: " +
                   std::string(dim == 3 ? "0, 0, 0.009" : "0, 0.009, 0") +
                   ", 1, 0, 0, 0",
               dim == 3 ? "0, 1, 0, 0"
                        : "0.70710678118654752, 0.70710678118654752, 0, 0")
        << "subsection Time\n set End time = 1\n set Time step = 0.25\nend\n"
        << "subsection Newton\n set Relative tolerance = 1e-12\nend\n"
        << "subsection Linear solver\n set Type = direct\nend\n"
        << "subsection Output\n set VTU interval = 0\n set Verbose = false\n"
        << "end\n";
    return prm.str();
  }

  /**
   * The plane-strain frictional drag of examples/frictional_drag: a rigid
   * cylinder (R = 10 mm, geom finger/link, reference normal -y) pressed
   * 5 mm into a 120 x 20 mm block (G = 17.2 kPa, nu = 0.45, Q1 mixed u-p-J,
   * 60 x 10 cells, bonded base id 2, contact on the top id 3) until
   * t = 0.5 s and pulled 20 mm along x until t = 1.5 s, friction @p mu.
   * The caller adds the 'Time' and 'Output' subsections.
   */
  inline std::string frictional_drag_prm(const double mu)
  {
    std::ostringstream s;
    s << block("-0.06, 0", "0.06, 0.02", "60, 10")
      << "subsection Finite element\n set Formulation = mixed u-p-J\n"
      << " set Polynomial degree = 1\nend\n"
      << neo_hookean(17241.4, 0.45)
      << "subsection Boundary conditions\n set Dirichlet boundary ids = 2\n"
      << " subsection Dirichlet boundary 2\n  set Components = x, y\n"
      << " end\nend\n"
      << contact("3", mu) << "subsection Rigid bodies\n set Names = finger\n"
      << " subsection Body finger\n  set Geom names = link\n"
      << "  set Trajectory = 0: -0.01, 0.0305, 0, 1, 0, 0, 0; "
      << "0.5: -0.01, 0.0255, 0, 1, 0, 0, 0; 1.5: 0.01, 0.0255, 0, 1, 0, 0, "
         "0\n"
      << "  subsection Geom link\n   set Type = cylinder\n"
      << "   set Size = 0.01, 0.1\n   set Reference normal = 0, -1, 0\n"
      << "  end\n end\nend\n";
    return s.str();
  }
} // namespace softgrasp_tests

#endif

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <softgrasp/solvers/simulation.h>

namespace softgrasp_tests
{
  /**
   * Hertz indentation, quarter model: a rigid sphere (R = 10 mm) pressed
   * d = 0.1 mm into a neo-Hookean block (mu = 10 kPa, nu = 0.45) of
   * @p size (m) per side (the contact radius is 1 mm), symmetry planes x = 0
   * and y = 0, a roller at the bottom, frictionless. The block mesh is graded
   * towards the contact with @p n elements per direction and neighbour size
   * ratio
   * @p ratio.
   */
  inline std::string hertz_prm(const unsigned int n,
                               const double       ratio,
                               const double       size,
                               const unsigned int degree,
                               const unsigned int steps,
                               const std::string &directory,
                               const std::string &linear_solver = "direct",
                               const unsigned int refinements   = 0,
                               const double       nu            = 0.45,
                               const double       depth         = 1e-4)
  {
    std::ostringstream s, sub, grading;
    sub << n << ", " << n << ", " << n;
    grading << ratio << ", " << ratio << ", " << 1 / ratio;
    s << ""
      << block("0, 0, " + std::to_string(-size),
               std::to_string(size) + ", " + std::to_string(size) + ", 0",
               sub.str(),
               grading.str())
      << "subsection Mesh\n set Global refinements = " << refinements
      << "\nend\n"
      << "subsection Finite element\n set Polynomial degree = " << degree
      << "\nend\n"
      << neo_hookean(10e3, nu) << "subsection Boundary conditions\n"
      << " set Dirichlet boundary ids = 0, 2, 4\n"
      << " subsection Dirichlet boundary 0\n  set Components = x\n end\n"
      << " subsection Dirichlet boundary 2\n  set Components = y\n end\n"
      << " subsection Dirichlet boundary 4\n  set Components = z\n end\n"
      << "end\n"
      << contact("5", 0)
      << rigid_body("indenter",
                    "ball",
                    "sphere",
                    "0.01",
                    "0: 0, 0, 0.01, 1, 0, 0, 0; 1: 0, 0, " +
                        std::to_string(0.01 - depth) + ", 1, 0, 0, 0")
      << "subsection Time\n set End time = 1\n set Time step = " << 1.0 / steps
      << "\nend\n"
      << "subsection Linear solver\n set Type = " << linear_solver << "\nend\n"
      << "subsection Output\n set Directory = " << directory
      << "\n set VTU interval = 0\n set Verbose = false\nend\n";
    return s.str();
  }

  /// The indenter trajectory of hertz_prm() pressed @p depth (m) along a
  /// cosine ramp d(t) = depth (1 - cos(pi t / T)) / 2 over [0, T] (zero
  /// speed at both ends), sampled at 41 points.
  inline std::string cosine_ramp_trajectory(const double depth, const double T)
  {
    std::ostringstream s;
    s.precision(12);
    for (unsigned int k = 0; k <= 40; ++k)
    {
      const double t = T * k / 40;
      const double d = depth * (1 - std::cos(M_PI * t / T)) / 2;
      s << (k ? "; " : "") << t << ": 0, 0, " << 0.01 - d << ", 1, 0, 0, 0";
    }
    return s.str();
  }

  /**
   * The smallest and largest nominal contact pressure n . f / A_0 (Pa; N/m
   * per metre in 2D) over the contact nodes of @p run, which must all be
   * closed (a pressed face). Collective.
   */
  template <int dim>
  std::pair<double, double>
  closed_pressure_range(const softgrasp::Simulation<dim> &run)
  {
    double p_min = 1e300, p_max = -1e300;
    for (const auto &node : run.contact()->nodes())
    {
      if (node.status == softgrasp::ContactStatus::inactive)
      {
        std::cerr << "a node of the pressed face is open" << std::endl;
        std::abort();
      }
      const double p = node.normal.dot(node.force) / node.reference_area;
      p_min          = std::min(p_min, p);
      p_max          = std::max(p_max, p);
    }
    return {dealii::Utilities::MPI::min(p_min, MPI_COMM_WORLD),
            dealii::Utilities::MPI::max(p_max, MPI_COMM_WORLD)};
  }

  /// Hertz's values for the problem of hertz_prm() (full sphere).
  struct HertzSolution
  {
    double force;  ///< (4/3) E* sqrt(R) d^3/2 (N)
    double radius; ///< sqrt(R d) (m)
  };
  inline HertzSolution hertz_solution(const double nu = 0.45,
                                      const double d  = 1e-4)
  {
    const double mu = 10e3, R = 0.01;
    const double E_star = 2 * mu * (1 + nu) / (1 - nu * nu);
    return {4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(d, 1.5),
            std::sqrt(R * d)};
  }

  /**
   * The contact radius of an indentation centred on the z axis, from the
   * surface nodes on the symmetry plane y = 0: the edge lies between the
   * last closed node and the first open one, and is placed where the gaps
   * g1, g2 of the first two open nodes (at r1 < r2) extrapolate to zero
   * with the opening law g ~ (r - a)^(3/2) of a smooth contact edge:
   *   a = r1 - g1^(2/3) (r2 - r1) / (g2^(2/3) - g1^(2/3)),
   * clamped to [last closed, first open]. Collective.
   */
  template <int dim>
  double edge_contact_radius(const softgrasp::Simulation<dim> &solver)
  {
    const auto         &contact = *solver.contact();
    const auto         &u       = solver.system().ghosted_solution();
    std::vector<double> data; // r, gap, closed
    for (const auto &node : contact.nodes())
    {
      if (dim == 3 && std::abs(node.reference_position[1]) > 1e-12)
        continue;
      data.push_back(node.reference_position[0] + u[node.dofs[0]]);
      data.push_back(node.gap);
      data.push_back(node.status != softgrasp::ContactStatus::inactive);
    }
    std::vector<std::array<double, 3>> nodes;
    for (const auto &part :
         dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, data))
      for (std::size_t i = 0; i + 2 < part.size(); i += 3)
        nodes.push_back({{part[i], part[i + 1], part[i + 2]}});
    std::sort(nodes.begin(), nodes.end());
    double last_closed = 0;
    for (const auto &n : nodes)
      if (n[2] > 0)
        last_closed = std::max(last_closed, n[0]);
    std::vector<std::array<double, 3>> open;
    for (const auto &n : nodes)
      if (n[0] > last_closed)
        open.push_back(n);
    if (open.size() < 2)
      return last_closed;
    const double k1 = std::pow(std::max(open[0][1], 0.0), 2.0 / 3.0);
    const double k2 = std::pow(std::max(open[1][1], 0.0), 2.0 / 3.0);
    const double a  = open[0][0] - k1 * (open[1][0] - open[0][0]) / (k2 - k1);
    return std::min(std::max(a, last_closed), open[0][0]);
  }
} // namespace softgrasp_tests
