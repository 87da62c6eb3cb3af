// The parallel-jaw gripper through the arm grasp (issue 54), from the
// shipped gripper_arm_grasp.prm alone (no C++ of its own), on the coarse
// limb with a 5 mm closure: MuJoCo closes the jaws across the rigid arm
// made from the limb, the explicit finite element solver drives the same
// box pads into the layered limb.
//  - MuJoCo: both pads touch at the equilibrium grasp, each pressed by
//    more than 1 N;
//  - finite elements: no penetration beyond 1 micrometre, the link forces
//    balance the reaction of the humerus (within 5 % of the largest link
//    force; the rest is inertia of the explicit run), both pads press with
//    more than 1 N at the end, more than twice the force at 4 mm (where
//    they first meet the coarse skin);
//  - injury table: the largest compression (e_min) of skin and fat lies
//    within 10 mm of a pad, and so does the largest contact pressure
//    (within 0.1 mm of a pad's surface).
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_coarse_arm(
      prm, "output-gripper", "gripper_arm_grasp.prm");
  set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", "0.005");
  set(prm, {"Rigid environment", "Indentation"}, "Samples", "4");

  ArmGraspStudy   study(MPI_COMM_WORLD, prm);
  GraspParameters grasp;
  grasp.parse_parameters(prm, PARAMETER_FILES);
  grasp.scene_file = study.rigid_scene(grasp.scene_file, "output-gripper");
  std::ostringstream   log;
  GraspSimulation      simulation(grasp, log);
  const KinematicsData data    = simulation.run();
  const auto           balance = softgrasp_tests::equilibrium_balance(data);
  SG_CHECK(balance.links == 2 && balance.smallest > 1,
           "MuJoCo: both pads pressed by more than 1 N");
  dealii::deallog << "MuJoCo: both pads touch the arm with more than 1 N"
                  << std::endl;

  study.run(data);
  const auto &s = study.summary();
  dealii::deallog << "FE: closure " << s.closure << " m in " << s.steps
                  << " records" << std::endl;
  SG_CHECK(s.penetration < 1e-6, "no penetration beyond 1 micrometre");
  SG_CHECK(s.balance < 0.05, "link forces balance the humerus' reaction");
  dealii::deallog << "penetration < 1 um, balance within 5 %" << std::endl;
  // On this coarse limb the pads first meet the skin after 4 mm: its
  // nodes lie 25 mm apart along the arm (a pad is 20 mm wide) and its 16
  // facets around up to 1 mm inside MuJoCo's 96-facet arm.
  double earlier = 0, last = 0;
  for (const auto &link : study.link_forces())
    if (link.link.find("_pad") != std::string::npos)
    {
      earlier += link.normal[link.normal.size() * 4 / 5];
      last += link.normal.back();
      SG_CHECK(link.normal.back() > 1, "the pad presses: " + link.link);
    }
  SG_CHECK(last > 2 * earlier, "the grip grows as the jaws close");
  dealii::deallog << "both pads press with more than 1 N at the end, more "
                     "than twice what they did at 4 mm"
                  << std::endl;

  const auto &injury = study.injury();
  for (const auto &t : injury.tissues())
    if (t.id == 1 || t.id == 2)
      SG_CHECK(t.e_min.geom_distance < 10e-3 &&
                   t.e_min.nearest_geom.find("_pad") != std::string::npos,
               "e_min of " + t.name + " next to a pad (" +
                   t.e_min.nearest_geom + ")");
  const auto &p = injury.surface();
  SG_CHECK(p.maximum.value > 0 && std::abs(p.maximum.geom_distance) < 1e-4 &&
               p.maximum.nearest_geom.find("_pad") != std::string::npos,
           "the largest pressure is on a pad's surface (" +
               p.maximum.nearest_geom + ")");
  dealii::deallog << "injury table: e_min of skin and fat, and the largest "
                     "pressure, next to the pads"
                  << std::endl;
}
