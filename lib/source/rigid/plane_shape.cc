#include <limits>
#include <softgrasp/rigid/plane_shape.h>

namespace softgrasp
{
  ShapeQuery PlaneShape::query(const Eigen::Vector3d &x) const
  {
    ShapeQuery q;
    q.distance = x.z();
    q.normal   = Eigen::Vector3d::UnitZ();
    q.closest  = Eigen::Vector3d(x.x(), x.y(), 0);
    return q;
  }

  double PlaneShape::bounding_radius() const
  {
    return std::numeric_limits<double>::infinity();
  }

  std::string PlaneShape::type() const
  {
    return "plane";
  }
} // namespace softgrasp
