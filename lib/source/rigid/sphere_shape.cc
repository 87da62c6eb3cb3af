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
    return type_name;
  }

  std::unique_ptr<SphereShape> SphereShape::create(const ShapeSpec &spec)
  {
    spec.require_positive(1, "(radius)");
    return std::make_unique<SphereShape>(spec.size[0]);
  }

  std::vector<std::vector<Eigen::Vector3d>> SphereShape::wireframe() const
  {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    const Eigen::Vector3d x = radius * Eigen::Vector3d::UnitX(),
                          y = radius * Eigen::Vector3d::UnitY(),
                          z = radius * Eigen::Vector3d::UnitZ();
    return {arc(o, x, y), arc(o, y, z), arc(o, z, x)};
  }

  SOFTGRASP_REGISTER_SHAPE(SphereShape,
                           "a sphere of radius size[0] about the geom origin")
} // namespace softgrasp
