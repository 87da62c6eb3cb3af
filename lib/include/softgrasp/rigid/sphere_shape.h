#ifndef softgrasp_rigid_sphere_shape_h
#define softgrasp_rigid_sphere_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Sphere of radius r about the local origin (MuJoCo "sphere", size r).
   */
  class SphereShape : public Shape
  {
  public:
    explicit SphereShape(const double radius);
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "sphere";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<SphereShape> create(const ShapeSpec &spec);

  private:
    double radius;
  };
} // namespace softgrasp

#endif
