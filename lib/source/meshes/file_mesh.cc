#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
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
    prm.leave_subsection();
  }

  template <int dim> void FileMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("File");
    file_name = Utilities::trim(prm.get("File name"));
    scale     = prm.get_double("Scale");
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
  }

  template class FileMesh<2>;
  template class FileMesh<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH(softgrasp::FileMesh,
                        file,
                        "file",
                        "a Gmsh (.msh) or Abaqus (.inp) mesh file")
