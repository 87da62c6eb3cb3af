#ifndef softgrasp_rigid_cylinder_shape_h
#define softgrasp_rigid_cylinder_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Cylinder of radius r with flat caps at z = -h and h (MuJoCo "cylinder",
   * size r, h).
   */
  class CylinderShape : public Shape
  {
  public:
    CylinderShape(const double radius, const double half_height);
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "cylinder";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<CylinderShape> create(const ShapeSpec &spec);

  private:
    double radius, half_height;
  };
} // namespace softgrasp

#endif
