// The kinematics file between the rigid-body simulator and the finite
// element solver (HDF5, schema version 2, doc/kinematics_file.md):
//  - a write/read round trip returns every number exactly;
//  - the rigid bodies built from it place each geom at the recorded pose at
//    the sample times (capsules stay analytic capsules), and the
//    equilibrium contact normals become the reference normals;
//  - a missing file, a file that is not HDF5, a wrong schema version, a
//    missing dataset, NaN, a wrong shape, non-increasing time and a phase
//    beyond the recorded samples give
//    errors that name the dataset and the fix.
#include "../tests.h"
#include "kinematics_example.h"

#include <hdf5.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/io/kinematics_file.h>

using namespace softgrasp;
using softgrasp_tests::example_kinematics;

namespace
{
  std::string error_of(const std::string &file)
  {
    try
    {
      read_kinematics_file(file);
    }
    catch (const InputError &e)
    {
      return e.what();
    }
    return "no error";
  }

  /// Overwrite (or delete, if @p values is empty) a dataset of a file.
  void tamper(const std::string         &file,
              const std::string         &path,
              const std::vector<double> &values)
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (values.empty())
      H5Ldelete(f, path.c_str(), H5P_DEFAULT);
    else
    {
      const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
      H5Dwrite(
          d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
      H5Dclose(d);
    }
    H5Fclose(f);
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  const KinematicsData written = example_kinematics();
  write_kinematics_file(written, "kinematics.h5");
  const KinematicsData read = read_kinematics_file("kinematics.h5");

  bool same =
      read.time == written.time && read.source == written.source &&
      read.bodies.size() == written.bodies.size() &&
      read.equilibrium_time == written.equilibrium_time &&
      read.joints[0].angle == written.joints[0].angle &&
      read.joints[0].target == written.joints[0].target &&
      read.equilibrium_forces[0].force == written.equilibrium_forces[0].force &&
      read.link_forces[0].force == written.link_forces[0].force &&
      read.link_forces[0].normal_force == written.link_forces[0].normal_force &&
      read.phases.size() == 2 && read.phases[1].name == "indentation" &&
      read.phases[1].start_time == 0.5 && read.phases[1].end_time == 1.25 &&
      read.phases[1].amount == 0.2;
  for (unsigned int b = 0; b < written.bodies.size(); ++b)
  {
    same = same && read.bodies[b].name == written.bodies[b].name &&
           read.bodies[b].geoms.size() == written.bodies[b].geoms.size();
    for (unsigned int i = 0; i < written.time.size(); ++i)
      same = same &&
             read.bodies[b].poses[i].position ==
                 written.bodies[b].poses[i].position &&
             (read.bodies[b].poses[i].orientation.coeffs() -
              written.bodies[b].poses[i].orientation.coeffs())
                     .norm() < 1e-15; // re-normalised on reading
  }
  dealii::deallog << "round trip exact (quaternions to 1e-15): " << same
                  << std::endl;
  SG_CHECK(same, "write/read round trip");

  // A mesh geom (schema 3): its surface round-trips exactly and becomes a
  // triangle-mesh shape; a file of schema 2 (no meshes) is still read.
  {
    KinematicsData       with_mesh = written;
    KinematicsData::Geom pad;
    pad.name      = "pad";
    pad.type      = "mesh";
    pad.size      = Eigen::Vector3d(0.01, 0.01, 0.01);
    pad.vertices  = {{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}, {0, 0, 0.01}};
    pad.triangles = {{{0, 2, 1}}, {{0, 1, 3}}, {{0, 3, 2}}, {{1, 2, 3}}};
    with_mesh.bodies[0].geoms.push_back(pad);
    write_kinematics_file(with_mesh, "mesh.h5");
    const auto  back = read_kinematics_file("mesh.h5");
    const auto &geom = back.bodies[0].geoms.back();
    SG_CHECK(geom.vertices == pad.vertices && geom.triangles == pad.triangles,
             "a mesh geom's surface round-trips exactly");
    SG_CHECK(rigid_bodies_from(back).bodies()[0].geoms().back().shape->type() ==
                 "mesh",
             "a mesh geom becomes a triangle-mesh shape");
    write_kinematics_file(written, "schema2.h5");
    const hid_t file = H5Fopen("schema2.h5", H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t a    = H5Aopen(file, "schema_version", H5P_DEFAULT);
    const int   v    = 2;
    H5Awrite(a, H5T_NATIVE_INT, &v);
    H5Aclose(a);
    H5Fclose(file);
    SG_CHECK(read_kinematics_file("schema2.h5").bodies.size() ==
                 written.bodies.size(),
             "a schema 2 file is still read");
    dealii::deallog << "mesh geom round trip exact, a mesh shape built; a "
                       "schema 2 file read: 1"
                    << std::endl;
  }

  const RigidBodySet set = rigid_bodies_from(read);
  SG_CHECK(set.bodies().size() == 2, "bodies without geoms are left out");
  double worst = 0;
  for (unsigned int b = 0; b < 2; ++b)
    for (unsigned int i = 0; i < written.time.size(); ++i)
    {
      const Pose expected =
          written.bodies[b].poses[i] * written.bodies[b].geoms[0].local_pose;
      const Pose got = set.bodies()[b].geom_pose(0, written.time[i]);
      worst          = std::max({worst,
                                 (got.position - expected.position).norm(),
                                 got.orientation.angularDistance(expected.orientation)});
    }
  SG_CHECK(worst < 1e-14, "geom poses at the sample times");
  SG_CHECK(set.bodies()[0].geoms()[0].shape->type() == "capsule",
           "capsules stay capsules");
  SG_CHECK((set.reference_normal(0, 0).direction - Eigen::Vector3d(0, 0.6, 0.8))
                   .norm() < 1e-15,
           "equilibrium normal as reference normal");
  dealii::deallog << "geom poses at the sample times, capsule geoms and the "
                  << "equilibrium normal: 1" << std::endl;

  // The indentation phase as a run of its own: time 0 at the equilibrium.
  const auto &phase = read.phase("indentation");
  const auto  cut   = read.slice(phase.start_time, phase.end_time);
  SG_CHECK(cut.time == std::vector<double>({0, 0.75}) &&
               cut.bodies[1].poses[1].position ==
                   written.bodies[1].poses[2].position &&
               cut.link_forces[0].force[0] == written.link_forces[0].force[1] &&
               cut.phases.size() == 1 && cut.phases[0].start_time == 0 &&
               cut.equilibrium_time == 0,
           "slice of the indentation phase");
  dealii::deallog << "indentation phase sliced to start at 0: 1" << std::endl;
  try
  {
    read.phase("pull");
    SG_CHECK(false, "unknown phase");
  }
  catch (const InputError &e)
  {
    dealii::deallog << e.what() << std::endl;
  }

  // Bad files.
  std::ofstream("not_hdf5.h5") << "text\n";
  const auto variant = [&](const std::string &name, auto change)
  {
    write_kinematics_file(written, name);
    change(name);
    return name;
  };
  const std::vector<std::string> bad = {
      "missing.h5",
      "not_hdf5.h5",
      variant("version.h5",
              [](const std::string &f)
              {
                const hid_t file =
                    H5Fopen(f.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
                const hid_t a = H5Aopen(file, "schema_version", H5P_DEFAULT);
                const int   v = 7;
                H5Awrite(a, H5T_NATIVE_INT, &v);
                H5Aclose(a);
                H5Fclose(file);
              }),
      variant("no_dataset.h5",
              [](const std::string &f)
              { tamper(f, "/bodies/thumb_proximal/quaternion", {}); }),
      variant("nan.h5",
              [](const std::string &f)
              {
                std::vector<double> p(9, 0.0);
                p[4] = std::nan("");
                tamper(f, "/bodies/finger_distal/position", p);
              }),
      variant("far.h5",
              [](const std::string &f)
              {
                // finite, but no scene of a hand: a diverged writer
                std::vector<double> p(9, 0.0);
                p[4] = 1e300;
                tamper(f, "/bodies/finger_distal/position", p);
              }),
      variant("triangle.h5",
              [](const std::string &f)
              {
                // a triangle of a mesh geom naming a vertex it does not have
                KinematicsData       data = example_kinematics();
                KinematicsData::Geom pad;
                pad.name      = "pad";
                pad.type      = "mesh";
                pad.vertices  = {{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}};
                pad.triangles = {{{0, 1, 5}}};
                data.bodies[0].geoms.push_back(pad);
                write_kinematics_file(data, f);
              }),
      variant("time.h5",
              [](const std::string &f) {
                tamper(f, "/time", {0, 0.5, 0.5});
              }),
      variant("phase.h5",
              [](const std::string &f)
              {
                // the indentation phase ends after the last sample (1.25 s)
                KinematicsData data     = example_kinematics();
                data.phases[1].end_time = 2.0;
                write_kinematics_file(data, f);
              }),
      variant("history.h5",
              [](const std::string &f)
              {
                tamper(f,
                       "/link_forces/thumb_proximal/thumb_proximal_capsule/"
                       "normal_force",
                       {});
              })};
  for (const auto &file : bad)
  {
    const std::string message = error_of(file);
    dealii::deallog << file << ": " << message << std::endl;
    SG_CHECK(message.find(file) != std::string::npos &&
                 message.find("Fix:") != std::string::npos,
             "the error names the file and the fix");
  }
}
