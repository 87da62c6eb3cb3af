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
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "capsule";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<CapsuleShape> create(const ShapeSpec &spec);

  private:
    double radius, half_length;
  };
} // namespace softgrasp

#endif
