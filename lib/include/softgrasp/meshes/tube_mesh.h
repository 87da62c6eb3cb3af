#ifndef softgrasp_meshes_tube_mesh_h
#define softgrasp_meshes_tube_mesh_h

#include <softgrasp/meshes/mesh_generator.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * 'Mesh/Type = tube': a hollow cylinder of soft tissue (e.g. bonded to a
   * rigid bone), whole or a symmetric part of it, in 3D. Its axis is the
   * local x axis from x = -L/2 to L/2 through 'Center'; a cross-section
   * point is (r cos t, r sin t) in (y, z). Radial cells are graded finest
   * at the outer surface (the contact); axially a zone of uniform cells
   * is followed by geometric growth towards the ends.
   *
   * Boundary ids: 0 outer surface, 1 inner surface (bond to a rigid core:
   * fix it), 2 end x = -L/2, 3 end x = L/2, 4 cut plane y = 0 (half and
   * quarter), 5 cut plane z = 0 (quarter). Curved: a cylindrical manifold
   * about the axis that follows the placement.
   */
  class TubeMesh : public MeshGenerator<3>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void
    create_coarse_mesh(dealii::Triangulation<3> &triangulation) const override;
    void attach_manifolds(dealii::Triangulation<3> &triangulation,
                          const Placement<3>       &placement) const override;
    bool is_curved() const override
    {
      return true;
    }

    double n_coarse_cells() const override;

    /// The radial node coordinates r from the inner to the outer surface.
    std::vector<double> radial_nodes() const;
    /// The angles of the circumferential nodes (rad; periodic if full).
    std::vector<double> angles() const;

    dealii::Point<3> center;                         ///< m, on the axis
    double           length                = 0.2;    ///< m
    double           inner_radius          = 0.01;   ///< m
    double           outer_radius          = 0.03;   ///< m
    std::string      sector                = "full"; ///< full, half, quarter
    unsigned int     circumferential_cells = 16;     ///< per full circle
    unsigned int     radial_cells          = 4;      ///< 1
    double           radial_grading        = 1.0;    ///< inner/outer size, 1
    double           zone_center           = 0;      ///< m, along the axis
    double           zone_length           = 0.2;    ///< m
    unsigned int     zone_cells            = 8;      ///< 1
    double           axial_growth          = 1.3;    ///< 1
  };
} // namespace softgrasp

#endif
