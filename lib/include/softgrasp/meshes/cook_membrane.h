#ifndef softgrasp_meshes_cook_membrane_h
#define softgrasp_meshes_cook_membrane_h

#include <deal.II/grid/tria.h>
#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  namespace Meshes
  {
    /**
     * Cook's tapered membrane: the quadrilateral with vertices (0, 0),
     * (48, 44), (48, 60), (0, 44) mm, @p n_per_edge elements along each
     * edge. In 3D it is extruded to @p thickness (m) with @p n_layers
     * elements. Coordinates are in metres.
     *
     * Boundary ids: 0 left (x = 0, clamped in the benchmark), 1 right
     * (x = 48 mm, loaded), 2 bottom, 3 top, and in 3D 4 back (z = 0) and
     * 5 front (z = thickness).
     */
    template <int dim>
    void cook_membrane(dealii::Triangulation<dim> &triangulation,
                       const unsigned int          n_per_edge,
                       const double                thickness = 1e-3,
                       const unsigned int          n_layers  = 1);
  } // namespace Meshes

  /// 'Mesh/Type = Cook's membrane': Meshes::cook_membrane() from the .prm.
  template <int dim> class CookMembraneMesh : public MeshGenerator<dim>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void        create_coarse_mesh(
               dealii::Triangulation<dim> &triangulation) const override;

    unsigned int elements_per_edge = 8;
    double       thickness         = 1e-3; ///< m, 3D only
    unsigned int layers            = 1;
  };
} // namespace softgrasp

#endif
