// The grippers through the arm grasp (issue 54), each from its shipped
// .prm alone (no C++ of its own), on the coarse limb: MuJoCo closes the
// hand on the rigid arm made from the limb, the explicit finite element
// solver drives the same links into the layered limb.
//  - gripper_arm_grasp.prm: the parallel-jaw gripper's mesh pads, 5 mm
//    beyond the equilibrium (on this coarse limb the pads first meet the
//    skin after 4 mm: its nodes lie 25 mm apart along the arm, a pad is
//    20 mm wide, and its 16 facets around lie up to 1 mm inside MuJoCo's
//    96-facet arm);
//  - underactuated_arm_grasp.prm: the large underactuated gripper (one
//    servo on a tendon), its distal phalanges under the arm, 0.1 rad of
//    tendon beyond the equilibrium.
// For each:
//  - MuJoCo: both pads (distal phalanges) touch at the equilibrium grasp,
//    each pressed by more than 1 N;
//  - finite elements: no penetration beyond 1 micrometre, the link forces
//    balance the reaction of the humerus (within 5 % of the largest link
//    force; the rest is inertia of the explicit run), both press with
//    more than 1 N at the end, more than 1.2 times their force at 4/5 of
//    the closure;
//  - injury table: the largest compression (e_min) of skin and fat lies
//    within 10 mm of them, and so does the largest contact pressure
//    (within 0.1 mm of one's surface).
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

namespace
{
  /**
   * The coarse arm grasp of parameter-files/@p file, closed by @p extra
   * beyond the equilibrium in 4 samples, in @p directory; the links whose
   * names contain @p tag must hold the arm in MuJoCo, press it in finite
   * elements (more than 1 N at the end, more than 1.2 times their force
   * at 4/5 of the closure) and be where the injury peaks.
   */
  void arm_grasp(const std::string &file,
                 const std::string &extra,
                 const std::string &tag,
                 const std::string &directory)
  {
    dealii::ParameterHandler prm;
    softgrasp_tests::read_coarse_arm(prm, directory, file);
    set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", extra);
    set(prm, {"Rigid environment", "Indentation"}, "Samples", "4");
    dealii::deallog << file << ':' << std::endl;

    ArmGraspStudy   study(MPI_COMM_WORLD, prm);
    GraspParameters grasp;
    grasp.parse_parameters(prm, PARAMETER_FILES);
    grasp.scene_file = study.rigid_scene(grasp.scene_file, directory);
    std::ostringstream   log;
    GraspSimulation      simulation(grasp, log);
    const KinematicsData data    = simulation.run();
    unsigned int         holding = 0;
    for (const auto &f : data.equilibrium_forces)
      holding += f.geom.find(tag) != std::string::npos && f.force.norm() > 1;
    SG_CHECK(holding == 2, "MuJoCo: two links pressed by more than 1 N");
    dealii::deallog << "MuJoCo: both *" << tag
                    << " touch the arm with more than 1 N" << std::endl;

    study.run(data);
    const auto &s = study.summary();
    dealii::deallog << "FE: closure " << s.closure << " in " << s.steps
                    << " records" << std::endl;
    SG_CHECK(s.penetration < 1e-6, "no penetration beyond 1 micrometre");
    SG_CHECK(s.balance < 0.05, "link forces balance the humerus' reaction");
    dealii::deallog << "penetration < 1 um, balance within 5 %" << std::endl;
    double earlier = 0, last = 0;
    for (const auto &link : study.link_forces())
      if (link.link.find(tag) != std::string::npos)
      {
        earlier += link.normal[link.normal.size() * 4 / 5];
        last += link.normal.back();
        SG_CHECK(link.normal.back() > 1, "the link presses: " + link.link);
      }
    SG_CHECK(last > 1.2 * earlier, "the grip grows as the hand closes");
    dealii::deallog << "both press with more than 1 N at the end, more than "
                       "1.2 times what they did at 4/5 of the closure"
                    << std::endl;

    const auto &injury = study.injury();
    for (const auto &t : injury.tissues())
      if (t.id == 1 || t.id == 2)
        SG_CHECK(t.e_min.geom_distance < 10e-3 &&
                     t.e_min.nearest_geom.find(tag) != std::string::npos,
                 "e_min of " + t.name + " next to a link (" +
                     t.e_min.nearest_geom + ")");
    const auto &p = injury.surface();
    SG_CHECK(p.maximum.value > 0 && std::abs(p.maximum.geom_distance) < 1e-4 &&
                 p.maximum.nearest_geom.find(tag) != std::string::npos,
             "the largest pressure is on a link's surface (" +
                 p.maximum.nearest_geom + ")");
    dealii::deallog << "injury table: e_min of skin and fat, and the largest "
                       "pressure, next to them"
                    << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  arm_grasp("gripper_arm_grasp.prm", "0.005", "_pad", "output-gripper");
  arm_grasp("underactuated_arm_grasp.prm",
            "0.1",
            "_distal_link",
            "output-underactuated");
}
