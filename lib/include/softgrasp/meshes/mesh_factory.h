#ifndef softgrasp_meshes_mesh_factory_h
#define softgrasp_meshes_mesh_factory_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The mesh of a run, from the "Mesh" subsection: a generated block,
   * Cook's membrane or ball, or a Gmsh/Abaqus file. The coarse mesh and the
   * global refinement are separate steps so that a checkpoint can rebuild
   * the same coarse mesh before it loads the refined, partitioned one.
   *
   * Generated meshes set material id 0 (unless "Material id" says
   * otherwise) and these boundary ids:
   *  - block: 0/1 at x min/max, 2/3 at y min/max, 4/5 at z min/max;
   *  - Cook's membrane: see Meshes::cook_membrane();
   *  - ball: 0 on the sphere, 1 on the rigid core ("Core radius" > 0).
   */
  template <int dim> class MeshFactory
  {
  public:
    enum class Type
    {
      block,
      cook_membrane,
      ball,
      file
    };

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);

    /// Build the coarse mesh (with its manifolds) into @p triangulation.
    void create_coarse_mesh(dealii::Triangulation<dim> &triangulation) const;

    /// Apply the global refinements.
    void refine(dealii::Triangulation<dim> &triangulation) const;

    /// A suitable mapping degree: 1, or the FE degree for curved meshes.
    bool has_curved_boundary() const;

    Type type = Type::block;
    // block
    dealii::Point<dim>        lower, upper; ///< m
    std::vector<unsigned int> subdivisions;
    std::vector<double>       grading; ///< size ratio of neighbours (1)
    // Cook's membrane
    unsigned int elements_per_edge = 8;
    double       thickness         = 1e-3; ///< m, 3D only
    unsigned int layers            = 1;
    // ball
    dealii::Point<dim> center;             ///< m
    double             radius      = 0.04; ///< m
    double             core_radius = 0;    ///< m; > 0: shell on a core
    unsigned int       shell_cells = 6;
    // file
    std::string file_name;
    double      scale = 1.0; ///< file units to m
    // all
    unsigned int               global_refinements = 0;
    double                     distortion         = 0; ///< of cell size, 1
    dealii::types::material_id material_id        = 0;
  };
} // namespace softgrasp

#endif
