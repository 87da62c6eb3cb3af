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
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "box";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<BoxShape> create(const ShapeSpec &spec);

  private:
    Eigen::Vector3d half;
  };
} // namespace softgrasp

#endif
