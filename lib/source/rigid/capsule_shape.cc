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
    return type_name;
  }

  std::unique_ptr<CapsuleShape> CapsuleShape::create(const ShapeSpec &spec)
  {
    spec.require_positive(2, "(radius, half-length)");
    return std::make_unique<CapsuleShape>(spec.size[0], spec.size[1]);
  }

  std::vector<std::vector<Eigen::Vector3d>> CapsuleShape::wireframe() const
  {
    const Eigen::Vector3d x   = radius * Eigen::Vector3d::UnitX(),
                          y   = radius * Eigen::Vector3d::UnitY(),
                          z   = radius * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d top = half_length * Eigen::Vector3d::UnitZ();
    std::vector<std::vector<Eigen::Vector3d>> lines = {arc(top, x, y),
                                                       arc(-top, x, y)};
    for (const Eigen::Vector3d &r : {x, y})
    {
      lines.push_back({-top + r, top + r});
      lines.push_back({-top - r, top - r});
      lines.push_back(arc(top, r, z, 0, M_PI, 16));
      lines.push_back(arc(-top, r, -z, 0, M_PI, 16));
    }
    return lines;
  }

  SOFTGRASP_REGISTER_SHAPE(CapsuleShape,
                           "a cylinder of radius size[0] and half-length "
                           "size[1] along local z with hemispherical caps")
} // namespace softgrasp
