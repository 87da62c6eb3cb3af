#ifndef softgrasp_rigid_triangle_mesh_shape_h
#define softgrasp_rigid_triangle_mesh_shape_h

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <softgrasp/rigid/shape.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A rigid body surface given as a closed triangle mesh (MuJoCo's "mesh"
   * geom; STL or OBJ files). The signed distance is the distance to the
   * closest triangle, found through a bounding-volume hierarchy of
   * axis-aligned boxes; its sign comes from the angle-weighted
   * pseudo-normal of the closest feature (face, edge or vertex; Baerentzen
   * and Aanaes 2005), which is exact for closed, consistently oriented
   * meshes. The mesh is checked to be such a mesh on construction.
   */
  class TriangleMeshShape : public Shape
  {
  public:
    /// @p vertices (m) and @p triangles (counter-clockwise seen from
    /// outside); @p source names the mesh in error messages.
    TriangleMeshShape(std::vector<Eigen::Vector3d>         vertices,
                      std::vector<std::array<unsigned, 3>> triangles,
                      const std::string                   &source);

    /**
     * Read an STL (ASCII or binary) or OBJ file; coordinates are multiplied
     * by @p scale (e.g. 0.001 for a file in mm). Errors name the file, the
     * problem and the fix.
     */
    static std::unique_ptr<TriangleMeshShape> read(const std::string &filename,
                                                   const double scale = 1.0);

    ShapeQuery  query(const Eigen::Vector3d &x) const override;
    double      bounding_radius() const override;
    std::string type() const override;
    std::vector<std::vector<Eigen::Vector3d>> wireframe() const override;

    /// The MuJoCo geom type name, spelled only here.
    static constexpr const char *type_name = "mesh";
    /// Build from a geom's spec (sizes checked).
    static std::unique_ptr<TriangleMeshShape> create(const ShapeSpec &spec);

    unsigned int n_triangles() const;

  private:
    struct BoxNode
    {
      Eigen::Vector3d lower, upper;
      int             left = -1, right = -1; ///< children, or -1 for a leaf
      unsigned int    begin = 0, end = 0;    ///< triangle range of a leaf
    };

    /// Directed edge (a, b) -> (triangle, local edge).
    using EdgeMap = std::map<std::pair<unsigned int, unsigned int>,
                             std::pair<unsigned int, unsigned int>>;
    /// The directed edges of a closed, consistently oriented surface; an
    /// InputError naming @p source otherwise.
    EdgeMap check_closed(const std::string &source) const;
    /// Face, vertex (angle-weighted) and edge normals of the outward
    /// oriented surface; an InputError for a degenerate triangle.
    void compute_normals(const EdgeMap &edges, const std::string &source);

    int  build(const unsigned int begin, const unsigned int end);
    void closest(const int              node,
                 const Eigen::Vector3d &x,
                 double                &best_squared,
                 unsigned int          &best_triangle,
                 Eigen::Vector3d       &best_point,
                 int                   &best_feature) const;

    std::vector<Eigen::Vector3d>         vertices;
    std::vector<std::array<unsigned, 3>> triangles;
    std::vector<Eigen::Vector3d>         face_normals;
    /// pseudo-normals per triangle edge (edge k joins corners k and k+1)
    std::vector<std::array<Eigen::Vector3d, 3>> edge_normals;
    std::vector<Eigen::Vector3d>                vertex_normals;
    std::vector<BoxNode>                        tree;
    std::vector<unsigned int>                   order; ///< triangles by leaf
    double                                      radius = 0;
    double                                      size   = 0;
  };
} // namespace softgrasp

#endif
