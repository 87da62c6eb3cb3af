// The step's potential E(u) that 'Contact/Enforcement = incremental
// potential' minimises (SolidSystem::assemble: strain energy with the
// element dilatation condensed, the inertia term, minus the work of dead
// loads, plus each contact node's augmented Lagrangian and lagged friction
// potential) against its gradient and Hessian by central differences:
//   -residual_i   = dE/du_i                (relative error <= 1e-6),
//   tangent_ij    = -d residual_i / du_j    (relative error <= 1e-6),
// over the free degrees of freedom of one cell, for the pure displacement
// element (Q1), mean dilatation (Q1-P0) and the projected dilatation
// (Q2-P1), a neo-Hookean and an anisotropic Holzapfel-Gasser-Ogden
// material, in 3D and 2D (plane strain). The cell is bonded at its base
// and a rigid sphere (cylinder in 2D) has been pressed into a corner of
// its top face by one converged step of the potential enforcement; the
// state is then moved off equilibrium by a fixed pseudo-random
// displacement, with at least one contact node closed and one open there
// (checked). Variants add friction (mu = 0.3, the lagged normal forces of
// the converged step), gravity (a dead load) and the inertia of an
// implicit dynamic step, and the potential integrated at the Gauss points
// of the faces ('Potential integration = faces').
#include "../contact_factory.h"
#include "../material_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/contact/potential_contact.h>
#include <softgrasp/solvers/simulation_access.h>

using namespace softgrasp_tests;

namespace
{
  const double L = 0.01; ///< cell edge (m)

  struct Case
  {
    unsigned int dim;
    unsigned int degree;
    std::string  formulation;
    std::string  material; ///< a name of model_fragments()
    double       friction = 0;
    bool         gravity  = false;
    bool         dynamic  = false;
    bool         faces    = false; ///< 'Potential integration = faces'
  };

  std::string material_prm(const std::string &name)
  {
    for (const auto &[model, fragment] : model_fragments("Simo-Taylor", "0.45"))
      if (model == name)
        return "subsection Materials\n set Material ids = 0\n"
               " subsection Material 0\n" +
               fragment + "\n end\nend\n";
    SG_CHECK(false, "unknown material " + name);
    return "";
  }

  /// One cell bonded at its base; a rigid sphere (cylinder along z in 2D)
  /// of radius 2 L, 0.01 L above the corner of the top face at the origin,
  /// pressed 0.05 L into it in one step.
  std::string case_prm(const Case &c)
  {
    const bool         three = c.dim == 3;
    const std::string  top   = three ? "5" : "3";
    std::ostringstream s;
    s.precision(12);
    const double centre = L + 2 * L; // of the indenter, touching at t = 0
    s << (three ? block("0, 0, 0", "0.01, 0.01, 0.01", "1, 1, 1")
                : block("0, 0", "0.01, 0.01", "1, 1"))
      << "subsection Finite element\n set Polynomial degree = " << c.degree
      << "\n set Formulation = " << c.formulation << "\nend\n"
      << material_prm(c.material) << "subsection Boundary conditions\n"
      << " set Dirichlet boundary ids = " << (three ? "4" : "2") << "\n"
      << (c.gravity ? std::string(" set Gravity = 3; -2") +
                          (three ? "; -9.81" : "") + "\n"
                    : "")
      << " subsection Dirichlet boundary " << (three ? "4" : "2")
      << "\n  set Components = " << (three ? "x, y, z" : "x, y")
      << "\n end\nend\n"
      << contact(top, c.friction)
      << "subsection Contact\n set Enforcement = incremental potential\n"
      // a soft penalty: the closed node's gap (lam/k in the augmented
      // Lagrangian's closed range) larger than the perturbation below
      << " set Penalty factor = 1\n set Potential integration = "
      << (c.faces ? "faces" : "nodes") << "\nend\n";
    const std::string T    = c.dynamic ? "0.01" : "1"; // s
    const std::string axis = three ? "0, 0, " : "0, ";
    const std::string z    = three ? "" : ", 0";
    s << rigid_body("indenter",
                    "tip",
                    three ? "sphere" : "cylinder",
                    three ? "0.02" : "0.02, 0.1",
                    "0: " + axis + std::to_string(centre + 0.01 * L) + z +
                        ", 1, 0, 0, 0; " + T + ": " + axis +
                        std::to_string(centre - 0.04 * L) + z + ", 1, 0, 0, 0")
      << "subsection Time\n set Integrator = "
      << (c.dynamic ? "implicit dynamic" : "quasi-static")
      << "\n set End time = " << T << "\n set Time step = " << T << "\nend\n"
      << "subsection Linear solver\n set Type = direct\nend\n"
      << "subsection Output\n set Directory = output-derivatives\n"
      << " set VTU interval = 0\n set Verbose = false\nend\n";
    return s.str();
  }

  /// A fixed pseudo-random number in [-1, 1] (the same on every machine).
  double next_random(unsigned long &state)
  {
    state = (state * 6364136223846793005UL + 1442695040888963407UL);
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2 - 1;
  }

  struct Errors
  {
    double       gradient = 0, hessian = 0;
    unsigned int closed = 0, open = 0, free = 0;
  };

  template <int dim> Errors differences(softgrasp::Simulation<dim> &simulation)
  {
    softgrasp::SimulationAccess<dim> access(simulation);
    auto                            &solid       = access.solid();
    const auto                      &constraints = solid.constraint_set();
    auto                            &u           = solid.solution();
    std::vector<dealii::types::global_dof_index> free;
    for (const auto i : solid.locally_owned_dofs())
      if (!constraints.is_constrained(i))
        free.push_back(i);

    // off equilibrium by up to 1e-3 L per entry
    unsigned long state = 12345;
    for (const auto i : free)
      u[i] += 1e-3 * L * next_random(state);
    u.compress(dealii::VectorOperation::insert);
    solid.update_ghosts();

    Errors errors;
    errors.free = free.size();
    // E and the residual on the free dofs at u + h e_j
    std::vector<double> r(free.size());
    auto at = [&](const dealii::types::global_dof_index j, const double h)
    {
      const double old = u[j];
      u[j]             = old + h;
      solid.update_ghosts();
      const auto result = solid.assemble(false);
      SG_CHECK(result.ok, "no inverted element");
      for (std::size_t k = 0; k < free.size(); ++k)
        r[k] = solid.residual_vector()[free[k]];
      u[j] = old;
      solid.update_ghosts();
      return result.energy;
    };
    // the gradient and tangent at the state
    SG_CHECK(solid.assemble(false).ok, "no inverted element");
    const dealii::TrilinosWrappers::MPI::Vector gradient =
        solid.residual_vector();
    // the closed and open points of the potential: nodes, or the faces'
    // Gauss points
    const auto *potential =
        dynamic_cast<const softgrasp::PotentialContact<dim> *>(
            simulation.contact());
    SG_CHECK(potential != nullptr, "the incremental potential");
    const auto [points, closed] = potential->count_points();
    errors.closed               = closed;
    errors.open                 = points - closed;
    solid.assemble(true);
    const auto  &K     = solid.tangent_matrix();
    const double h     = 1e-6 * L;
    double       g_max = 0, K_max = 0;
    for (const auto i : free)
    {
      g_max = std::max(g_max, std::abs(gradient[i]));
      for (const auto j : free)
        K_max = std::max(K_max, std::abs(K.el(i, j)));
    }
    for (const auto j : free)
    {
      const double              E_plus  = at(j, h);
      const std::vector<double> r_plus  = r;
      const double              E_minus = at(j, -h);
      const double              dE      = (E_plus - E_minus) / (2 * h);
      errors.gradient =
          std::max(errors.gradient, std::abs(dE + gradient[j]) / g_max);
      // column j of the tangent: -(r(u + h e_j) - r(u - h e_j)) / 2h
      for (std::size_t k = 0; k < free.size(); ++k)
        errors.hessian = std::max(
            errors.hessian,
            std::abs(-(r_plus[k] - r[k]) / (2 * h) - K.el(free[k], j)) / K_max);
    }
    return errors;
  }

  template <int dim> void check(const Case &c)
  {
    auto simulation = make_solver<dim>(case_prm(c));
    simulation->run();
    const Errors e = differences(*simulation);
    dealii::deallog << dim << "D Q" << c.degree << " " << c.formulation << ", "
                    << c.material << (c.friction > 0 ? ", friction" : "")
                    << (c.gravity ? ", gravity" : "")
                    << (c.dynamic ? ", inertia" : "")
                    << (c.faces ? ", on faces" : "") << ": " << e.free
                    << " free dofs, " << e.closed << " contact points closed, "
                    << e.open << " open; gradient and Hessian "
                    << (e.gradient <= 1e-6 && e.hessian <= 1e-6 ? "agree"
                                                                : "DIFFER")
                    << " with differences" << std::endl;
    std::cout << "  relative errors: gradient " << e.gradient << ", Hessian "
              << e.hessian << std::endl;
    SG_CHECK(e.closed >= 1 && e.open >= 1,
             "a contact point closed and one open");
    SG_CHECK(e.gradient <= 1e-6, "dE/du is minus the residual");
    SG_CHECK(e.hessian <= 1e-6, "the tangent is the residual's derivative");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const std::string nh  = "neo-Hookean";
  const std::string hgo = "Holzapfel-Gasser-Ogden (2 families)";
  for (const std::string &material : {nh, hgo})
  {
    check<3>({3, 1, "displacement", material});
    check<3>({3, 1, "mixed u-p-J", material});
    check<3>({3, 2, "mixed u-p-J", material});
  }
  check<3>({3, 2, "mixed u-p-J", nh, 0.3});
  check<3>({3, 1, "mixed u-p-J", hgo, 0.3, true});
  check<3>({3, 2, "mixed u-p-J", nh, 0, false, true});
  check<2>({2, 1, "mixed u-p-J", nh});
  check<2>({2, 2, "mixed u-p-J", hgo, 0.3, true, true});
  // the potential at the faces' Gauss points: each couples a face's nodes
  check<3>({3, 1, "displacement", nh, 0, false, false, true});
  check<3>({3, 2, "mixed u-p-J", nh, 0.3, false, false, true});
  check<3>({3, 2, "mixed u-p-J", hgo, 0.3, true, true, true});
  check<2>({2, 1, "mixed u-p-J", nh, 0, false, false, true});
  check<2>({2, 2, "mixed u-p-J", hgo, 0.3, true, true, true});
}
