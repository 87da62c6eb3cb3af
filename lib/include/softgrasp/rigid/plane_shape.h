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
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "plane";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<PlaneShape> create(const ShapeSpec &spec);

  private:
    /// Half-sizes (m) of the drawn square; the plane itself is infinite.
    Eigen::Vector2d drawn_half_size{0.05, 0.05};
  };
} // namespace softgrasp

#endif
