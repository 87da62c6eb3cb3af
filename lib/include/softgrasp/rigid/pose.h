#ifndef softgrasp_rigid_pose_h
#define softgrasp_rigid_pose_h

#include <Eigen/Geometry>

namespace softgrasp
{
  /**
   * A rigid placement: position p (m) and unit quaternion q (w, x, y, z as
   * in MuJoCo). A point X of the local frame sits at x = p + R(q) X.
   */
  struct Pose
  {
    Eigen::Vector3d    position    = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();

    /// local -> world
    Eigen::Vector3d to_world(const Eigen::Vector3d &local) const
    {
      return position + orientation * local;
    }

    /// world -> local
    Eigen::Vector3d to_local(const Eigen::Vector3d &world) const
    {
      return orientation.conjugate() * (world - position);
    }

    /// Rotate a direction from local to world.
    Eigen::Vector3d rotate_to_world(const Eigen::Vector3d &direction) const
    {
      return orientation * direction;
    }

    /// The composition this * other (other given in this frame).
    Pose operator*(const Pose &other) const
    {
      return {to_world(other.position), orientation * other.orientation};
    }
  };
} // namespace softgrasp

#endif
