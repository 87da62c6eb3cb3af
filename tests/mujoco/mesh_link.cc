// A hand link that is a mesh geom goes through the grasp study's rigid
// stage into the finite element stage, where it sits exactly where MuJoCo
// puts it (issue 54): the sphere scene's hand with the thumb's distal link
// replaced by a box pad read from a binary STL file whose vertices are not
// centred (MuJoCo re-centres the mesh at its centroid and turns it to its
// principal axes, moving geom_pos and geom_quat to match):
//  - the rigid stage runs (it refused mesh links before) and the
//    kinematics file carries the pad's 8 vertices and 12 triangles;
//  - at every recorded sample the pad's vertices, placed by the softgrasp
//    rigid body built from the file, coincide with the STL's corners placed
//    by MuJoCo's own forward kinematics of the recorded joint angles as
//    the scene file puts them (body frame, no geom offset), within MuJoCo's
//    single-precision storage of mesh vertices;
//  - the finite element link's signed distance equals the analytic box's
//    (BoxShape) at 2000 points around the pad.
#include "../tests.h"
#include "grasp_helpers.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>
#include <softgrasp/rigid/box_shape.h>

using namespace softgrasp;
using Eigen::Vector3d;

namespace
{
  /// The pad: 18 x 14 x 40 mm, its top face at the joint (z from -0.04 to
  /// 0, so its centroid is 20 mm below the body origin).
  const Vector3d half(0.009, 0.007, 0.02);
  const Vector3d centre(0, 0, -0.02);

  std::vector<Vector3d> pad_corners()
  {
    std::vector<Vector3d> corners;
    for (unsigned int i = 0; i < 8; ++i)
      corners.push_back(centre + Vector3d((i & 1 ? 1 : -1) * half[0],
                                          (i & 2 ? 1 : -1) * half[1],
                                          (i & 4 ? 1 : -1) * half[2]));
    return corners;
  }

  /// The pad as a binary STL file (MuJoCo 2.2 reads binary STL).
  void write_pad_stl(const std::string &file)
  {
    const auto corners = pad_corners();
    // two triangles per face, counter-clockwise from outside
    const unsigned faces[6][4] = {{0, 2, 3, 1},
                                  {4, 5, 7, 6},
                                  {0, 1, 5, 4},
                                  {2, 6, 7, 3},
                                  {0, 4, 6, 2},
                                  {1, 3, 7, 5}};
    std::ofstream  out(file, std::ios::binary);
    char           header[80] = {};
    out.write(header, 80);
    const std::uint32_t n = 12;
    out.write(reinterpret_cast<const char *>(&n), 4);
    for (const auto &q : faces)
      for (const auto &t : {std::array<unsigned, 3>{{q[0], q[1], q[2]}},
                            std::array<unsigned, 3>{{q[0], q[2], q[3]}}})
      {
        float data[12] = {};
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            data[3 + 3 * c + d] = static_cast<float>(corners[t[c]][d]);
        out.write(reinterpret_cast<const char *>(data), 48);
        out.write("\0\0", 2);
      }
  }

  std::string file_text(const std::string &file)
  {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in),
            std::istreambuf_iterator<char>()};
  }

  /// The shipped sphere scene with the thumb's distal capsule replaced by
  /// the pad mesh, written into the working directory; its absolute path.
  std::string write_scene()
  {
    const std::string mjcf = PARAMETER_FILES "/mjcf/";
    std::string       hand = file_text(mjcf + "three_finger_hand.xml");
    const std::string capsule =
        "<geom name=\"thumb_distal_link\" class=\"finger\"\n"
        "                fromto=\"0 0 0 0 0 -0.04\" size=\"0.009\"/>";
    const auto at = hand.find(capsule);
    AssertThrow(at != std::string::npos,
                dealii::ExcMessage("the thumb's distal capsule moved"));
    hand.replace(at,
                 capsule.size(),
                 "<geom name=\"thumb_distal_link\" class=\"finger\" "
                 "type=\"mesh\" mesh=\"pad\"/>");
    const auto body = hand.find("<worldbody>");
    hand.insert(body, "<asset><mesh name=\"pad\" file=\"pad.stl\"/></asset>\n");
    std::ofstream("three_finger_hand.xml") << hand;
    std::ofstream("sphere_scene.xml") << file_text(mjcf + "sphere_scene.xml");
    write_pad_stl("pad.stl");
    return std::filesystem::absolute("sphere_scene.xml").string();
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_sphere_squeeze(prm);
  softgrasp_tests::set(prm, {"Rigid environment"}, "Scene file", write_scene());
  const auto         parameters = softgrasp_tests::sphere_grasp_parameters(prm);
  std::ostringstream log;
  GraspSimulation    simulation(parameters, log);
  write_kinematics_file(simulation.run(), "kinematics.h5");
  const KinematicsData data   = read_kinematics_file("kinematics.h5");
  const RigidBodySet   bodies = rigid_bodies_from(data);

  unsigned int b = 0, g = 0;
  for (unsigned int i = 0; i < bodies.bodies().size(); ++i)
    for (unsigned int j = 0; j < bodies.bodies()[i].geoms().size(); ++j)
      if (bodies.bodies()[i].geoms()[j].name == "thumb_distal_link")
        std::tie(b, g) = std::make_pair(i, j);
  const auto &file_geom = [&]() -> const KinematicsData::Geom &
  {
    for (const auto &body : data.bodies)
      for (const auto &geom : body.geoms)
        if (geom.name == "thumb_distal_link")
          return geom;
    AssertThrow(false, dealii::ExcMessage("no thumb_distal_link"));
    return data.bodies[0].geoms[0];
  }();
  dealii::deallog << "pad in the kinematics file: type " << file_geom.type
                  << ", " << file_geom.vertices.size() << " vertices, "
                  << file_geom.triangles.size() << " triangles" << std::endl;

  // The pad's corners by MuJoCo's forward kinematics of the recorded
  // angles, as the scene file places them, against the rigid body's.
  const MujocoModel &mujoco  = simulation.model();
  const mjModel     *m       = mujoco.model();
  mjData            *d       = mujoco.make_data();
  const int          thumb   = mujoco.id(mjOBJ_BODY, "thumb_distal", "body");
  const auto        &rigid   = bodies.bodies()[b];
  const auto         corners = pad_corners();
  double             worst   = 0;
  for (std::size_t i = 0; i < data.time.size(); ++i)
  {
    mj_resetData(m, d);
    for (const auto &joint : data.joints)
      d->qpos[m->jnt_qposadr[mujoco.id(mjOBJ_JOINT, joint.name, "joint")]] =
          joint.angle[i];
    mj_kinematics(m, d);
    Eigen::Matrix3d R;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        R(r, c) = d->xmat[9 * thumb + 3 * r + c];
    const Vector3d x(
        d->xpos[3 * thumb], d->xpos[3 * thumb + 1], d->xpos[3 * thumb + 2]);
    const Pose pose = rigid.geom_pose(g, data.time[i]);
    for (const auto &corner : corners)
    {
      double nearest = 1;
      for (const auto &v : file_geom.vertices)
        nearest = std::min(
            nearest,
            (pose.position + pose.orientation * v - (x + R * corner)).norm());
      worst = std::max(worst, nearest);
    }
  }
  mj_deleteData(d);
  SG_CHECK(worst < 1e-8, "the pad sits where MuJoCo puts it");
  dealii::deallog << "pad corners against MuJoCo's at " << data.time.size()
                  << " samples: within 1e-8 m " << (worst < 1e-8) << std::endl;

  // The finite element link against the analytic box, in the body frame
  // (the geom's local pose applied to the mesh's own frame).
  const auto                            &geom = rigid.geoms()[g];
  const BoxShape                         box(half);
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  double                                 distance_error = 0;
  for (unsigned int k = 0; k < 2000; ++k)
  {
    const Vector3d x_body =
        centre +
        Vector3d(u(random) * half[0], u(random) * half[1], u(random) * half[2]);
    const Vector3d x_geom = geom.local_pose.orientation.conjugate() *
                            (x_body - geom.local_pose.position);
    distance_error = std::max(distance_error,
                              std::abs(geom.shape->query(x_geom).distance -
                                       box.query(x_body - centre).distance));
  }
  SG_CHECK(distance_error < 1e-8, "the mesh link's distance is the box's");
  dealii::deallog << "finite element link's signed distance against the "
                     "box at 2000 points: within 1e-8 m "
                  << (distance_error < 1e-8) << std::endl;
}
