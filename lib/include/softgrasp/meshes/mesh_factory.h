#ifndef softgrasp_meshes_mesh_factory_h
#define softgrasp_meshes_mesh_factory_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>
#include <memory>
#include <softgrasp/meshes/mesh_generator.h>
#include <string>

namespace softgrasp
{
  /**
   * The mesh of a run, from the "Mesh" subsection: the generator that
   * 'Mesh/Type' names (any registered MeshGenerator: block, Cook's
   * membrane, ball, file, layered limb, ...), its placement, the material
   * id of single-material meshes, the random distortion and the global
   * refinements. The coarse mesh and the refinement are separate steps so
   * that a checkpoint can rebuild the same coarse mesh before it loads the
   * refined, partitioned one.
   *
   * A study may replace the generator (set_generator()) or the placement
   * after parsing: typed values, never written back into the .prm.
   */
  template <int dim> class MeshFactory
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);

    /// Build the coarse mesh (with its manifolds) into @p triangulation,
    /// placed by 'placement'.
    void create_coarse_mesh(dealii::Triangulation<dim> &triangulation) const;

    /// Apply the global refinements.
    void refine(dealii::Triangulation<dim> &triangulation) const;

    /// True if the mesh has curved manifolds (mapping of the FE degree).
    bool has_curved_boundary() const;

    /// Use @p mesh instead of the one 'Mesh/Type' names.
    void set_generator(std::shared_ptr<const MeshGenerator<dim>> mesh,
                       const std::string                        &name);

    const MeshGenerator<dim> &generator() const;

    std::string    type_name = "block"; ///< the registered name
    Placement<dim> placement; ///< of the generator's frame in the world
    unsigned int   global_refinements      = 0;
    double         distortion              = 0; ///< of cell size, 1
    dealii::types::material_id material_id = 0;

  private:
    /// Refuse entries set for a mesh type other than 'Mesh/Type' (they
    /// would be ignored); @p prm is inside "Mesh".
    void refuse_entries_of_other_types(dealii::ParameterHandler &prm);

    std::shared_ptr<const MeshGenerator<dim>> mesh;
  };
} // namespace softgrasp

#endif
