#ifndef softgrasp_meshes_block_mesh_h
#define softgrasp_meshes_block_mesh_h

#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  /**
   * 'Mesh/Type = block': an axis-parallel box of hexahedra (quadrilaterals
   * in 2D), optionally graded per direction. Boundary ids 0/1 at x min/max,
   * 2/3 at y min/max, 4/5 at z min/max.
   */
  template <int dim> class BlockMesh : public MeshGenerator<dim>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void        create_coarse_mesh(
               dealii::Triangulation<dim> &triangulation) const override;

    dealii::Point<dim>        lower, upper; ///< m
    std::vector<unsigned int> subdivisions; ///< per direction
    std::vector<double>       grading;      ///< size ratio of neighbours, 1
  };
} // namespace softgrasp

#endif
