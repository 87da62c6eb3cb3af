#ifndef softgrasp_rigid_plane_shape_h
#define softgrasp_rigid_plane_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Half-space z <= 0 of the local frame: surface z = 0, outward normal +z
   * (MuJoCo "plane"; infinite, MuJoCo's size only affects rendering).
   */
  class PlaneShape : public Shape
  {
  public:
    PlaneShape() = default;
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;
  };
} // namespace softgrasp

#endif
