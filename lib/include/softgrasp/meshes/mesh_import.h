#ifndef softgrasp_meshes_mesh_import_h
#define softgrasp_meshes_mesh_import_h

#include <deal.II/grid/tria.h>
#include <string>

namespace softgrasp
{
  namespace Meshes
  {
    /**
     * Read a coarse mesh from a Gmsh (.msh, format 2 or 4) or Abaqus (.inp)
     * file into @p triangulation, keeping the material ids (Gmsh physical
     * volume/surface tags, Abaqus element sets) and boundary ids (Gmsh
     * physical surface/curve tags, Abaqus surfaces). Coordinates are
     * multiplied by @p scale to give metres (1e-3 for a file in mm).
     *
     * A missing, unreadable or malformed file, or an unsupported extension,
     * is an InputError naming the file and the fix.
     */
    template <int dim>
    void read_mesh_file(dealii::Triangulation<dim> &triangulation,
                        const std::string          &filename,
                        const double                scale = 1.0);
  } // namespace Meshes
} // namespace softgrasp

#endif
