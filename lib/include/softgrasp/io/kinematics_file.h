#ifndef softgrasp_io_kinematics_file_h
#define softgrasp_io_kinematics_file_h

#include <array>
#include <limits>
#include <softgrasp/rigid/rigid_body_set.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The kinematics a rigid-body simulator (MuJoCo) hands to the finite
   * element solver: every body's world pose over time, the geoms of each
   * body, the joint angles and targets, and the contact forces at the
   * equilibrium grasp. The HDF5 layout (schema version 3: with the
   * surfaces of mesh geoms; version 2 files are still read) is documented
   * in doc/kinematics_file.md. SI units: s, m, rad, N.
   */
  struct KinematicsData
  {
    static constexpr int schema_version = 3;
    /// The oldest schema version the reader still reads.
    static constexpr int oldest_schema_version = 2;

    struct Geom
    {
      std::string     name;
      std::string     type;                           ///< MuJoCo geom type
      Eigen::Vector3d size = Eigen::Vector3d::Zero(); ///< MuJoCo size (m)
      Pose            local_pose;                     ///< in the body frame
      /// A mesh geom's closed surface in the geom's frame (m), as MuJoCo
      /// holds it (re-centred); empty for the other types.
      std::vector<Eigen::Vector3d> vertices;
      /// Its triangles (vertex indices, counter-clockwise from outside).
      std::vector<std::array<unsigned, 3>> triangles;
    };
    struct Body
    {
      std::string       name;
      std::vector<Pose> poses; ///< world pose per time sample
      std::vector<Geom> geoms;
    };
    struct Joint
    {
      std::string         name;
      std::vector<double> angle;  ///< rad (or m for slide joints)
      std::vector<double> target; ///< commanded actuator target
    };
    /// Contact force on a geom (a finger link) at the equilibrium state.
    struct LinkForce
    {
      std::string     body, geom;
      Eigen::Vector3d force = Eigen::Vector3d::Zero(); ///< world (N)
      /// Unit contact normal, world, from the link into the object: the
      /// link's outward surface normal (1).
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    };

    /// The contact force MuJoCo computed on a link at every time sample.
    struct LinkHistory
    {
      std::string                  body, geom;
      std::vector<Eigen::Vector3d> force; ///< on the link, world (N)
      /// Normal part: sum over the link's contacts of (n n^T) f (N).
      std::vector<Eigen::Vector3d> normal_force;
    };
    /**
     * A phase of the recorded run, e.g. "closing" (simulated up to the
     * equilibrium state), "indentation" (the fingers closed further by
     * @p amount rad, poses from forward kinematics) or "pull" (the base
     * moved by @p amount m along the slider).
     */
    struct Phase
    {
      std::string name;
      double      start_time = 0; ///< s
      double      end_time   = 0; ///< s
      double      amount     = 0; ///< in @p unit, see the phase
      /// The unit of @p amount: "rad" (hinge fingers' closure), "m" (slide
      /// fingers' closure, the pull's distance); "rad" in files without it.
      std::string unit = "rad";
    };

    /// The phase called @p name; an InputError listing the phases if none.
    const Phase &phase(const std::string &name) const;

    /**
     * The samples with start_time <= t <= end_time, with times shifted so
     * that @p start_time becomes 0 (the equilibrium state as time 0 of a
     * finite element run). Histories are cut alike; phases are kept if
     * they lie inside and shifted.
     */
    KinematicsData slice(const double start_time, const double end_time) const;

    std::string         source; ///< what produced the file
    std::vector<double> time;   ///< s, strictly increasing
    std::vector<Body>   bodies;
    std::vector<Joint>  joints;
    double equilibrium_time = std::numeric_limits<double>::quiet_NaN(); ///< s
    std::vector<LinkForce>   equilibrium_forces;
    std::vector<LinkHistory> link_forces;
    std::vector<Phase>       phases;
  };

  /// Write @p data to @p filename (HDF5, schema version 2), atomically.
  void write_kinematics_file(const KinematicsData &data,
                             const std::string    &filename);

  /**
   * Read and validate a kinematics file. A missing file, a file that is not
   * HDF5, a wrong schema version, a missing dataset or attribute, a dataset
   * of the wrong shape, NaN, or non-increasing time is an InputError naming
   * the file, the dataset and the fix.
   */
  KinematicsData read_kinematics_file(const std::string &filename);

  /**
   * The rigid bodies of @p data for the contact solver: every body with
   * exactly its geoms (capsules stay analytic capsules) moving on its
   * recorded poses; the equilibrium contact normals become the geoms'
   * reference normals for the normal/lateral force split. Bodies without
   * geoms are left out.
   */
  RigidBodySet rigid_bodies_from(const KinematicsData &data);
} // namespace softgrasp

#endif
