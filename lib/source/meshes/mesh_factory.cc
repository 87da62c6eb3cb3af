#include <deal.II/grid/grid_tools.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/meshes/mesh_factory.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void MeshFactory<dim>::declare_parameters(ParameterHandler &prm)
  {
    std::string descriptions;
    for (const auto &[name, entry] : MeshRegistry<dim>::all())
      descriptions += "; '" + name + "': " + entry.description;
    prm.enter_subsection("Mesh");
    prm.declare_entry(
        "Type",
        "block",
        Patterns::Selection(MeshRegistry<dim>::names_separated_by("|")),
        "The kind of mesh, with its entries in the subsection "
        "of that name" +
            descriptions + ".");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 10),
                      "Uniform refinements of the coarse mesh. Unit: 1.");
    prm.declare_entry("Material id",
                      "0",
                      Patterns::Integer(0, 254),
                      "Material id of meshes of one material (files and "
                      "layered meshes carry their own). Unit: 1.");
    prm.declare_entry("Distortion",
                      "0",
                      Patterns::Double(0, 0.4),
                      "Move every interior vertex of the coarse mesh by a "
                      "random vector of up to this fraction of the adjacent "
                      "edge length (deterministic seed); for patch tests of "
                      "distorted elements. Unit: 1.");
    for (const auto &[name, entry] : MeshRegistry<dim>::all())
      entry.declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void MeshFactory<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    type_name          = prm.get("Type");
    global_refinements = prm.get_integer("Global refinements");
    distortion         = prm.get_double("Distortion");
    material_id =
        static_cast<types::material_id>(prm.get_integer("Material id"));
    std::shared_ptr<MeshGenerator<dim>> created =
        MeshRegistry<dim>::create(type_name, "mesh type ('Mesh/Type')");
    created->parse_parameters(prm);
    mesh = created;
    refuse_entries_of_other_types(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void MeshFactory<dim>::refuse_entries_of_other_types(ParameterHandler &prm)
  {
    for (const auto &[name, entry] : MeshRegistry<dim>::all())
    {
      if (name == type_name)
        continue;
      const auto changed =
          entries_changed_from_default(prm, entry.declare_parameters);
      if (changed.empty())
        continue;
      std::string list;
      for (const auto &path : changed)
        list += (list.empty() ? "'Mesh/" : ", 'Mesh/") + path + "'";
      throw InputError(
          "'Mesh/Type' is '" + type_name + "', but " + list +
          (changed.size() == 1 ? " belongs" : " belong") + " to mesh type '" +
          name +
          "' and would be ignored (only the entries of 'Mesh/Type' are "
          "read). Fix: set 'Mesh/Type = " +
          name + "' to use " + (changed.size() == 1 ? "it" : "them") +
          ", or delete " + (changed.size() == 1 ? "it" : "them") +
          " (or put '#' before the line).");
    }
  }

  template <int dim>
  void MeshFactory<dim>::set_generator(
      std::shared_ptr<const MeshGenerator<dim>> generator,
      const std::string                        &name)
  {
    mesh      = std::move(generator);
    type_name = name;
  }

  template <int dim>
  const MeshGenerator<dim> &MeshFactory<dim>::generator() const
  {
    if (!mesh)
      throw std::logic_error("MeshFactory used before parse_parameters()");
    return *mesh;
  }

  template <int dim>
  void
  MeshFactory<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    generator().create_coarse_mesh(triangulation);
    if (!placement.is_identity())
      GridTools::transform([this](const Point<dim> &x) { return placement(x); },
                           triangulation);
    generator().attach_manifolds(triangulation, placement);
    if (!generator().sets_material_ids())
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
    return generator().is_curved();
  }

  template class MeshFactory<2>;
  template class MeshFactory<3>;
} // namespace softgrasp
