#ifndef softgrasp_rigid_rigid_body_h
#define softgrasp_rigid_rigid_body_h

#include <memory>
#include <softgrasp/rigid/pose_trajectory.h>
#include <softgrasp/rigid/shape.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A rigid contactor: a set of geoms (a shape at a pose in the body frame,
   * e.g. the capsules of a finger link) moving with the body along a pose
   * trajectory. Queries are in world coordinates at a given time (s).
   */
  class RigidBody
  {
  public:
    struct Geom
    {
      std::string                  name;
      std::shared_ptr<const Shape> shape;
      Pose                         local_pose; ///< in the body frame
    };

    /// Proximity of a world point to one geom, in world coordinates.
    struct Query
    {
      unsigned int    geom     = 0;
      double          distance = 0; ///< signed, negative inside (m)
      Eigen::Vector3d normal;       ///< outward unit normal (world)
      Eigen::Vector3d closest;      ///< closest surface point (world, m)
    };

    RigidBody(std::string name, PoseTrajectory trajectory);

    void add_geom(const std::string           &name,
                  std::shared_ptr<const Shape> shape,
                  const Pose                  &local_pose);

    /// World pose of geom @p g at @p time.
    Pose geom_pose(const unsigned int g, const double time) const;

    /// Query of world point @p x against geom @p g at @p time.
    Query query(const unsigned int     g,
                const Eigen::Vector3d &x,
                const double           time) const;

    /// The geom with the smallest signed distance to @p x at @p time.
    Query closest_geom(const Eigen::Vector3d &x, const double time) const;

    const std::string       &name() const;
    const std::vector<Geom> &geoms() const;
    const PoseTrajectory    &trajectory() const;

  private:
    std::string       body_name;
    PoseTrajectory    motion;
    std::vector<Geom> geom_list;
  };
} // namespace softgrasp

#endif
