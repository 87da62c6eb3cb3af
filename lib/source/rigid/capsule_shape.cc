#include <algorithm>
#include <softgrasp/rigid/capsule_shape.h>

namespace softgrasp
{
  CapsuleShape::CapsuleShape(const double radius, const double half_length)
      : radius(radius)
      , half_length(half_length)
  {
  }

  ShapeQuery CapsuleShape::query(const Eigen::Vector3d &x) const
  {
    // nearest point of the axis segment, then a sphere about it
    const Eigen::Vector3d axis_point(
        0, 0, std::clamp(x.z(), -half_length, half_length));
    const Eigen::Vector3d v = x - axis_point;
    const double          r = v.norm();
    ShapeQuery            q;
    q.normal   = r > 0 ? Eigen::Vector3d(v / r) : Eigen::Vector3d::UnitX();
    q.distance = r - radius;
    q.closest  = axis_point + radius * q.normal;
    return q;
  }

  double CapsuleShape::bounding_radius() const
  {
    return radius + half_length;
  }

  std::string CapsuleShape::type() const
  {
    return "capsule";
  }
} // namespace softgrasp
