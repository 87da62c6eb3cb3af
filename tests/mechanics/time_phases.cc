// Per-phase stepping ('Time/Phases'): a block stretched by 20 % with a
// coarse first phase (0.25 s steps to 0.5 s) and a fine second one (0.1 s
// steps to 1 s) records exactly the phase grid with both the quasi-static
// and the explicit solver, the quasi-static stretch ends at the exact
// uniaxial force of the material (and every cell's quadrature-point
// strains the exact stretches), and bad phase lists are refused with a
// message naming the entry and the fix.
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/postprocess/strain_postprocessor.h>

using namespace softgrasp_tests;

namespace
{
  const double L = 0.01; // block edge (m)

  std::string stretch_prm(const std::string &integrator,
                          const std::string &phases,
                          const std::string &directory)
  {
    std::ostringstream displacement, time;
    displacement << 0.2 * L << " * (1 - cos(pi * t)) / 2";
    time << " set Integrator = " << integrator
         << "\n set End time = 1\n set Phases = " << phases << "\n";
    return stretched_cube_prm(L, displacement.str(), time.str(), directory) +
           "subsection Explicit dynamics\n set Mass damping = 200\nend\n";
  }

  /// Run and check the recorded times against @p expected; return the
  /// last x reaction on the loaded face (N) and, for the quasi-static run,
  /// check the quadrature-point strains of every cell against the exact
  /// homogeneous stretches.
  double run(const std::string &integrator, const std::vector<double> &expected)
  {
    auto solver = make_solver<3>(
        stretch_prm(integrator, "0.5: 0.25; 1: 0.1", "out-" + integrator));
    solver->run();
    const auto &history = solver->history();
    dealii::deallog << integrator << ": recorded times";
    SG_CHECK(history.rows.size() == expected.size(), "one row per step");
    for (unsigned int i = 0; i < history.rows.size(); ++i)
    {
      const double t = history.value(i, "time");
      dealii::deallog << ' ' << t;
      SG_CHECK(close(t, expected[i], 0, 1e-12), "the phase grid");
    }
    dealii::deallog << std::endl;
    if (integrator == "quasi-static")
    {
      const auto exact = softgrasp::HomogeneousLoading::uniaxial(
          solver->materials().get(0), {}, 1.2);
      const auto &tria = solver->system().dof_handler().get_triangulation();
      dealii::Vector<float> e_max(tria.n_active_cells()),
          e_min(tria.n_active_cells());
      softgrasp::cell_strain_extremes(solver->system(), e_max, e_min);
      for (const auto &cell : tria.active_cell_iterators())
      {
        SG_CHECK(close(e_max[cell->active_cell_index()], 0.2, 1e-6),
                 "e_max at the quadrature points: the stretch 1.2");
        SG_CHECK(close(e_min[cell->active_cell_index()],
                       exact.stretches[1] - 1,
                       1e-6),
                 "e_min at the quadrature points: the lateral stretch");
      }
      dealii::deallog << "cell extremes of e at the quadrature points: "
                      << e_max[0] << ", " << e_min[0] << " (exact 0.2, "
                      << exact.stretches[1] - 1 << ")" << std::endl;
    }
    return history.value(history.rows.size() - 1, "reaction_1_x");
  }

  void refused(const std::string &phases)
  {
    try
    {
      make_solver<3>(stretch_prm("quasi-static", phases, "out-bad"));
    }
    catch (const softgrasp::InputError &e)
    {
      dealii::deallog << "'" << phases << "' refused: " << e.what()
                      << std::endl;
      return;
    }
    SG_CHECK(false, "a bad phase list is refused");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);
  const std::vector<double> grid  = {0, 0.25, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  const double              force = run("quasi-static", grid);
  run("explicit dynamic", grid);

  auto probe = make_solver<3>(stretch_prm("quasi-static", "", "out-probe"));
  const auto exact = softgrasp::HomogeneousLoading::uniaxial(
      probe->materials().get(0), {}, 1.2);
  const double expected = exact.nominal_stress * L * L;
  dealii::deallog << "quasi-static force " << force << " N, exact " << expected
                  << " N" << std::endl;
  SG_CHECK(close(force, expected, 1e-8), "the exact uniaxial force");

  refused("0.5: 0.25; 0.9: 0.1");
  refused("0.5: 0.25; 0.4: 0.1");
  refused("0.5 0.25; 1: 0.1");
  refused("0.5: 0.25; 1: 0.1, 0.2");
}
