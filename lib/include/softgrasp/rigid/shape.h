#ifndef softgrasp_rigid_shape_h
#define softgrasp_rigid_shape_h

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <memory>
#include <softgrasp/base/plugin_registry.h>
#include <string>
#include <vector>

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

    /// Polylines that draw the shape (local frame, m), for pictures.
    virtual std::vector<std::vector<Eigen::Vector3d>> wireframe() const = 0;
  };

  /// What a shape is built from: MuJoCo's geom type and size vector (m),
  /// and for a triangle mesh its file and length scale.
  struct ShapeSpec
  {
    std::string     type;
    Eigen::Vector3d size = Eigen::Vector3d::Zero(); ///< m
    std::string     geom_name;                      ///< for messages
    std::string     mesh_file;                      ///< STL or OBJ
    double          mesh_scale = 1;                 ///< m per file unit
    /// A mesh given by its surface instead of a file (from a kinematics
    /// file): vertices (m) and triangles, counter-clockwise from outside.
    std::vector<Eigen::Vector3d>         vertices;
    std::vector<std::array<unsigned, 3>> triangles;

    /// Throw an InputError naming the geom unless size[0..n) are positive
    /// and finite; @p meaning says what they are.
    void require_positive(const unsigned int n,
                          const std::string &meaning) const;
  };

  /**
   * Builds the shape of one geom type: each shape type registers one
   * (SOFTGRASP_REGISTER_SHAPE) under its MuJoCo type name, so the code
   * that creates shapes never lists the types.
   */
  class ShapeBuilder
  {
  public:
    virtual ~ShapeBuilder()                                           = default;
    virtual std::unique_ptr<Shape> build(const ShapeSpec &spec) const = 0;
    /// Shapes take their sizes from the geom, not from a subsection.
    static void declare_parameters(dealii::ParameterHandler &)
    {
    }
  };

  /// The registry of shape types.
  using ShapeRegistry = PluginRegistry<ShapeBuilder>;

  /// The builder of a shape class with a static create(const ShapeSpec &).
  template <class ShapeClass> class ShapeBuilderOf : public ShapeBuilder
  {
  public:
    std::unique_ptr<Shape> build(const ShapeSpec &spec) const override
    {
      return ShapeClass::create(spec);
    }
  };

  /**
   * Build a shape from MuJoCo's geom type and size vector (m), e.g.
   * sphere (r), capsule (r, half-length), cylinder (r, half-height), box
   * (three half-sizes), ellipsoid (three radii), plane, mesh (from the
   * spec's file). An unknown type lists the registered ones; missing or
   * non-positive sizes are an InputError naming the geom.
   */
  std::unique_ptr<Shape> create_shape(const ShapeSpec &spec);

  /// The polyline c + cos(t) a + sin(t) b for t from @p from to @p to
  /// (rad) in @p n segments: circles, ellipses and arcs of wireframes.
  std::vector<Eigen::Vector3d> arc(const Eigen::Vector3d &c,
                                   const Eigen::Vector3d &a,
                                   const Eigen::Vector3d &b,
                                   const double           from = 0,
                                   const double           to   = 2 * M_PI,
                                   const unsigned int     n    = 32);

  /// The same for the primitive types (no mesh file).
  std::unique_ptr<Shape> create_shape(const std::string     &type,
                                      const Eigen::Vector3d &size,
                                      const std::string     &geom_name);
} // namespace softgrasp

/**
 * Register shape class @p Class (derived from Shape, with a static
 * constexpr type_name and a static create(const ShapeSpec &)) under its
 * type name.
 */
#define SOFTGRASP_REGISTER_SHAPE(Class, description)                           \
  namespace                                                                    \
  {                                                                            \
    [[maybe_unused]] const bool softgrasp_registered_shape_##Class =           \
        ::softgrasp::ShapeRegistry::register_plugin(                           \
            Class::type_name,                                                  \
            description,                                                       \
            &::softgrasp::ShapeBuilder::declare_parameters,                    \
            []() -> std::unique_ptr<::softgrasp::ShapeBuilder> {               \
              return std::make_unique<::softgrasp::ShapeBuilderOf<Class>>();   \
            });                                                                \
  }

#endif
