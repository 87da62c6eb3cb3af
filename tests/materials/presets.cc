// Every tissue preset builds through the parameter file, has the density
// and small-strain moduli documented in doc/materials.md, and user entries
// override preset entries.

#include "../tests.h"

#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>

using namespace dealii;
using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog();
  // name, rho_0 (kg/m^3), mu_0 (Pa) as tabulated in doc/materials.md
  const std::vector<std::tuple<std::string, double, double>> expected = {
      {"skin", 1109, 0.4e6},
      {"subcutaneous fat", 911, 530},
      {"skeletal muscle", 1090, 7466.67},
      {"fascia", 1142, 3.6667e6},
      {"ligament", 1142, 3.6667e6},
      {"natural rubber", 930, 422.5e3},
      {"cortical bone", 1908, 6.8846e9}};
  SG_CHECK(expected.size() == TissuePresets::all().size(),
           "every preset is checked");

  for (const auto &[name, rho, mu] : expected)
  {
    const auto material = MaterialLibrary::create_preset(name);
    SG_CHECK_CLOSE(material->density(), rho, 1e-12, 0, name + ": density");
    SG_CHECK_CLOSE(material->initial_shear_modulus(),
                   mu,
                   1e-6,
                   0,
                   name + ": shear modulus");
    const auto d = material->structural_directions(Point<3>());
    const auto u = HomogeneousLoading::uniaxial(*material, d, 1.1);
    SG_CHECK(u.nominal_stress > 0, name + ": tension gives positive stress");
    deallog << material->summary() << std::endl
            << "  uniaxial nominal stress at stretch 1.1: " << u.nominal_stress
            << " Pa" << std::endl;
  }

  // A user entry overrides the preset's value.
  ParameterHandler prm;
  MaterialLibrary::declare_parameters(prm);
  MaterialLibrary::parse_input_from_string(
      prm,
      "subsection Materials\nset Material ids = 1, 2\nsubsection Material "
      "1\nset "
      "Preset = skin\nset Density = 1200\nend\nsubsection Material 2\nset "
      "Preset = subcutaneous fat\nsubsection neo-Hookean\nset Shear modulus = "
      "1000\nend\nend\nend\n");
  MaterialLibrary library;
  library.parse_parameters(prm);
  SG_CHECK_CLOSE(library.get(1).density(), 1200, 1e-12, 0, "density override");
  SG_CHECK_CLOSE(library.get(1).initial_shear_modulus(),
                 0.4e6,
                 1e-6,
                 0,
                 "preset kept where not overridden");
  SG_CHECK_CLOSE(library.get(2).initial_shear_modulus(),
                 1000,
                 1e-12,
                 0,
                 "modulus override");
  deallog << "user entries override presets" << std::endl << "OK" << std::endl;
}
