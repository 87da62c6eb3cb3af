#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/rigid_body.h>

namespace softgrasp
{
  RigidBody::RigidBody(std::string name, PoseTrajectory trajectory)
      : body_name(std::move(name))
      , motion(std::move(trajectory))
  {
  }

  void RigidBody::add_geom(const std::string           &name,
                           std::shared_ptr<const Shape> shape,
                           const Pose                  &local_pose)
  {
    Pose pose = local_pose;
    if (!pose.position.allFinite() || !(pose.orientation.norm() > 1e-12))
      throw InputError("Geom '" + name + "' of body '" + body_name +
                       "' has a non-finite position or a zero quaternion. "
                       "Fix: give a finite position (m) and a non-zero "
                       "quaternion (w, x, y, z).");
    pose.orientation.normalize();
    geom_list.push_back({name, std::move(shape), pose});
  }

  Pose RigidBody::geom_pose(const unsigned int g, const double time) const
  {
    return motion.pose(time) * geom_list.at(g).local_pose;
  }

  RigidBody::Query RigidBody::query(const unsigned int     g,
                                    const Eigen::Vector3d &x,
                                    const double           time) const
  {
    const Pose       pose  = geom_pose(g, time);
    const ShapeQuery local = geom_list.at(g).shape->query(pose.to_local(x));
    Query            q;
    q.geom     = g;
    q.distance = local.distance;
    q.normal   = pose.rotate_to_world(local.normal);
    q.closest  = pose.to_world(local.closest);
    return q;
  }

  RigidBody::Query RigidBody::closest_geom(const Eigen::Vector3d &x,
                                           const double           time) const
  {
    if (geom_list.empty())
      throw InputError("Body '" + body_name +
                       "' has no geoms. Fix: add at least one geom.");
    Query best = query(0, x, time);
    for (unsigned int g = 1; g < geom_list.size(); ++g)
    {
      const Query q = query(g, x, time);
      if (q.distance < best.distance)
        best = q;
    }
    return best;
  }

  const std::string &RigidBody::name() const
  {
    return body_name;
  }

  const std::vector<RigidBody::Geom> &RigidBody::geoms() const
  {
    return geom_list;
  }

  const PoseTrajectory &RigidBody::trajectory() const
  {
    return motion;
  }
} // namespace softgrasp
