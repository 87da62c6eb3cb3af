// The same .prm switches the sphere_squeeze study between the solvers: the
// coarse study (as mujoco/sphere_squeeze) run with 'Time/Integrator =
// quasi-static' and '= explicit dynamic' (mass scaling to 1e-4 s and mass
// damping for the 1 s quasi-static indentation). The shipped file's mixed
// u-p-J Q1 element is Q1-P0 in both solvers (mean dilatation in the
// explicit one), so they discretise the same problem. Checks:
//  - every link's final normal force agrees within 3 %;
//  - the explicit link forces balance the core's support reaction within
//    5 % of the largest (inertia and damping are small, not zero);
//  - no penetration after any explicit step.
#include "../tests.h"
#include "grasp_helpers.h"

#include <iomanip>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_coarse_sphere_squeeze(prm);
  prm.enter_subsection("Explicit dynamics");
  prm.set("Mass scaling time step", "1e-4");
  prm.set("Mass damping", "100");
  prm.leave_subsection();

  std::ostringstream   log;
  GraspSimulation      simulation(softgrasp_tests::sphere_grasp_parameters(prm),
                             log);
  const KinematicsData data = simulation.run();

  std::vector<IndentationStudy::Summary> results;
  for (const std::string integrator : {"quasi-static", "explicit dynamic"})
  {
    prm.enter_subsection("Time");
    prm.set("Integrator", integrator);
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Directory",
            integrator == "quasi-static" ? "implicit" : "explicit");
    prm.leave_subsection();
    IndentationStudy study(MPI_COMM_WORLD, prm);
    study.run(data);
    results.push_back(study.summary());
  }
  const auto &implicit = results[0], &explicit_run = results[1];
  double      worst = 0;
  for (std::size_t l = 0; l < implicit.links.size(); ++l)
  {
    const double difference =
        explicit_run.normal_fe[l] / implicit.normal_fe[l] - 1;
    worst = std::max(worst, std::abs(difference));
    std::ostringstream line;
    line << implicit.links[l] << ": quasi-static " << std::fixed
         << std::setprecision(1) << implicit.normal_fe[l] << " N, explicit "
         << explicit_run.normal_fe[l] << " N";
    dealii::deallog << line.str() << std::endl;
  }
  dealii::deallog << "link forces agree within 3 %: " << (worst < 0.03)
                  << ", explicit balance with the support within 5 %: "
                  << (explicit_run.balance < 0.05)
                  << ", no penetration: " << (explicit_run.penetration < 1e-9)
                  << std::endl;
  SG_CHECK(worst < 0.03, "explicit and quasi-static link forces agree");
  SG_CHECK(explicit_run.balance < 0.05, "explicit force balance");
  SG_CHECK(explicit_run.penetration < 1e-9, "no penetration");
}
