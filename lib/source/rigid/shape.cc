#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/box_shape.h>
#include <softgrasp/rigid/capsule_shape.h>
#include <softgrasp/rigid/cylinder_shape.h>
#include <softgrasp/rigid/ellipsoid_shape.h>
#include <softgrasp/rigid/plane_shape.h>
#include <softgrasp/rigid/sphere_shape.h>
#include <sstream>

namespace softgrasp
{
  namespace
  {
    void require_positive(const Eigen::Vector3d &size,
                          const unsigned int     n,
                          const std::string     &type,
                          const std::string     &geom_name,
                          const std::string     &meaning)
    {
      for (unsigned int i = 0; i < n; ++i)
        if (!(size[i] > 0) || !std::isfinite(size[i]))
        {
          std::ostringstream message;
          message << "Geom '" << geom_name << "' of type " << type
                  << " has size[" << i << "] = " << size[i]
                  << ", but its sizes are " << meaning
                  << ", all positive and finite (m). Fix: correct the geom's "
                     "size.";
          throw InputError(message.str());
        }
    }
  } // namespace

  std::unique_ptr<Shape> create_shape(const std::string     &type,
                                      const Eigen::Vector3d &size,
                                      const std::string     &geom_name)
  {
    if (type == "sphere")
    {
      require_positive(size, 1, type, geom_name, "(radius)");
      return std::make_unique<SphereShape>(size[0]);
    }
    if (type == "capsule")
    {
      require_positive(size, 2, type, geom_name, "(radius, half-length)");
      return std::make_unique<CapsuleShape>(size[0], size[1]);
    }
    if (type == "cylinder")
    {
      require_positive(size, 2, type, geom_name, "(radius, half-height)");
      return std::make_unique<CylinderShape>(size[0], size[1]);
    }
    if (type == "box")
    {
      require_positive(size, 3, type, geom_name, "three half-sizes");
      return std::make_unique<BoxShape>(size);
    }
    if (type == "ellipsoid")
    {
      require_positive(size, 3, type, geom_name, "three radii");
      return std::make_unique<EllipsoidShape>(size);
    }
    if (type == "plane")
      return std::make_unique<PlaneShape>();
    throw InputError("Geom '" + geom_name + "' has the unknown type '" + type +
                     "'. Fix: use one of: sphere, capsule, cylinder, box, "
                     "ellipsoid, plane.");
  }
} // namespace softgrasp
