#ifndef softgrasp_meshes_cook_membrane_h
#define softgrasp_meshes_cook_membrane_h

#include <deal.II/grid/tria.h>

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
} // namespace softgrasp

#endif
