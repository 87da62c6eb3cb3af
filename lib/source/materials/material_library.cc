#include <deal.II/base/utilities.h>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/scoped_subsection.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    std::vector<types::material_id> parse_ids(const std::string &text)
    {
      std::vector<types::material_id> ids;
      for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const int id = Utilities::string_to_int(item);
        ids.push_back(static_cast<types::material_id>(id));
      }
      return ids;
    }

    std::string subsection_name(const types::material_id id)
    {
      return "Material " + std::to_string(static_cast<unsigned int>(id));
    }
  } // namespace

  void MaterialLibrary::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry("Material ids",
                      "0",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Comma-separated material ids of the mesh that carry a "
                      "material; each id then has a subsection 'Material "
                      "<id>'.");
    prm.leave_subsection();
  }

  void MaterialLibrary::declare_material_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "A label for output tables; defaults to the preset or "
                      "model name.");
    prm.declare_entry("Preset",
                      "none",
                      Patterns::Selection(TissuePresets::selection()),
                      "A tissue preset (model, parameters and density from "
                      "the literature, see doc/materials.md); entries set "
                      "in this subsection override the preset's.");
    prm.declare_entry("Model",
                      "",
                      Patterns::Anything(),
                      "Isochoric strain-energy model, one of: " +
                          IsochoricModelRegistry::names_separated_by(", ") +
                          ".");
    CheckedSection::declare_number(prm,
                                   "Density",
                                   "Reference mass density rho_0. Unit: "
                                   "kg/m^3. Range: (0, inf).");
    prm.enter_subsection("Volumetric");
    prm.declare_entry("Energy",
                      "Simo-Taylor",
                      Patterns::Selection(VolumetricEnergy::names()),
                      "Volumetric energy U(J): quadratic kappa/2 (J-1)^2, "
                      "logarithmic kappa/2 (ln J)^2, Simo-Taylor kappa/4 "
                      "(J^2 - 1 - 2 ln J).");
    CheckedSection::declare_number(prm,
                                   "Bulk modulus",
                                   "Bulk modulus kappa. Unit: Pa. Range: (0, "
                                   "inf). Give this or Poisson's ratio.");
    CheckedSection::declare_number(
        prm,
        "Poisson's ratio",
        "Small-strain Poisson's ratio nu, giving kappa = 2 mu_0 (1 + nu) / (3 "
        "(1 "
        "- 2 nu)). Unit: 1. Range: (-1, 0.5). Give this or Bulk modulus.");
    prm.leave_subsection();
    for (const auto &[name, entry] : IsochoricModelRegistry::all())
    {
      prm.enter_subsection(name);
      entry.declare_parameters(prm);
      prm.leave_subsection();
    }
  }

  void MaterialLibrary::parse_input(ParameterHandler  &prm,
                                    const std::string &filename)
  {
    ParameterReader reader;
    add_passes(reader);
    reader.read_file(prm, filename);
  }

  void MaterialLibrary::parse_input_from_string(ParameterHandler  &prm,
                                                const std::string &text,
                                                const std::string &source)
  {
    ParameterReader reader;
    add_passes(reader);
    reader.read_string(prm, text, source);
  }

  void MaterialLibrary::add_passes(ParameterReader &reader)
  {
    // Pass 1: the ids are known; declare one subsection per id.
    reader.add_pass(
        [](ParameterHandler &prm)
        {
          prm.enter_subsection("Materials");
          for (const auto id : parse_ids(prm.get("Material ids")))
          {
            prm.enter_subsection(subsection_name(id));
            declare_material_parameters(prm);
            prm.leave_subsection();
          }
          prm.leave_subsection();
        });
    // Pass 2: apply presets; the final strict parse puts the user's entries
    // on top of them.
    reader.add_pass(
        [](ParameterHandler &prm)
        {
          prm.enter_subsection("Materials");
          const auto ids = parse_ids(prm.get("Material ids"));
          prm.leave_subsection();
          for (const auto id : ids)
          {
            prm.enter_subsection("Materials");
            prm.enter_subsection(subsection_name(id));
            const std::string preset = prm.get("Preset");
            prm.leave_subsection();
            prm.leave_subsection();
            if (preset != "none")
              prm.parse_input_from_string(
                  "subsection Materials\nsubsection " + subsection_name(id) +
                  "\n" + TissuePresets::get(preset).parameters + "end\nend\n");
          }
        });
  }

  std::shared_ptr<const Material>
  MaterialLibrary::create_material(ParameterHandler  &prm,
                                   const std::string &path,
                                   const std::string &default_name)
  {
    const CheckedSection section(prm, path);
    const std::string    model_name = Utilities::trim(prm.get("Model"));
    if (model_name.empty())
      throw InputError("Parameter '" + section.path_of("Model") +
                       "' is not set. Fix: set it to one of: " +
                       IsochoricModelRegistry::names_separated_by(", ") +
                       ", or select a Preset (" + TissuePresets::selection() +
                       ").");
    std::unique_ptr<IsochoricModel> model = IsochoricModelRegistry::create(
        model_name, "material model in '" + section.path_of("Model") + "'");
    {
      const ScopedSubsection model_section(prm, model_name);
      model->parse_parameters(prm, path + "/" + model_name);
    }

    const double density = section.get_positive("Density", "kg/m^3");

    double      kappa = 0;
    std::string energy_name;
    {
      const ScopedSubsection volumetric_section(prm, "Volumetric");
      const CheckedSection   volumetric(prm, path + "/Volumetric");
      const bool             has_kappa = volumetric.is_set("Bulk modulus");
      const bool             has_nu    = volumetric.is_set("Poisson's ratio");
      if (has_kappa == has_nu)
        throw InputError(
            "Subsection '" + path +
            "/Volumetric' must set exactly one of 'Bulk "
            "modulus' (Pa) and 'Poisson's ratio' (1), but " +
            (has_kappa ? "both are set" : "neither is set") +
            ". Fix: set one and clear the other with 'set <name> =' (a "
            "preset may have set one).");
      if (has_kappa)
        kappa = volumetric.get_positive("Bulk modulus", "Pa");
      else
      {
        const double nu =
            volumetric.get_in_range("Poisson's ratio", -1.0, 0.5, false, "");
        if (nu <= -1.0)
          throw InputError("Parameter '" +
                           volumetric.path_of("Poisson's ratio") +
                           "' must lie in (-1, 0.5). Fix: choose a value in "
                           "that range.");
        kappa = 2.0 * model->initial_shear_modulus() * (1.0 + nu) /
                (3.0 * (1.0 - 2.0 * nu));
      }
      energy_name = prm.get("Energy");
    }
    const VolumetricEnergy energy(VolumetricEnergy::type_from_name(energy_name),
                                  kappa);

    std::string name = Utilities::trim(prm.get("Name"));
    if (name.empty())
      name = default_name;
    return std::make_shared<const Material>(
        name, std::move(model), energy, density);
  }

  std::shared_ptr<const Material>
  MaterialLibrary::create_preset(const std::string &preset_name)
  {
    return create_from_fragment(TissuePresets::get(preset_name).parameters,
                                preset_name);
  }

  std::shared_ptr<const Material>
  MaterialLibrary::create_from_fragment(const std::string &fragment,
                                        const std::string &name)
  {
    ParameterHandler prm;
    declare_material_parameters(prm);
    prm.parse_input_from_string(fragment);
    return create_material(prm, name, name);
  }

  void MaterialLibrary::print_parameters(ParameterHandler &prm,
                                         std::ostream     &out)
  {
    ParameterReader::declare_program_entry(prm);
    {
      const ScopedSubsection materials(prm, "Materials");
      const ScopedSubsection material(prm, "Material 0");
      declare_material_parameters(prm);
    }
    prm.print_parameters(out, ParameterHandler::PRM);
  }

  void MaterialLibrary::parse_parameters(ParameterHandler &prm)
  {
    materials.clear();
    prm.enter_subsection("Materials");
    const auto ids = parse_ids(prm.get("Material ids"));
    for (const auto id : ids)
    {
      prm.enter_subsection(subsection_name(id));
      const std::string preset = prm.get("Preset");
      const std::string model  = Utilities::trim(prm.get("Model"));
      try
      {
        materials[id] = create_material(prm,
                                        "Materials/" + subsection_name(id),
                                        preset != "none" ? preset : model);
      }
      catch (...)
      {
        prm.leave_subsection();
        prm.leave_subsection();
        throw;
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  const Material &MaterialLibrary::get(const types::material_id id) const
  {
    return *get_shared(id);
  }

  std::shared_ptr<const Material>
  MaterialLibrary::get_shared(const types::material_id id) const
  {
    const auto it = materials.find(id);
    if (it == materials.end())
    {
      std::string ids;
      for (const auto &[known, material] : materials)
        ids += (ids.empty() ? "" : ", ") +
               std::to_string(static_cast<unsigned int>(known));
      throw InputError("The mesh has material id " +
                       std::to_string(static_cast<unsigned int>(id)) +
                       ", but the parameter file configures materials only "
                       "for ids {" +
                       ids +
                       "}. Fix: add the id to 'Materials/Material ids' and "
                       "give it a 'Material <id>' subsection.");
    }
    return it->second;
  }

  std::vector<types::material_id> MaterialLibrary::material_ids() const
  {
    std::vector<types::material_id> ids;
    for (const auto &[id, material] : materials)
      ids.push_back(id);
    return ids;
  }

  std::vector<std::string> MaterialLibrary::implausible_constants() const
  {
    std::vector<std::string> lines;
    for (const auto &[id, material] : materials)
    {
      const double      mu  = material->initial_shear_modulus();
      const double      rho = material->density();
      const std::string who = "Material " +
                              std::to_string(static_cast<unsigned int>(id)) +
                              " (" + material->name() + ")";
      std::ostringstream line;
      if (!(mu >= 1 && mu <= 1e10))
        line << who << " has an initial shear modulus of " << mu
             << " Pa, far outside any tissue's (soft tissues about 100 Pa to "
                "10 MPa, cortical bone about 5 GPa): check its unit (Pa, not "
                "kPa or MPa).";
      else if (!(rho >= 100 && rho <= 1e4))
        line << who << " has a density of " << rho
             << " kg/m^3, far outside any tissue's (about 1000 to 2000 "
                "kg/m^3): check its unit (kg/m^3, not g/cm^3).";
      if (!line.str().empty())
        lines.push_back(line.str());
    }
    return lines;
  }

  void MaterialLibrary::set(const types::material_id        id,
                            std::shared_ptr<const Material> material)
  {
    materials[id] = std::move(material);
  }
} // namespace softgrasp
