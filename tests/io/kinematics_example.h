// A valid kinematics recording shared by the kinematics-file tests.
#ifndef softgrasp_tests_kinematics_example_h
#define softgrasp_tests_kinematics_example_h

#include <softgrasp/io/kinematics_file.h>

namespace softgrasp_tests
{
  /// A small valid recording: two finger links with capsules, a body
  /// without geoms, a joint, equilibrium forces, link forces, two phases.
  inline softgrasp::KinematicsData example_kinematics()
  {
    softgrasp::KinematicsData data;
    data.source = "test";
    data.time   = {0, 0.5, 1.25};
    for (const std::string name : {"thumb_proximal", "finger_distal"})
    {
      softgrasp::KinematicsData::Body body;
      body.name = name;
      for (unsigned int i = 0; i < data.time.size(); ++i)
      {
        softgrasp::Pose pose;
        pose.position    = Eigen::Vector3d(0.01 * i, -0.02, 0.1 + 0.003 * i);
        pose.orientation = Eigen::Quaterniond(
            Eigen::AngleAxisd(0.3 * i, Eigen::Vector3d(0, 1, 1).normalized()));
        body.poses.push_back(pose);
      }
      softgrasp::KinematicsData::Geom geom;
      geom.name                   = name + "_capsule";
      geom.type                   = "capsule";
      geom.size                   = Eigen::Vector3d(0.008, 0.02, 0);
      geom.local_pose.position    = Eigen::Vector3d(0, 0, 0.02);
      geom.local_pose.orientation = Eigen::Quaterniond(
          Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
      body.geoms.push_back(geom);
      data.bodies.push_back(body);
    }
    softgrasp::KinematicsData::Body
        world; // a body without geoms (left out of contact)
    world.name  = "hand_base";
    world.poses = data.bodies[0].poses;
    data.bodies.push_back(world);
    data.joints.push_back({"thumb_hinge", {0, 0.1, 0.2}, {0.05, 0.15, 0.3}});
    data.equilibrium_time = 0.5;
    data.equilibrium_forces.push_back({"thumb_proximal",
                                       "thumb_proximal_capsule",
                                       {1.5, -2, 10},
                                       {0, 0.6, 0.8}});
    softgrasp::KinematicsData::LinkHistory history;
    history.body = "thumb_proximal";
    history.geom = "thumb_proximal_capsule";
    for (unsigned int i = 0; i < data.time.size(); ++i)
    {
      history.force.emplace_back(0.5 * i, -1, 3 * i);
      history.normal_force.emplace_back(0, -0.6 * i, 2.5 * i);
    }
    data.link_forces.push_back(history);
    data.phases.push_back({"closing", 0, 0.5, 0});
    data.phases.push_back({"indentation", 0.5, 1.25, 0.2});
    return data;
  }
} // namespace softgrasp_tests

#endif
