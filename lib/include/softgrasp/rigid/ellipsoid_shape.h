#ifndef softgrasp_rigid_ellipsoid_shape_h
#define softgrasp_rigid_ellipsoid_shape_h

#include <softgrasp/rigid/shape.h>

namespace softgrasp
{
  /**
   * Ellipsoid with radii (a, b, c) (MuJoCo "ellipsoid"). The closest point
   * solves the Lagrange condition x_i = y_i (1 + t / r_i^2) for t by bisection
   * on a monotone function (Eberly), to round-off, including the degenerate
   * case of points on the plane of the shortest axis.
   */
  class EllipsoidShape : public Shape
  {
  public:
    explicit EllipsoidShape(const Eigen::Vector3d &radii);
    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "ellipsoid";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<EllipsoidShape> create(const ShapeSpec &spec);

  private:
    Eigen::Vector3d radii;
  };
} // namespace softgrasp

#endif
