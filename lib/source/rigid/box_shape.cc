#include <softgrasp/rigid/box_shape.h>

namespace softgrasp
{
  BoxShape::BoxShape(const Eigen::Vector3d &half_sizes)
      : half(half_sizes)
  {
  }

  ShapeQuery BoxShape::query(const Eigen::Vector3d &x) const
  {
    ShapeQuery            q;
    const Eigen::Vector3d excess = x.cwiseAbs() - half;
    if ((excess.array() > 0).any())
    {
      q.closest               = x.cwiseMax(-half).cwiseMin(half);
      const Eigen::Vector3d v = x - q.closest;
      q.distance              = v.norm();
      q.normal                = v / q.distance;
      return q;
    }
    // inside: the nearest face
    Eigen::Index i;
    q.distance        = excess.maxCoeff(&i);
    const double sign = x[i] >= 0 ? 1.0 : -1.0;
    q.normal          = Eigen::Vector3d::Zero();
    q.normal[i]       = sign;
    q.closest         = x;
    q.closest[i]      = sign * half[i];
    return q;
  }

  double BoxShape::bounding_radius() const
  {
    return half.norm();
  }

  std::string BoxShape::type() const
  {
    return "box";
  }
} // namespace softgrasp
