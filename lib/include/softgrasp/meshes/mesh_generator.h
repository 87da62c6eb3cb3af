#ifndef softgrasp_meshes_mesh_generator_h
#define softgrasp_meshes_mesh_generator_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <softgrasp/base/plugin_registry.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A rigid placement x -> R x + t of a mesh built in its own frame: how a
   * study puts the tissue at the pose a rigid-body simulator recorded for
   * the grasped object. R is a rotation, t in m.
   */
  template <int dim> struct Placement
  {
    dealii::Tensor<2, dim> rotation = dealii::unit_symmetric_tensor<dim>();
    dealii::Tensor<1, dim> translation; ///< m

    dealii::Point<dim> operator()(const dealii::Point<dim> &x) const
    {
      return dealii::Point<dim>(rotation * x + translation);
    }
    /// A direction (unit vector or tangent) rotated, not translated.
    dealii::Tensor<1, dim> rotate(const dealii::Tensor<1, dim> &v) const
    {
      return rotation * v;
    }
    bool is_identity() const
    {
      return (rotation -
              dealii::Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()))
                     .norm() == 0 &&
             translation.norm() == 0;
    }
  };

  /**
   * One kind of coarse mesh (block, ball, file, layered limb, ...), chosen
   * by 'Mesh/Type'. An implementation declares its entries in its own
   * subsection of "Mesh" (a static declare_parameters(), passed at
   * registration), reads them in parse_parameters() with the handler inside
   * "Mesh", and builds the coarse mesh in its own frame. Implementations
   * register themselves by name (SOFTGRASP_REGISTER_MESH); MeshFactory
   * never lists them.
   */
  template <int dim> class MeshGenerator
  {
  public:
    virtual ~MeshGenerator() = default;

    /// Read this generator's entries; @p prm is inside "Mesh".
    virtual void parse_parameters(dealii::ParameterHandler &prm) = 0;

    /// Build the coarse mesh in the generator's own frame, with boundary,
    /// material (if sets_material_ids()) and manifold ids.
    virtual void
    create_coarse_mesh(dealii::Triangulation<dim> &triangulation) const = 0;

    /// Attach the manifolds of the ids create_coarse_mesh() set, for the
    /// mesh moved by @p placement (its vertices already are).
    virtual void attach_manifolds(dealii::Triangulation<dim> &triangulation,
                                  const Placement<dim>       &placement) const
    {
      (void)triangulation;
      (void)placement;
    }

    /// True if the mesh has curved manifolds (the mapping then has the
    /// element's degree).
    virtual bool is_curved() const
    {
      return false;
    }

    /// The number of coarse cells, known before the mesh is built so that
    /// a run too large for the machine is refused before it is (0: known
    /// only once built, e.g. for a file).
    virtual double n_coarse_cells() const
    {
      return 0;
    }

    /// True if the generator sets the material ids (several tissues);
    /// otherwise 'Mesh/Material id' is applied to every cell.
    virtual bool sets_material_ids() const
    {
      return false;
    }
  };

  template <int dim> using MeshRegistry = PluginRegistry<MeshGenerator<dim>>;

  /**
   * The coordinates of the cell boundaries of an interval [a, b] split into
   * @p n cells whose sizes grow by @p ratio from a to b (1: uniform).
   */
  std::vector<double> geometric_division(const double       a,
                                         const double       b,
                                         const unsigned int n,
                                         const double       ratio);

  /**
   * The cell boundaries of [a, b] with a zone [zone_begin, zone_end] of
   * @p zone_cells uniform cells (size h) and, on each side of it, cells
   * that grow by @p growth (>= 1) from h towards a and b; as many as fill
   * the rest (the outermost are scaled to end exactly at a and b).
   */
  std::vector<double> zoned_division(const double       a,
                                     const double       b,
                                     const double       zone_begin,
                                     const double       zone_end,
                                     const unsigned int zone_cells,
                                     const double       growth);

  /// "v, v[, v]": a default with one value per coordinate direction.
  template <int dim> std::string per_direction(const std::string &value);

  /// A point of @p dim comma-separated coordinates (m); @p path names the
  /// entry in the error message.
  template <int dim>
  dealii::Point<dim> parse_point(const std::string &text,
                                 const std::string &path);
} // namespace softgrasp

/**
 * Register the mesh generator template @p Class (instantiated for 2D and 3D)
 * under @p name; @p tag is a unique identifier.
 */
#define SOFTGRASP_REGISTER_MESH(Class, tag, name, description)                 \
  namespace                                                                    \
  {                                                                            \
    [[maybe_unused]] const bool softgrasp_mesh_2d_##tag =                      \
        ::softgrasp::MeshRegistry<2>::register_plugin(                         \
            name,                                                              \
            description,                                                       \
            &Class<2>::declare_parameters,                                     \
            []() -> std::unique_ptr<::softgrasp::MeshGenerator<2>>             \
            { return std::make_unique<Class<2>>(); });                         \
    [[maybe_unused]] const bool softgrasp_mesh_3d_##tag =                      \
        ::softgrasp::MeshRegistry<3>::register_plugin(                         \
            name,                                                              \
            description,                                                       \
            &Class<3>::declare_parameters,                                     \
            []() -> std::unique_ptr<::softgrasp::MeshGenerator<3>>             \
            { return std::make_unique<Class<3>>(); });                         \
  }

/// As SOFTGRASP_REGISTER_MESH, for a 3D-only (non-template) @p Class.
#define SOFTGRASP_REGISTER_MESH_3D(Class, tag, name, description)              \
  namespace                                                                    \
  {                                                                            \
    [[maybe_unused]] const bool softgrasp_mesh_3d_##tag =                      \
        ::softgrasp::MeshRegistry<3>::register_plugin(                         \
            name,                                                              \
            description,                                                       \
            &Class::declare_parameters,                                        \
            []() -> std::unique_ptr<::softgrasp::MeshGenerator<3>>             \
            { return std::make_unique<Class>(); });                            \
  }

#endif
