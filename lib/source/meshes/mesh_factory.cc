#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/meshes/cook_membrane.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/meshes/mesh_import.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    const std::vector<std::pair<std::string, int>> type_names = {
        {"block", 0}, {"Cook's membrane", 1}, {"ball", 2}, {"file", 3}};

    /// "v, v[, v]": one value per coordinate direction.
    template <int dim> std::string per_direction(const std::string &value)
    {
      return dim == 2 ? value + ", " + value
                      : value + ", " + value + ", " + value;
    }

    /// A list with one value for all directions or one per direction.
    template <int dim, typename T>
    std::vector<T> per_direction_list(const std::vector<T> &values,
                                      const std::string    &path)
    {
      if (values.size() != 1 && values.size() != dim)
        throw InputError("Parameter '" + path + "' has " +
                         std::to_string(values.size()) + " values; a " +
                         std::to_string(dim) + "D block needs " +
                         std::to_string(dim) +
                         " (one per direction) or 1 (the same in all). Fix: "
                         "give " +
                         std::to_string(dim) + " values.");
      return values.size() == dim ? values
                                  : std::vector<T>(dim, values.front());
    }

    template <int dim>
    Point<dim> parse_point(const std::string &text, const std::string &path)
    {
      std::vector<double> values;
      try
      {
        values =
            Utilities::string_to_double(Utilities::split_string_list(text));
      }
      catch (...)
      {
      }
      if (values.size() != dim)
        throw InputError("Parameter '" + path + "' = '" + text + "' needs " +
                         std::to_string(dim) +
                         " comma-separated coordinates (m) in a " +
                         std::to_string(dim) +
                         "D problem. Fix: give one number per coordinate.");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }
  } // namespace

  template <int dim>
  void MeshFactory<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Type",
                      "block",
                      Patterns::Selection("block|Cook's membrane|ball|file"),
                      "Generated block, Cook's membrane or ball, or a mesh "
                      "file (Gmsh .msh or Abaqus .inp).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 10),
                      "Uniform refinements of the coarse mesh. Unit: 1.");
    prm.declare_entry("Material id",
                      "0",
                      Patterns::Integer(0, 254),
                      "Material id of generated meshes (files carry their "
                      "own). Unit: 1.");
    prm.declare_entry("Distortion",
                      "0",
                      Patterns::Double(0, 0.4),
                      "Move every interior vertex of the coarse mesh by a "
                      "random vector of up to this fraction of the adjacent "
                      "edge length (deterministic seed); for patch tests of "
                      "distorted elements. Unit: 1.");
    prm.enter_subsection("Block");
    prm.declare_entry("Lower corner",
                      per_direction<dim>("0"),
                      Patterns::Anything(),
                      "Corner with the smallest coordinates. Unit: m.");
    prm.declare_entry("Upper corner",
                      per_direction<dim>("0.01"),
                      Patterns::Anything(),
                      "Corner with the largest coordinates. Unit: m.");
    prm.declare_entry("Subdivisions",
                      per_direction<dim>("2"),
                      Patterns::List(Patterns::Integer(1)),
                      "Elements per direction before refinement. Unit: 1.");
    prm.declare_entry("Grading",
                      per_direction<dim>("1"),
                      Patterns::List(Patterns::Double(0)),
                      "Per direction, the size ratio of neighbouring "
                      "elements from the lower to the upper corner: 1 is "
                      "uniform, > 1 grows towards the upper corner, < 1 "
                      "refines towards it (e.g. near a contact). Unit: 1.");
    prm.leave_subsection();
    prm.enter_subsection("Cook's membrane");
    prm.declare_entry("Elements per edge",
                      "8",
                      Patterns::Integer(1),
                      "Elements along each edge of the membrane. Unit: 1.");
    prm.declare_entry("Thickness",
                      "0.001",
                      Patterns::Double(0),
                      "Out-of-plane thickness (3D only). Unit: m.");
    prm.declare_entry("Layers",
                      "1",
                      Patterns::Integer(1),
                      "Elements through the thickness (3D only). Unit: 1.");
    prm.leave_subsection();
    prm.enter_subsection("Ball");
    prm.declare_entry("Center",
                      per_direction<dim>("0"),
                      Patterns::Anything(),
                      "Centre of the ball. Unit: m.");
    prm.declare_entry(
        "Radius", "0.04", Patterns::Double(0), "Radius of the ball. Unit: m.");
    prm.declare_entry("Core radius",
                      "0",
                      Patterns::Double(0),
                      "Radius of a rigid core that holds the ball (a shell "
                      "mesh whose inner surface has boundary id 1, to be "
                      "fixed by a Dirichlet condition); 0: a solid ball. "
                      "Unit: m.");
    prm.declare_entry("Shell cells",
                      "6",
                      Patterns::Selection("6|12|24|48|96"),
                      "Coarse cells of the shell around a core (3D: 6, 12, "
                      "24, 48 or 96; 2D: any). Unit: 1.");
    prm.leave_subsection();
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
    prm.leave_subsection();
  }

  template <int dim>
  void MeshFactory<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    const std::string name = prm.get("Type");
    for (const auto &entry : type_names)
      if (entry.first == name)
        type = static_cast<Type>(entry.second);
    global_refinements = prm.get_integer("Global refinements");
    distortion         = prm.get_double("Distortion");
    material_id =
        static_cast<types::material_id>(prm.get_integer("Material id"));
    prm.enter_subsection("Block");
    lower =
        parse_point<dim>(prm.get("Lower corner"), "Mesh/Block/Lower corner");
    upper =
        parse_point<dim>(prm.get("Upper corner"), "Mesh/Block/Upper corner");
    std::vector<unsigned int> n;
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Subdivisions")))
      n.push_back(Utilities::string_to_int(s));
    subdivisions = per_direction_list<dim>(n, "Mesh/Block/Subdivisions");
    std::vector<double> ratios;
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Grading")))
      ratios.push_back(Utilities::string_to_double(s));
    grading = per_direction_list<dim>(ratios, "Mesh/Block/Grading");
    for (const double g : grading)
      if (!(g > 0))
        throw InputError("Parameter 'Mesh/Block/Grading' must be positive. "
                         "Fix: give size ratios > 0 (1 is uniform).");
    for (unsigned int d = 0; d < dim; ++d)
      if (!(upper[d] > lower[d]) && type == Type::block)
        throw InputError("Parameter 'Mesh/Block/Upper corner' must exceed "
                         "'Lower corner' in every coordinate. Fix: swap or "
                         "correct the corners (m).");
    prm.leave_subsection();
    prm.enter_subsection("Cook's membrane");
    elements_per_edge = prm.get_integer("Elements per edge");
    thickness         = prm.get_double("Thickness");
    layers            = prm.get_integer("Layers");
    prm.leave_subsection();
    prm.enter_subsection("Ball");
    center      = parse_point<dim>(prm.get("Center"), "Mesh/Ball/Center");
    radius      = prm.get_double("Radius");
    core_radius = prm.get_double("Core radius");
    shell_cells = prm.get_integer("Shell cells");
    if (core_radius >= radius)
      throw InputError("'Mesh/Ball/Core radius' (" +
                       std::to_string(core_radius) +
                       " m) is not smaller than 'Mesh/Ball/Radius' (" +
                       std::to_string(radius) +
                       " m). Fix: give a core radius below the radius, or 0 "
                       "for a solid ball.");
    prm.leave_subsection();
    prm.enter_subsection("File");
    file_name = Utilities::trim(prm.get("File name"));
    scale     = prm.get_double("Scale");
    if (!(scale > 0))
      throw InputError("Parameter 'Mesh/File/Scale' is " +
                       std::to_string(scale) +
                       "; it must be positive. Fix: give the factor from the "
                       "file's length unit to metres (1 for metres, 1e-3 for "
                       "millimetres).");
    if (type == Type::file && file_name.empty())
      throw InputError("Parameter 'Mesh/File name' is empty but 'Mesh/Type' "
                       "is 'file'. Fix: name a .msh or .inp file.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  MeshFactory<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    switch (type)
    {
    case Type::block:
    {
      std::vector<std::vector<double>> steps(dim);
      for (unsigned int d = 0; d < dim; ++d)
      {
        double total = 0;
        for (unsigned int i = 0; i < subdivisions[d]; ++i)
          total += std::pow(grading[d], i);
        for (unsigned int i = 0; i < subdivisions[d]; ++i)
          steps[d].push_back((upper[d] - lower[d]) * std::pow(grading[d], i) /
                             total);
      }
      GridGenerator::subdivided_hyper_rectangle(
          triangulation, steps, lower, upper, true);
      break;
    }
    case Type::cook_membrane:
      Meshes::cook_membrane(
          triangulation, elements_per_edge, thickness, layers);
      break;
    case Type::ball:
      if (core_radius > 0)
      {
        // hyper_shell: 0 inner, 1 outer; softgrasp: 0 outer, 1 core.
        GridGenerator::hyper_shell(
            triangulation, center, core_radius, radius, shell_cells, true);
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              face->set_boundary_id(face->boundary_id() == 0 ? 1 : 0);
      }
      else
        GridGenerator::hyper_ball_balanced(triangulation, center, radius);
      break;
    case Type::file:
      Meshes::read_mesh_file(triangulation, file_name, scale);
      break;
    }
    if (type != Type::file) // files carry their own material ids
      for (const auto &cell : triangulation.active_cell_iterators())
        cell->set_material_id(material_id);
    if (distortion > 0)
      GridTools::distort_random(distortion, triangulation, true);
  }

  template <int dim>
  void MeshFactory<dim>::refine(Triangulation<dim> &triangulation) const
  {
    if (global_refinements > 0)
      triangulation.refine_global(global_refinements);
  }

  template <int dim> bool MeshFactory<dim>::has_curved_boundary() const
  {
    return type == Type::ball;
  }

  template class MeshFactory<2>;
  template class MeshFactory<3>;
} // namespace softgrasp
