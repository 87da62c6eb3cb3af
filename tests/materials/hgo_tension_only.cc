// Holzapfel-Gasser-Ogden fibres carry load only in tension: with the fibre
// family along x (kappa = 0), states that shorten the fibre give exactly
// the stress of the neo-Hookean matrix alone, while stretching the fibre
// adds the closed-form fibre stress
//   sigma_11 - sigma_22 = mu (l^2 - 1/l) + 2 k1 (l^2 - 1) exp(k2 (l^2-1)^2) l^2
// at isochoric uniaxial stretch l > 1.

#include "../material_factory.h"
#include "../tests.h"

using namespace dealii;
using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog();
  const double      mu = 1e4, k1 = 5e4, k2 = 2;
  const std::string vol = "set Density = 1000\nsubsection Volumetric\nset "
                          "Poisson's ratio = 0.45\nend\n";
  const auto        hgo = softgrasp_tests::material_from_prm(
      "set Model = Holzapfel-Gasser-Ogden\n" + vol +
      "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = 1e4\nset k1 = "
             "5e4\nset k2 = 2\nend");
  const auto matrix = softgrasp_tests::material_from_prm(
      "set Model = neo-Hookean\n" + vol +
      "subsection neo-Hookean\nset Shear modulus = 1e4\nend");
  const StructuralDirections fibres = hgo->structural_directions(Point<3>());
  const StructuralDirections none;
  SG_CHECK(fibres.n_directions == 1 &&
               std::abs(fibres.direction[0][0] - 1) < 1e-15,
           "default fibre direction is x");

  for (const double l : {0.6, 0.8, 0.95, 1.05, 1.2, 1.4})
  {
    // uniaxial isochoric stretch along the fibre, and a compressible
    // state that shortens (or lengthens) the fibre with J != 1
    Tensor<2, 3> F, G;
    F[0][0] = l;
    F[1][1] = F[2][2] = 1 / std::sqrt(l);
    G[0][0]           = l;
    G[1][1]           = 1.1;
    G[2][2]           = 0.95;
    const auto sF     = hgo->cauchy_stress(F, fibres);
    const auto sG     = hgo->cauchy_stress(G, fibres);
    const auto mF     = matrix->cauchy_stress(F, none);
    const auto mG     = matrix->cauchy_stress(G, none);
    if (l < 1)
    {
      SG_CHECK((sF - mF).norm() <= 1e-12 * mF.norm(),
               "compressed fibre adds no stress (uniaxial)");
      SG_CHECK((sG - mG).norm() <= 1e-12 * mG.norm(),
               "compressed fibre adds no stress (J != 1)");
    }
    else
    {
      const double closed =
          mu * (l * l - 1 / l) +
          2 * k1 * (l * l - 1) * std::exp(k2 * std::pow(l * l - 1, 2)) * l * l;
      SG_CHECK_CLOSE(sF[0][0] - sF[1][1],
                     closed,
                     1e-10,
                     0,
                     "stretched fibre: closed-form stress");
      SG_CHECK(sG[0][0] > mG[0][0], "stretched fibre stiffens");
    }
    deallog << "fibre stretch " << l
            << ": sigma_11 - sigma_22 = " << sF[0][0] - sF[1][1]
            << " Pa (matrix alone " << mF[0][0] - mF[1][1] << " Pa)"
            << std::endl;
  }
  deallog << "OK" << std::endl;
}
