#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/shape.h>
#include <sstream>

namespace softgrasp
{
  void ShapeSpec::require_positive(const unsigned int n,
                                   const std::string &meaning) const
  {
    for (unsigned int i = 0; i < n; ++i)
      if (!(size[i] > 0) || !std::isfinite(size[i]))
      {
        std::ostringstream message;
        message << "Geom '" << geom_name << "' of type " << type << " has size["
                << i << "] = " << size[i] << ", but its sizes are " << meaning
                << ", all positive and finite (m). Fix: correct the geom's "
                   "size.";
        throw InputError(message.str());
      }
  }

  std::vector<Eigen::Vector3d> arc(const Eigen::Vector3d &c,
                                   const Eigen::Vector3d &a,
                                   const Eigen::Vector3d &b,
                                   const double           from,
                                   const double           to,
                                   const unsigned int     n)
  {
    std::vector<Eigen::Vector3d> points;
    for (unsigned int i = 0; i <= n; ++i)
    {
      const double t = from + (to - from) * i / n;
      points.push_back(c + std::cos(t) * a + std::sin(t) * b);
    }
    return points;
  }

  std::unique_ptr<Shape> create_shape(const ShapeSpec &spec)
  {
    return ShapeRegistry::create(spec.type,
                                 "type of geom '" + spec.geom_name + "':")
        ->build(spec);
  }

  std::unique_ptr<Shape> create_shape(const std::string     &type,
                                      const Eigen::Vector3d &size,
                                      const std::string     &geom_name)
  {
    ShapeSpec spec;
    spec.type      = type;
    spec.size      = size;
    spec.geom_name = geom_name;
    return create_shape(spec);
  }
} // namespace softgrasp
