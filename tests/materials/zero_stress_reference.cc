// Every model (with every volumetric energy) and every tissue preset at
// F = I: zero energy, zero stress, and a tangent equal to the isotropic
// small-strain elasticity tensor lambda I(x)I + 2 mu_0 II with
// lambda = kappa - 2/3 mu_0 (fibres carry no load at the reference state).
// The wave speed computed from the tangent equals sqrt((kappa+4/3 mu)/rho).

#include "../material_factory.h"
#include "../tests.h"

#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>
#include <softgrasp/materials/volumetric_energy.h>

using namespace dealii;
using namespace softgrasp;

void
check(const Material &material, const std::string &label)
{
  const Tensor<2, 3>         F = unit_symmetric_tensor<3>();
  const StructuralDirections d =
      material.structural_directions(Point<3>(0.01, 0.02, 0.03));
  Material::Response r;
  material.evaluate_material(F, d, true, r);

  const double                mu     = material.initial_shear_modulus();
  const double                kappa  = material.bulk_modulus();
  const double                lambda = kappa - 2.0 / 3.0 * mu;
  const SymmetricTensor<4, 3> expected =
      lambda * outer_product(unit_symmetric_tensor<3>(),
                             unit_symmetric_tensor<3>()) +
      2.0 * mu * identity_tensor<3>();

  const double scale = mu + kappa;
  SG_CHECK(std::abs(r.energy) <= 1e-12 * scale, label + ": energy at F = I");
  SG_CHECK(r.stress.norm() <= 1e-12 * scale, label + ": stress at F = I");
  SG_CHECK((r.tangent - expected).norm() <= 1e-10 * expected.norm(),
           label + ": tangent at F = I differs from linear elasticity");
  SG_CHECK_CLOSE(material.dilatational_wave_speed(F, d),
                 material.reference_wave_speed(),
                 1e-10,
                 0,
                 label + ": wave speed at F = I");
  deallog << label << ": |S| = " << r.stress.norm() / scale << ", mu_0 = " << mu
          << " Pa, kappa = " << kappa
          << " Pa, c_d = " << material.reference_wave_speed() << " m/s"
          << std::endl;
}

int
main()
{
  softgrasp_tests::initlog();
  for (const std::string volumetric :
       {"quadratic", "logarithmic", "Simo-Taylor"})
    for (const auto &[label, fragment] :
         softgrasp_tests::model_fragments(volumetric))
      check(*softgrasp_tests::material_from_prm(fragment),
            label + " / " + volumetric);
  for (const auto &preset : TissuePresets::all())
    check(*MaterialLibrary::create_preset(preset.name),
          "preset " + preset.name);
  deallog << "OK" << std::endl;
}
