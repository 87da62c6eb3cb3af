#ifndef softgrasp_meshes_ball_mesh_h
#define softgrasp_meshes_ball_mesh_h

#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  /**
   * 'Mesh/Type = ball': a solid ball, or a spherical shell on a rigid core,
   * whole or a symmetric part of it (half: x >= c; quarter: x, y >= c;
   * octant: x, y, z >= c, with c the centre). Boundary ids: 0 on the
   * sphere, 1 on the core's surface, 2/3/4 on the cut planes x/y/z = c
   * (symmetry planes). Curved: its spherical manifold follows the
   * placement.
   */
  template <int dim> class BallMesh : public MeshGenerator<dim>
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
      return true;
    }

    dealii::Point<dim> center;             ///< m
    double             radius      = 0.04; ///< m
    double             core_radius = 0;    ///< m; > 0: shell on a core
    unsigned int       shell_cells = 6;
    /// The part of the ball: "full", "half", "quarter" or "octant" (3D).
    std::string sector = "full";

  private:
    /// The part (not the full ball) from deal.II's positive-orthant ball
    /// or shell, mirrored at the planes y = c and z = c as needed, with
    /// boundary and manifold ids set by position.
    void create_sector(dealii::Triangulation<dim> &triangulation) const;
  };
} // namespace softgrasp

#endif
