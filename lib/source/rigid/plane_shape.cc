#include <cmath>
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
    return type_name;
  }

  std::unique_ptr<PlaneShape> PlaneShape::create(const ShapeSpec &spec)
  {
    auto plane = std::make_unique<PlaneShape>();
    for (unsigned int d = 0; d < 2; ++d)
      if (spec.size[d] > 0 && std::isfinite(spec.size[d]))
        plane->drawn_half_size[d] = spec.size[d];
    return plane;
  }

  std::vector<std::vector<Eigen::Vector3d>> PlaneShape::wireframe() const
  {
    const double a = drawn_half_size[0], b = drawn_half_size[1];
    // the outline and its diagonals (a square of the plane)
    return {{{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}, {-a, -b, 0}},
            {{-a, -b, 0}, {a, b, 0}},
            {{-a, b, 0}, {a, -b, 0}}};
  }

  SOFTGRASP_REGISTER_SHAPE(
      PlaneShape,
      "the half-space below the local x-y plane (infinite; size[0..1], if "
      "positive, only set the drawn extent)")
} // namespace softgrasp
