#ifndef softgrasp_rigid_box_shape_h
#define softgrasp_rigid_box_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Box with half-sizes (a, b, c) along the local axes (MuJoCo "box").
   */
  class BoxShape : public Shape
  {
  public:
    explicit BoxShape(const Eigen::Vector3d &half_sizes);
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;

  private:
    Eigen::Vector3d half;
  };
} // namespace softgrasp

#endif
