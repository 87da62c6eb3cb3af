#include <softgrasp/rigid/sphere_shape.h>

namespace softgrasp
{
  SphereShape::SphereShape(const double radius)
      : radius(radius)
  {
  }

  ShapeQuery SphereShape::query(const Eigen::Vector3d &x) const
  {
    ShapeQuery   q;
    const double r = x.norm();
    q.normal       = r > 0 ? Eigen::Vector3d(x / r) : Eigen::Vector3d::UnitZ();
    q.distance     = r - radius;
    q.closest      = radius * q.normal;
    return q;
  }

  double SphereShape::bounding_radius() const
  {
    return radius;
  }

  std::string SphereShape::type() const
  {
    return "sphere";
  }
} // namespace softgrasp
