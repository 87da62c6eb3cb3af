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
    return type_name;
  }

  std::unique_ptr<BoxShape> BoxShape::create(const ShapeSpec &spec)
  {
    spec.require_positive(3, "three half-sizes");
    return std::make_unique<BoxShape>(spec.size);
  }

  std::vector<std::vector<Eigen::Vector3d>> BoxShape::wireframe() const
  {
    // the 12 edges: along each axis d, four edges at the corners of the
    // other two
    std::vector<std::vector<Eigen::Vector3d>> lines;
    for (unsigned int d = 0; d < 3; ++d)
      for (const double s1 : {-1.0, 1.0})
        for (const double s2 : {-1.0, 1.0})
        {
          Eigen::Vector3d a;
          a[d]              = -half[d];
          a[(d + 1) % 3]    = s1 * half[(d + 1) % 3];
          a[(d + 2) % 3]    = s2 * half[(d + 2) % 3];
          Eigen::Vector3d b = a;
          b[d]              = half[d];
          lines.push_back({a, b});
        }
    return lines;
  }

  SOFTGRASP_REGISTER_SHAPE(
      BoxShape, "a box with half-sizes size[0..2] along the local axes")
} // namespace softgrasp
