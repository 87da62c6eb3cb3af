#ifndef softgrasp_rigid_shape_h
#define softgrasp_rigid_shape_h

#include <Eigen/Core>
#include <memory>
#include <string>

namespace softgrasp
{
  /// Result of a proximity query of a point against a shape (local frame).
  struct ShapeQuery
  {
    double          distance = 0; ///< signed distance, negative inside (m)
    Eigen::Vector3d normal;       ///< outward unit normal at the closest point
    Eigen::Vector3d closest;      ///< closest point on the surface (m)
  };

  /**
   * A rigid geometric primitive in its local frame, with the conventions of
   * MuJoCo's geoms (axis of capsules and cylinders along local z, plane
   * normal along local z). A shape answers, for any point, the signed
   * distance to its surface (negative inside), the outward normal and the
   * closest surface point: all a rigid contactor needs (the mortar contact
   * evaluates gaps and normals through it).
   */
  class Shape
  {
  public:
    virtual ~Shape() = default;

    /// Query point @p x given in the shape's local frame (m).
    virtual ShapeQuery query(const Eigen::Vector3d &x) const = 0;

    /// Radius of a sphere about the local origin that holds the shape (m);
    /// infinite for unbounded shapes (plane).
    virtual double bounding_radius() const = 0;

    /// The MuJoCo geom type name ("sphere", "capsule", ...).
    virtual std::string type() const = 0;
  };

  /**
   * Build a shape from MuJoCo's geom type and size vector (m):
   * sphere (r), capsule (r, half-length), cylinder (r, half-height),
   * box (three half-sizes), ellipsoid (three radii), plane (half-sizes,
   * ignored: the plane is infinite). Unknown types, missing or non-positive
   * sizes are an InputError naming the geom.
   */
  std::unique_ptr<Shape> create_shape(const std::string     &type,
                                      const Eigen::Vector3d &size,
                                      const std::string     &geom_name);
} // namespace softgrasp

#endif
