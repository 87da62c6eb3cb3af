#ifndef softgrasp_rigid_capsule_shape_h
#define softgrasp_rigid_capsule_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Capsule: the points within r of the segment z in [-h, h] of the local z
   * axis (MuJoCo "capsule", size r, h).
   */
  class CapsuleShape : public Shape
  {
  public:
    CapsuleShape(const double radius, const double half_length);
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;

  private:
    double radius, half_length;
  };
} // namespace softgrasp

#endif
