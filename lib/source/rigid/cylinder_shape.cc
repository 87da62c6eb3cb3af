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
    return "cylinder";
  }
} // namespace softgrasp
