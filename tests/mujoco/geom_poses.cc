// The kinematics file reproduces MuJoCo's geometry: the sphere scene's grasp
// is simulated (closing to the equilibrium, then the indentation phase),
// written to HDF5 and read back; at every recorded sample, MuJoCo's forward
// kinematics of the recorded joint angles and object pose gives each geom's
// world pose (geom_xpos, geom_xmat), which must equal the pose of the same
// geom of the softgrasp rigid bodies built from the file (1e-12). For the
// three-finger hand, the parallel-jaw gripper (slide joints, mesh pads) and
// the underactuated gripper (one servo on a tendon: its recorded poses
// come from the loaded hand, its joints all in the file).
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

namespace
{
  /// The grasp of @p parameters written and read back, its geom poses
  /// compared with MuJoCo's; logs whether they agree.
  void compare(const GraspParameters &parameters,
               const unsigned int     geoms_per_sample)
  {
    std::ostringstream log;
    GraspSimulation    simulation(parameters, log);
    write_kinematics_file(simulation.run(), "kinematics.h5");
    const KinematicsData data   = read_kinematics_file("kinematics.h5");
    const RigidBodySet   bodies = rigid_bodies_from(data);

    const MujocoModel &mujoco = simulation.model();
    const mjModel     *m      = mujoco.model();
    mjData            *d      = mujoco.make_data();
    const int object = mujoco.id(mjOBJ_BODY, parameters.object_body, "body");
    const int free_qpos =
        m->jnt_qposadr[m->body_jntadr[object]]; // the object's free joint
    double       worst_position = 0, worst_angle = 0;
    unsigned int compared = 0;
    for (std::size_t i = 0; i < data.time.size(); ++i)
    {
      mj_resetData(m, d);
      for (const auto &joint : data.joints)
        d->qpos[m->jnt_qposadr[mujoco.id(mjOBJ_JOINT, joint.name, "joint")]] =
            joint.angle[i];
      for (const auto &body : data.bodies)
        if (body.name == parameters.object_body)
        {
          const Pose &p = body.poses[i];
          for (int k = 0; k < 3; ++k)
            d->qpos[free_qpos + k] = p.position[k];
          d->qpos[free_qpos + 3] = p.orientation.w();
          d->qpos[free_qpos + 4] = p.orientation.x();
          d->qpos[free_qpos + 5] = p.orientation.y();
          d->qpos[free_qpos + 6] = p.orientation.z();
        }
      mj_kinematics(m, d);
      for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
        for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
        {
          const int geom =
              mujoco.id(mjOBJ_GEOM, bodies.bodies()[b].geoms()[g].name, "geom");
          const Pose pose = bodies.bodies()[b].geom_pose(g, data.time[i]);
          const Eigen::Vector3d xpos(d->geom_xpos[3 * geom],
                                     d->geom_xpos[3 * geom + 1],
                                     d->geom_xpos[3 * geom + 2]);
          Eigen::Matrix3d       xmat;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
              xmat(r, c) = d->geom_xmat[9 * geom + 3 * r + c];
          worst_position =
              std::max(worst_position, (pose.position - xpos).norm());
          worst_angle = std::max(
              worst_angle, (pose.orientation.toRotationMatrix() - xmat).norm());
          ++compared;
        }
    }
    mj_deleteData(d);
    dealii::deallog << "samples " << (data.time.size() > 50)
                    << ", geom poses compared "
                    << (compared > geoms_per_sample * 50) << std::endl;
    dealii::deallog << "largest position difference below 1e-12 m: "
                    << (worst_position < 1e-12) << std::endl;
    dealii::deallog << "largest rotation matrix difference below 1e-12: "
                    << (worst_angle < 1e-12) << std::endl;
    SG_CHECK(worst_position < 1e-12, "geom positions equal MuJoCo's geom_xpos");
    SG_CHECK(worst_angle < 1e-12, "geom orientations equal MuJoCo's geom_xmat");
    SG_CHECK(data.phase("indentation").amount ==
                 parameters.indentation.extra_angle,
             "indentation phase recorded");
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  const auto parameters = softgrasp_tests::sphere_grasp_parameters(prm);
  compare(parameters, 7);

  dealii::deallog << "parallel-jaw gripper (slide joints, mesh pads):"
                  << std::endl;
  auto jaw          = parameters;
  jaw.scene_file    = PARAMETER_FILES "/mjcf/gripper_sphere_scene.xml";
  jaw.finger_joints = {"left_jaw_joint", "right_jaw_joint"};
  jaw.contact_links = {"left_pad", "right_pad"};
  jaw.closing_speed = 0.05;
  jaw.grip          = 0.002;
  jaw.indentation.extra_angle = 0.002;
  compare(jaw, 5);

  dealii::deallog << "underactuated gripper (one servo on a tendon):"
                  << std::endl;
  compare(softgrasp_tests::underactuated_sphere_grasp(parameters), 5);
}
