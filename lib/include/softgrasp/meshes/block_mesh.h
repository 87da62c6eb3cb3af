#ifndef softgrasp_meshes_block_mesh_h
#define softgrasp_meshes_block_mesh_h

#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  /**
   * 'Mesh/Type = block': an axis-parallel box of hexahedra (quadrilaterals
   * in 2D), optionally graded per direction, or with a fine zone of
   * uniform cells (e.g. under a contact) and geometric growth away from
   * it. Boundary ids 0/1 at x min/max, 2/3 at y min/max, 4/5 at z min/max.
   */
  template <int dim> class BlockMesh : public MeshGenerator<dim>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void        create_coarse_mesh(
               dealii::Triangulation<dim> &triangulation) const override;
    double n_coarse_cells() const override;

    dealii::Point<dim>        lower, upper; ///< m
    std::vector<unsigned int> subdivisions; ///< per direction
    std::vector<double>       grading;      ///< size ratio of neighbours, 1
    /// Corners of the fine zone (m); empty if there is none.
    std::vector<dealii::Point<dim>> fine_zone;

    /// The cell boundaries along direction @p d (m).
    std::vector<double> divisions(const unsigned int d) const;
  };
} // namespace softgrasp

#endif
