#ifndef softgrasp_meshes_file_mesh_h
#define softgrasp_meshes_file_mesh_h

#include <memory>
#include <softgrasp/meshes/manifold_rules.h>
#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  /**
   * 'Mesh/Type = file': a Gmsh (.msh) or Abaqus (.inp) mesh with its own
   * material and boundary ids, scaled to metres; optionally with curved
   * manifolds on some of those ids ('Manifolds', ManifoldRules).
   */
  template <int dim> class FileMesh : public MeshGenerator<dim>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void        create_coarse_mesh(
               dealii::Triangulation<dim> &triangulation) const override;
    void attach_manifolds(dealii::Triangulation<dim> &triangulation,
                          const Placement<dim>       &placement) const override;
    bool is_curved() const override
    {
      return manifolds && !manifolds->empty();
    }
    bool sets_material_ids() const override
    {
      return true;
    }

    std::string                         file_name;
    double                              scale = 1.0; ///< file units to m
    std::unique_ptr<ManifoldRules<dim>> manifolds;
  };
} // namespace softgrasp

#endif
