// Contact in the linear solve as constraints on the contact nodes: the
// iterative solver (CG + ML AMG on the condensed, symmetric tangent; GMRES
// while nodes slide with friction) and the direct solver must take the
// same Newton path to the same KKT point, also with the AMG kept over
// Newton iterations ('Linear solver/Reuse AMG').
//  - Hertz (frictionless, Q2, quarter model): force and contact radius of
//    both solvers agree to 1e-6, Newton iterations per step are equal, the
//    condensed tangent is symmetric (CG) at the end, the force is within
//    3 % of Hertz's, and CG needs a bounded number of iterations;
//  - a block pressed onto a floor and dragged with mu = 0.3 (stick, partial
//    slip, sliding): normal and lateral force of both solvers agree to 1e-6
//    at every step, and the tangent is unsymmetric while it slides (the
//    multipliers named: the default takes the incremental potential with
//    friction, which adds no constraints).
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/contact/mortar_contact.h>

using namespace softgrasp_tests;

namespace
{
  /// Whether the contact conditions of @p solver leave a symmetric tangent.
  bool symmetric(const softgrasp::Simulation<3> &solver)
  {
    const auto *mortar =
        dynamic_cast<const softgrasp::MortarContact<3> *>(solver.contact());
    SG_CHECK(mortar != nullptr, "the quasi-static solver uses mortar contact");
    return mortar->symmetric();
  }

  void hertz()
  {
    const auto                       exact = hertz_solution();
    std::vector<double>              force, radius;
    std::vector<std::vector<double>> newton;
    double                           cg_per_newton = 0;
    // 'kept': iterative with the AMG kept over Newton iterations.
    for (const std::string variant : {"direct", "iterative", "kept"})
    {
      const std::string type = variant == "direct" ? "direct" : "iterative";
      // Exact linear solves: the same Newton path is expected.
      auto solver = make_solver<3>(
          hertz_prm(6, 1.72, 0.05, 2, 2, "output-cs-" + variant, type) +
          "subsection Newton\n set Inexact linear solves = false\nend\n"
          "subsection Linear solver\n set Reuse AMG = " +
          (variant == "kept" ? "true" : "false") + "\nend\n");
      solver->run();
      const auto forces =
          solver->contact_output()->geom_forces(solver->system());
      force.push_back(4 * forces[0][0].force[2]);
      radius.push_back(edge_contact_radius(*solver));
      const auto         &h = solver->history();
      std::vector<double> its;
      double              linear = 0, steps = 0;
      for (std::size_t row = 1; row < h.rows.size(); ++row)
      {
        its.push_back(h.value(row, "newton_iterations"));
        linear += h.value(row, "linear_iterations");
        steps += h.value(row, "newton_iterations");
      }
      newton.push_back(its);
      if (variant == "iterative")
      {
        cg_per_newton = linear / steps;
        SG_CHECK(symmetric(*solver),
                 "frictionless contact leaves a symmetric tangent (CG)");
      }
    }
    dealii::deallog << "Hertz: force " << force[1] << " N (Hertz "
                    << exact.force << " N), contact radius " << radius[1] * 1e3
                    << " mm" << std::endl;
    SG_CHECK(std::abs(force[1] - force[0]) <= 1e-6 * force[0],
             "direct and iterative forces agree");
    SG_CHECK(std::abs(radius[1] - radius[0]) <= 1e-6 * radius[0],
             "direct and iterative contact radii agree");
    SG_CHECK(newton[0] == newton[1], "the same Newton iterations per step");
    SG_CHECK(std::abs(force[2] - force[0]) <= 1e-6 * force[0] &&
                 newton[0] == newton[2],
             "a kept AMG changes neither the force nor the Newton path");
    SG_CHECK(std::abs(force[1] / exact.force - 1) < 0.03,
             "force within 3 % of Hertz");
    SG_CHECK(cg_per_newton < 300, "CG iterations per Newton step bounded");
    dealii::deallog << "Hertz: direct and iterative agree" << std::endl;
  }

  void drag()
  {
    const double                     mu = 0.3;
    std::vector<std::vector<double>> normal, lateral;
    bool                             unsymmetric_seen = false;
    for (const std::string variant : {"direct", "iterative", "kept"})
    {
      const std::string  type = variant == "direct" ? "direct" : "iterative";
      std::ostringstream prm;
      prm << block_on_floor(mu,
                            "0.001 * max(t - 1, 0); 0; -0.00025 * min(t, 1)")
          << "subsection Time\n set End time = 1.5\n set Time step = 0.1\nend\n"
          << "subsection Contact\n set Enforcement = lagrange multipliers\n"
          << "end\n"
          << "subsection Newton\n set Relative tolerance = 1e-11\n"
          << " set Inexact linear solves = false\nend\n"
          << "subsection Linear solver\n set Type = " << type
          << "\n set Reuse AMG = " << (variant == "kept" ? "true" : "false")
          << "\nend\n"
          << "subsection Output\n set Directory = output-cs-drag-" << variant
          << "\n set VTU interval = 0\n set Verbose = false\nend\n";
      auto solver = make_solver<3>(prm.str());
      solver->run();
      const auto         &h = solver->contact_history();
      std::vector<double> n, l;
      for (std::size_t row = 1; row < h.rows.size(); ++row)
      {
        n.push_back(h.value(row, "floor/plane:normal_force"));
        l.push_back(h.value(row, "floor/plane:lateral_force"));
      }
      normal.push_back(n);
      lateral.push_back(l);
      if (variant == "iterative")
        unsymmetric_seen = !symmetric(*solver);
    }
    SG_CHECK(normal[0].size() == normal[1].size() &&
                 normal[0].size() == normal[2].size(),
             "same number of steps");
    double worst = 0;
    for (unsigned int k : {1u, 2u})
      for (std::size_t i = 0; i < normal[0].size(); ++i)
        worst =
            std::max({worst,
                      std::abs(normal[k][i] - normal[0][i]) / normal[0][i],
                      std::abs(lateral[k][i] - lateral[0][i]) / normal[0][i]});
    SG_CHECK(worst <= 1e-6, "direct and iterative forces agree at every step");
    SG_CHECK(unsymmetric_seen, "sliding with friction: unsymmetric (GMRES)");
    dealii::deallog << "drag: " << normal[0].size()
                    << " steps, final N = " << normal[1].back()
                    << " N, F_t/(mu N) = "
                    << lateral[1].back() / (mu * normal[1].back())
                    << "; direct and iterative agree" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);
  hertz();
  drag();
}
