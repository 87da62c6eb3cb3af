// A time stepper of the user's own, registered from outside the library as
// the built-in ones are (SOFTGRASP_REGISTER_TIME_STEPPER): 'Time/Integrator'
// then offers it, an unknown name lists it among the valid ones, and a run
// with it goes through the same Simulation (mesh, solid, history, fields).
// The stepper here loads in one Newton solve at the end time ("load in one
// step"); on a neo-Hookean block stretched by 20 % (hyperelastic, so the
// end state does not depend on the path) its force must equal the exact
// uniaxial force and the built-in quasi-static stepper's to Newton's
// tolerance, with two history rows (t = 0 and the end).
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/mechanics/newton_solver.h>
#include <softgrasp/solvers/time_stepper.h>

using namespace softgrasp_tests;

namespace
{
  /// Equilibrium at t = 0 and at the end time, one Newton solve each.
  template <int dim> class OneStepLoading : public softgrasp::TimeStepper<dim>
  {
  public:
    bool needs_tangent() const override
    {
      return true;
    }
    bool has_inertia() const override
    {
      return false;
    }
    unsigned int
    n_checkpoint_fields(const softgrasp::SolverParameters &) const override
    {
      return 0;
    }
    std::unique_ptr<softgrasp::ContactSurface<dim>>
    make_contact(const softgrasp::SimulationAccess<dim> &,
                 const double) override
    {
      throw softgrasp::InputError("'load in one step' has no contact.");
    }
    void run(const softgrasp::SimulationAccess<dim> &run) override
    {
      const softgrasp::NewtonSolver<dim> newton(run.parameters().newton,
                                                run.verbose_out());
      run.print_summary("load in one step");
      for (const double t : {0.0, run.parameters().time.end_time})
      {
        run.boundary_conditions().set_time(t);
        const auto result = newton.solve(run.solid());
        SG_CHECK(result.converged, "one Newton solve reaches equilibrium");
        run.state().step = t > 0 ? 1 : 0;
        run.state().time = t;
        run.record(t, {{"newton_iterations", double(result.iterations)}}, {});
        run.write_fields(t);
      }
    }
  };

  const double L = 0.01; // block edge (m)

  std::string stretch_prm(const std::string &integrator)
  {
    std::ostringstream displacement;
    displacement << 0.2 * L << " * t";
    return stretched_cube_prm(L,
                              displacement.str(),
                              " set Integrator = " + integrator +
                                  "\n set End time = 1\n set Time step = "
                                  "0.25\n",
                              "out-" + integrator.substr(0, 4));
  }

  double final_force(softgrasp::Simulation<3> &simulation)
  {
    simulation.run();
    const auto &history = simulation.history();
    return history.value(history.rows.size() - 1, "reaction_1_x");
  }
} // namespace

SOFTGRASP_REGISTER_TIME_STEPPER(OneStepLoading,
                                one_step_loading,
                                "load in one step",
                                "equilibrium at t = 0 and at the end time "
                                "only (a test's own stepper)")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);

  auto         one_step = make_solver<3>(stretch_prm("load in one step"));
  const double force    = final_force(*one_step);
  const auto  &rows     = one_step->history().rows;
  SG_CHECK(rows.size() == 2, "two recorded states: t = 0 and the end");
  dealii::deallog << "load in one step: " << rows.size() << " rows, columns:";
  for (const auto &name : one_step->history().columns)
    dealii::deallog << ' ' << name;
  dealii::deallog << std::endl;

  auto         stepped   = make_solver<3>(stretch_prm("quasi-static"));
  const double reference = final_force(*stepped);
  const auto   exact     = softgrasp::HomogeneousLoading::uniaxial(
      stepped->materials().get(0), {}, 1.2);
  const double expected = exact.nominal_stress * L * L;
  dealii::deallog << "force: one step " << force << " N, quasi-static "
                  << reference << " N in " << stepped->history().rows.size() - 1
                  << " steps, exact " << expected << " N" << std::endl;
  SG_CHECK(close(force, expected, 1e-8), "the exact uniaxial force");
  SG_CHECK(close(force, reference, 1e-8), "the built-in stepper's force");

  try
  {
    make_solver<3>(stretch_prm("no such stepper"));
    SG_CHECK(false, "an unknown integrator is refused");
  }
  catch (const std::exception &e)
  {
    const std::string message = e.what();
    SG_CHECK(message.find("load in one step") != std::string::npos,
             "the valid names include the user's stepper");
    dealii::deallog << "unknown integrator: " << message << std::endl;
  }
}
