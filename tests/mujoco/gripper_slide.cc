// A hand that closes on slide joints (issue 54): the parallel-jaw gripper
// of parameter-files/mjcf/parallel_jaw_gripper.xml (two jaws on slide
// joints with rubber pads, position actuators; no C++ of its own) grasps
// the free sphere of the sphere scene through the grasp program's rigid
// stage, set up by the .prm alone ('Finger joints' in metres):
//  - both pads touch at the equilibrium grasp, each pressed by more than
//    1 N, and their forces on the free, weightless sphere balance within
//    1 % of the larger;
//  - the indentation phase closes the jaws by 'Extra joint angle' = 1 mm,
//    which the kinematics file records, and the rigid bodies built from
//    the file move the pads 1 mm (each) towards the sphere;
//  - the log gives the closing in m/s and m.
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const std::vector<std::string> rigid = {"Rigid environment"};
  set(prm, rigid, "Scene file", "mjcf/gripper_sphere_scene.xml");
  set(prm, rigid, "Finger joints", "left_jaw_joint, right_jaw_joint");
  set(prm, rigid, "Contact links", "left_pad, right_pad");
  set(prm, rigid, "Closing speed", "0.05");
  set(prm, rigid, "Grip", "0.002");
  set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", "0.001");
  set(prm, {"Rigid environment", "Indentation"}, "Samples", "4");
  const auto         parameters = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;
  GraspSimulation    simulation(parameters, log);
  write_kinematics_file(simulation.run(), "kinematics.h5");
  const KinematicsData data = read_kinematics_file("kinematics.h5");

  Eigen::Vector3d sum      = Eigen::Vector3d::Zero();
  double          smallest = 1e9, largest = 0;
  for (const auto &f : data.equilibrium_forces)
    if (f.geom == "left_pad" || f.geom == "right_pad")
    {
      sum += f.force;
      smallest = std::min(smallest, f.force.norm());
      largest  = std::max(largest, f.force.norm());
    }
  SG_CHECK(smallest > 1, "both pads pressed by more than 1 N");
  SG_CHECK(sum.norm() < 0.01 * largest, "the pads' forces balance");
  dealii::deallog << "both pads touch at the equilibrium with more than 1 N "
                     "each, forces balanced within 1 %: 1"
                  << std::endl;

  const auto &phase = data.phase("indentation");
  SG_CHECK(std::abs(phase.amount - 0.001) < 1e-15, "closure recorded in m");
  const RigidBodySet bodies = rigid_bodies_from(data);
  double             moved  = 0;
  unsigned int       pads   = 0;
  for (const auto &body : bodies.bodies())
    for (unsigned int g = 0; g < body.geoms().size(); ++g)
      if (body.geoms()[g].name == "left_pad" ||
          body.geoms()[g].name == "right_pad")
      {
        // moved along x, towards the sphere, relative to the base
        const double start = body.geom_pose(g, phase.start_time).position[0];
        const double end   = body.geom_pose(g, phase.end_time).position[0];
        moved = std::max(moved, std::abs(std::abs(start - end) - 0.001));
        ++pads;
      }
  SG_CHECK(pads == 2 && moved < 1e-9, "the pads close 1 mm each");
  dealii::deallog << "indentation of 1 mm recorded, both pads moved 1 mm: 1"
                  << std::endl;
  SG_CHECK(log.str().find(" m/s, grip 0.002 m beyond first touch") !=
               std::string::npos,
           "the log's units");
  dealii::deallog << "closing logged in m/s and m: 1" << std::endl;
}
