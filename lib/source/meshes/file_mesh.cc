#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/meshes/file_mesh.h>
#include <softgrasp/meshes/mesh_import.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void FileMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("File");
    prm.declare_entry("File name",
                      "",
                      Patterns::Anything(),
                      "Gmsh (.msh) or Abaqus (.inp) file, relative to the "
                      "working directory.");
    prm.declare_entry("Scale",
                      "1",
                      Patterns::Double(0),
                      "Factor from the file's length unit to metres (1e-3 "
                      "for millimetres). Unit: m per file unit.");
    prm.declare_entry(
        "Manifolds",
        "",
        Patterns::Anything(),
        "Curved geometry on the file's ids, so that the (quadratic) mapping "
        "and refinement follow the true surfaces, not the file's "
        "straight-sided cells: rules separated by ';', each 'boundary <id>: "
        "<kind>' (those faces and their edges) or 'material <id>: <kind>' "
        "(those cells). Kinds: 'sphere x, y, z' (centre; a circle in 2D), "
        "'cylinder ax, ay, az through x, y, z' (axis direction and a point "
        "on the axis; 3D), 'transfinite' (material ids only: blends the "
        "curved boundaries into the cells' interior). Example for a solid "
        "ball: 'boundary 0: sphere 0, 0, 0; material 0: transfinite'. "
        "Boundary faces of a transfinite material that no rule names stay "
        "flat. Empty: the file's cells as they are. Unit: m (after "
        "'Scale').");
    prm.leave_subsection();
  }

  template <int dim> void FileMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("File");
    file_name = Utilities::trim(prm.get("File name"));
    RunManifest::protect_input(file_name);
    scale     = prm.get_double("Scale");
    manifolds = std::make_unique<ManifoldRules<dim>>(prm.get("Manifolds"),
                                                     "Mesh/File/Manifolds");
    prm.leave_subsection();
    if (!(scale > 0))
      throw InputError("Parameter 'Mesh/File/Scale' is " +
                       std::to_string(scale) +
                       "; it must be positive. Fix: give the factor from the "
                       "file's length unit to metres (1 for metres, 1e-3 for "
                       "millimetres).");
    if (file_name.empty())
      throw InputError("Parameter 'Mesh/File/File name' is empty but "
                       "'Mesh/Type' is 'file'. Fix: name a .msh or .inp "
                       "file.");
  }

  template <int dim>
  void
  FileMesh<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    Meshes::read_mesh_file(triangulation, file_name, scale);
    if (manifolds)
      manifolds->set_manifold_ids(triangulation);
  }

  template <int dim>
  void FileMesh<dim>::attach_manifolds(Triangulation<dim>   &triangulation,
                                       const Placement<dim> &placement) const
  {
    if (manifolds)
      manifolds->attach(triangulation, placement);
  }

  template class FileMesh<2>;
  template class FileMesh<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH(softgrasp::FileMesh,
                        file,
                        "file",
                        "a Gmsh (.msh) or Abaqus (.inp) mesh file")
