#ifndef softgrasp_meshes_file_mesh_h
#define softgrasp_meshes_file_mesh_h

#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  /**
   * 'Mesh/Type = file': a Gmsh (.msh) or Abaqus (.inp) mesh with its own
   * material and boundary ids, scaled to metres.
   */
  template <int dim> class FileMesh : public MeshGenerator<dim>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void        create_coarse_mesh(
               dealii::Triangulation<dim> &triangulation) const override;
    bool sets_material_ids() const override
    {
      return true;
    }

    std::string file_name;
    double      scale = 1.0; ///< file units to m
  };
} // namespace softgrasp

#endif
