#ifndef softgrasp_meshes_manifold_rules_h
#define softgrasp_meshes_manifold_rules_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <softgrasp/meshes/mesh_generator.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Curved geometry for a mesh read from a file, from the .prm
   * ('Mesh/File/Manifolds'): a list of rules "target: kind", each giving
   * the cells of a material id or the boundary faces of a boundary id a
   * manifold, so that the mapping and refinement follow the true surfaces
   * instead of the file's straight-sided cells.
   *
   * Targets: 'boundary <id>' (those faces and their edges) and
   * 'material <id>' (those cells, their faces and edges). Kinds:
   * 'sphere <centre>' (a circle in 2D), 'cylinder <axis direction> through
   * <point on the axis>' (3D), 'transfinite' (material ids only: the cell
   * interiors blend the curved boundaries into the volume, deal.II's
   * TransfiniteInterpolationManifold). Points in m, in the mesh's own
   * frame. Boundary faces of a transfinite material that no boundary rule
   * names stay flat. Boundary rules are applied after material rules.
   */
  template <int dim> class ManifoldRules
  {
  public:
    /// One rule.
    struct Rule
    {
      enum class Target
      {
        boundary,
        material
      } target;
      unsigned int id; ///< boundary or material id
      enum class Kind
      {
        sphere,
        cylinder,
        transfinite
      } kind;
      dealii::Point<dim>     point; ///< sphere centre or point on axis, m
      dealii::Tensor<1, dim> axis;  ///< cylinder axis (unit)

      /// @p x relative to the centre (sphere), or to the axis with its
      /// axial part removed (cylinder); its norm is the radius at @p x (m).
      dealii::Tensor<1, dim> from_centre(const dealii::Point<dim> &x) const
      {
        dealii::Tensor<1, dim> d = x - point;
        if (kind == Kind::cylinder)
          d -= (d * axis) * axis;
        return d;
      }
    };

    /// Parse @p text ("" for none); @p path names the entry in errors.
    ManifoldRules(const std::string &text, const std::string &path);

    bool empty() const
    {
      return rules.empty();
    }
    /// Set the manifold ids (rule k gets id k) on a coarse mesh read from a
    /// file; an id that the mesh does not have is an InputError listing
    /// the ids it has, and so is a sphere or cylinder rule on boundary
    /// faces that do not lie on such a surface around its centre or axis
    /// (check_fit()).
    void set_manifold_ids(dealii::Triangulation<dim> &triangulation) const;
    /// Attach the manifolds for the mesh moved by @p placement.
    void attach(dealii::Triangulation<dim> &triangulation,
                const Placement<dim>       &placement) const;

    const std::vector<Rule> &list() const
    {
      return rules;
    }

  private:
    /// Every face of boundary rule @p k (sphere or cylinder) must have its
    /// vertices at one distance from the centre (axis), within 1 % of the
    /// face's size; an InputError naming the rule, the id, the largest
    /// distance of a vertex from its face's surface and the fix otherwise.
    void check_fit(const dealii::Triangulation<dim> &triangulation,
                   const unsigned int                k) const;
    /// Every edge of the cells of material rule @p k (sphere or cylinder)
    /// must run along the rule's coordinate lines: on one sphere (cylinder)
    /// within 1 % of its length, or radially (in a plane through the
    /// axis); an InputError naming the rule, the edge and the fix otherwise.
    void check_cells_fit(const dealii::Triangulation<dim> &triangulation,
                         const unsigned int                k) const;

    std::vector<Rule>        rules;
    std::vector<std::string> texts; ///< each rule as written
    std::string              path;
  };
} // namespace softgrasp

#endif
