#include <cmath>
#include <softgrasp/rigid/cylinder_shape.h>

namespace softgrasp
{
  CylinderShape::CylinderShape(const double radius, const double half_height)
      : radius(radius)
      , half_height(half_height)
  {
  }

  ShapeQuery CylinderShape::query(const Eigen::Vector3d &x) const
  {
    const double          rho = std::hypot(x.x(), x.y());
    const Eigen::Vector3d radial =
        rho > 0 ? Eigen::Vector3d(x.x() / rho, x.y() / rho, 0)
                : Eigen::Vector3d::UnitX();
    const double          side  = x.z() >= 0 ? 1.0 : -1.0;
    const Eigen::Vector3d axial = side * Eigen::Vector3d::UnitZ();
    const double          dr    = rho - radius;
    const double          dz    = std::abs(x.z()) - half_height;
    ShapeQuery            q;
    if (dr > 0 && dz > 0) // nearest to the rim
    {
      q.closest =
          radius * radial + side * half_height * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d v = x - q.closest;
      q.distance              = v.norm();
      q.normal                = v / q.distance;
    }
    else if (dr > dz) // mantle
    {
      q.distance = dr;
      q.normal   = radial;
      q.closest =
          Eigen::Vector3d(radius * radial.x(), radius * radial.y(), x.z());
    }
    else // cap
    {
      q.distance = dz;
      q.normal   = axial;
      q.closest  = Eigen::Vector3d(x.x(), x.y(), side * half_height);
    }
    return q;
  }

  double CylinderShape::bounding_radius() const
  {
    return std::hypot(radius, half_height);
  }

  std::string CylinderShape::type() const
  {
    return type_name;
  }

  std::unique_ptr<CylinderShape> CylinderShape::create(const ShapeSpec &spec)
  {
    spec.require_positive(2, "(radius, half-height)");
    return std::make_unique<CylinderShape>(spec.size[0], spec.size[1]);
  }

  std::vector<std::vector<Eigen::Vector3d>> CylinderShape::wireframe() const
  {
    const Eigen::Vector3d x   = radius * Eigen::Vector3d::UnitX(),
                          y   = radius * Eigen::Vector3d::UnitY();
    const Eigen::Vector3d top = half_height * Eigen::Vector3d::UnitZ();
    std::vector<std::vector<Eigen::Vector3d>> lines = {arc(top, x, y),
                                                       arc(-top, x, y)};
    for (const Eigen::Vector3d &r :
         {x, y, Eigen::Vector3d(-x), Eigen::Vector3d(-y)})
      lines.push_back({-top + r, top + r});
    return lines;
  }

  SOFTGRASP_REGISTER_SHAPE(
      CylinderShape,
      "a cylinder of radius size[0] and half-height size[1] along local z")
} // namespace softgrasp
