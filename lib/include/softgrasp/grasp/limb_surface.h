#ifndef softgrasp_grasp_limb_surface_h
#define softgrasp_grasp_limb_surface_h

#include <Eigen/Core>
#include <array>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>
#include <softgrasp/meshes/layered_limb.h>
#include <vector>

namespace softgrasp
{
  /**
   * The closed skin surface of a limb segment as triangles with outward
   * normals, in the limb's own frame (axis along x, centred at x = 0; see
   * doc/layered_limb.md): what the rigid arm of a MuJoCo scene is made of,
   * so that the rigid arm and the finite element limb share one geometry.
   * It comes either from the layered limb's analytic shape or from any
   * mesh's skin faces (boundary id 0), whose open ends are closed by flat
   * caps.
   */
  struct LimbSurface
  {
    using Triangle = std::array<Eigen::Vector3d, 3>;

    double                length = 0; ///< extent along the axis (m)
    std::vector<Triangle> triangles;  ///< outward, limb frame (m)

    /// The enclosed volume (divergence theorem; m^3).
    double volume() const;

    /// The skin of @p limb with @p facets facets around it: a ruled
    /// surface between the shoulder and elbow rings, and flat end caps.
    static LimbSurface of_layered_limb(const LimbGeometry &limb,
                                       const unsigned int  facets);

    /**
     * The faces of @p mesh with boundary id @p skin (quadrilaterals split
     * into two triangles, oriented out of their cells), each open end
     * closed by a fan about the centroid of its rim. Throws an InputError
     * if no face has that id, if the skin is not a manifold surface, or if
     * the mesh is not in the limb's frame (its skin centred at x = 0).
     */
    static LimbSurface of_mesh(const dealii::Triangulation<3>  &mesh,
                               const dealii::types::boundary_id skin);
  };
} // namespace softgrasp

#endif
