// DruckerStability along uniaxial and equibiaxial stress:
//  - a neo-Hookean solid is stable from l = 0.3 to 3;
//  - a Yeoh solid with a negative C20 (C10 = 1 kPa, C20 = -40 Pa) is not:
//    in uniaxial tension its Kirchhoff stress tau = l P stops rising at
//    l* = 2.797 (the incompressible closed form P = 2 (l - l^-2)
//    (C10 + 2 C20 (I1 - 3)), I1 = l^2 + 2/l, solved here by bisection, not
//    by the library), so the check must fail in uniaxial tension no later
//    than the first grid stretch beyond l*, and be stable in tension
//    below l* - 0.2 where the closed form's d tau / d ln l is still above
//    0.25 mu_0; with C20 = 0 the same solid is stable;
//  - every tissue preset over the grasp's range, l = 0.5 to 2, printed.

#include "../tests.h"

#include <cmath>
#include <softgrasp/materials/drucker_stability.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  std::shared_ptr<const Material> yeoh(const double C20)
  {
    return MaterialLibrary::create_from_fragment(
        "set Model = Yeoh\nset Density = 1000\nsubsection Volumetric\n set "
        "Bulk modulus = 2e8\nend\nsubsection Yeoh\n set Coefficients = 1e3, " +
            std::to_string(C20) + "\nend\n",
        "Yeoh");
  }

  /// d(l P)/dl of the incompressible closed form in uniaxial stress.
  double closed_form_slope(const double l, const double C20)
  {
    const auto tau = [&](const double s)
    {
      const double I1 = s * s + 2 / s;
      return s * 2 * (s - 1 / (s * s)) * (1e3 + 2 * C20 * (I1 - 3));
    };
    const double h = 1e-6;
    return (tau(l + h) - tau(l - h)) / (2 * h);
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();

  const auto neo = MaterialLibrary::create_from_fragment(
      "set Model = neo-Hookean\nset Density = 1000\nsubsection Volumetric\n "
      "set Poisson's ratio = 0.45\nend\nsubsection neo-Hookean\n set Shear "
      "modulus = 1e3\nend\n",
      "neo-Hookean");
  const auto neo_check = DruckerStability::check(*neo, 0.3, 3.0);
  deallog << "neo-Hookean: " << neo_check.summary(0.3, 3.0) << std::endl;
  SG_CHECK(neo_check.stable, "a neo-Hookean solid is stable");

  // the closed form's loss of stability in uniaxial tension, by bisection
  const double C20 = -40;
  double       a = 1.5, b = 4;
  SG_CHECK(closed_form_slope(a, C20) > 0 && closed_form_slope(b, C20) < 0,
           "the closed form changes sign in [1.5, 4]");
  for (unsigned int k = 0; k < 60; ++k)
    (closed_form_slope(0.5 * (a + b), C20) > 0 ? a : b) = 0.5 * (a + b);
  const double l_star = 0.5 * (a + b);
  deallog << "Yeoh, C20 = -40 Pa: closed-form loss in uniaxial tension at l = "
          << std::setprecision(4) << l_star << std::endl;

  // uniaxial tension only, 0.05 apart
  const std::vector<HomogeneousTest> uniaxial = {HomogeneousTest::uniaxial};
  const auto                         unstable =
      DruckerStability::check(*yeoh(C20), 1.0, 3.5, 51, uniaxial);
  deallog << "  the check: " << unstable.summary(1.0, 3.5) << std::endl;
  SG_CHECK(!unstable.stable && unstable.stretch > 1 &&
               unstable.stretch <= l_star + 0.05 + 1e-12,
           "unstable no later than the closed form's stretch");
  const auto below =
      DruckerStability::check(*yeoh(C20), 1.0, l_star - 0.2, 41, uniaxial);
  deallog << "  below l* - 0.2: " << (below.stable ? "stable" : "unstable")
          << std::endl;
  SG_CHECK(below.stable && closed_form_slope(l_star - 0.2, C20) > 500,
           "stable where the closed form is clearly stable");
  const auto positive = DruckerStability::check(*yeoh(0), 1.0, 3.5, 51);
  // both paths: equibiaxial tension raises I1 faster and fails first
  deallog << "  both paths: "
          << DruckerStability::check(*yeoh(C20), 1.0, 3.5, 51).summary(1.0, 3.5)
          << std::endl;
  deallog << "Yeoh, C20 = 0: " << (positive.stable ? "stable" : "unstable")
          << std::endl;
  SG_CHECK(positive.stable, "C20 = 0 is stable");

  for (const auto &preset : TissuePresets::all())
  {
    const auto check = DruckerStability::check(
        *MaterialLibrary::create_preset(preset.name), 0.5, 2.0, 31);
    deallog << preset.name << ": " << (check.stable ? "stable" : "unstable")
            << " from l = 0.5 to 2" << std::endl;
  }
}
