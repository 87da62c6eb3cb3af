// Uniaxial and equibiaxial stress against the closed forms of incompressible
// hyperelasticity for neo-Hookean, Mooney-Rivlin, Ogden, Yeoh and
// Veronda-Westmann:
//  (a) exactly, at isochoric F (J = 1), where the deviatoric stress
//      difference sigma_11 - sigma_22 (uniaxial) or sigma_11 - sigma_33
//      (equibiaxial) of the decoupled model equals the incompressible one;
//  (b) as a full homogeneous-loading solve (lateral stresses zero, Newton
//      with the consistent tangent) with kappa = 1e6 mu_0, where the nominal
//      stress approaches the incompressible closed form to O(mu/kappa).

#include "../material_factory.h"
#include "../tests.h"

#include <functional>
#include <softgrasp/materials/homogeneous_loading.h>

using namespace dealii;
using namespace softgrasp;

struct Case
{
  std::string                   name;
  std::string                   fragment;
  std::function<double(double)> uniaxial;    // incompressible sigma_11
  std::function<double(double)> equibiaxial; // incompressible sigma_11
};

int
main()
{
  softgrasp_tests::initlog();
  const std::string vol = "set Density = 1000\nsubsection Volumetric\nset "
                          "Bulk modulus = BULK\nend\n";
  const double      mu = 1e4, c10 = 4e3, c01 = 1e3;
  const std::vector<double> mu_p = {6.3e3, 0.012e3, -0.1e3},
                            a_p  = {1.3, 5.0, -2.0};
  const std::vector<double> yeoh = {5e3, -1e2, 20};
  const double              vw1 = 2e3, vw2 = 5;

  auto yeoh_sum = [&](const double I1)
  {
    double s = 0;
    for (unsigned int i = 1; i <= 3; ++i)
      s += i * yeoh[i - 1] * std::pow(I1 - 3.0, i - 1.0);
    return s;
  };

  const std::vector<Case> cases = {
      {"neo-Hookean",
       "set Model = neo-Hookean\n" + vol +
           "subsection neo-Hookean\nset Shear modulus = 1e4\nend",
       [&](double l) { return mu * (l * l - 1 / l); },
       [&](double l) { return mu * (l * l - std::pow(l, -4)); }},
      {"Mooney-Rivlin",
       "set Model = Mooney-Rivlin\n" + vol +
           "subsection Mooney-Rivlin\nset C10 = 4e3\nset C01 = 1e3\nend",
       [&](double l) { return 2 * (c10 + c01 / l) * (l * l - 1 / l); },
       [&](double l)
       { return 2 * (c10 + c01 * l * l) * (l * l - std::pow(l, -4)); }},
      {"Ogden",
       "set Model = Ogden\n" + vol +
           "subsection Ogden\nset Moduli = 6.3e3, 0.012e3, -0.1e3\nset "
           "Exponents "
           "= 1.3, 5.0, -2.0\nend",
       [&](double l)
       {
         double s = 0;
         for (unsigned int p = 0; p < 3; ++p)
           s += mu_p[p] * (std::pow(l, a_p[p]) - std::pow(l, -a_p[p] / 2));
         return s;
       },
       [&](double l)
       {
         double s = 0;
         for (unsigned int p = 0; p < 3; ++p)
           s += mu_p[p] * (std::pow(l, a_p[p]) - std::pow(l, -2 * a_p[p]));
         return s;
       }},
      {"Yeoh",
       "set Model = Yeoh\n" + vol +
           "subsection Yeoh\nset Coefficients = 5e3, -1e2, 20\nend",
       [&](double l) { return 2 * (l * l - 1 / l) * yeoh_sum(l * l + 2 / l); },
       [&](double l)
       {
         return 2 * (l * l - std::pow(l, -4)) *
                yeoh_sum(2 * l * l + std::pow(l, -4));
       }},
      {"Veronda-Westmann",
       "set Model = Veronda-Westmann\n" + vol +
           "subsection Veronda-Westmann\nset C1 = 2e3\nset C2 = 5\nend",
       [&](double l)
       {
         const double W1 = vw1 * vw2 * std::exp(vw2 * (l * l + 2 / l - 3));
         return 2 * (l * l - 1 / l) * (W1 - 0.5 * vw1 * vw2 / l);
       },
       [&](double l)
       {
         const double W1 =
             vw1 * vw2 * std::exp(vw2 * (2 * l * l + std::pow(l, -4) - 3));
         return 2 * (l * l - std::pow(l, -4)) * (W1 - 0.5 * vw1 * vw2 * l * l);
       }}};

  const StructuralDirections none;
  for (const Case &c : cases)
  {
    std::string fragment = c.fragment;
    fragment.replace(fragment.find("BULK"), 4, "1e10");
    const auto material = softgrasp_tests::material_from_prm(fragment);
    deallog << c.name << " (mu_0 = " << material->initial_shear_modulus()
            << " Pa)" << std::endl;
    for (const double l : {0.7, 0.9, 1.1, 1.5, 2.0})
    {
      // (a) exact at J = 1
      Tensor<2, 3> Fu, Fb;
      Fu[0][0] = l;
      Fu[1][1] = Fu[2][2] = 1 / std::sqrt(l);
      Fb[0][0] = Fb[1][1] = l;
      Fb[2][2]            = 1 / (l * l);
      const auto su       = material->cauchy_stress(Fu, none);
      const auto sb       = material->cauchy_stress(Fb, none);
      SG_CHECK_CLOSE(su[0][0] - su[1][1],
                     c.uniaxial(l),
                     1e-10,
                     1e-10 * mu,
                     c.name + ": uniaxial stress difference at J = 1");
      SG_CHECK_CLOSE(sb[0][0] - sb[2][2],
                     c.equibiaxial(l),
                     1e-10,
                     1e-10 * mu,
                     c.name + ": equibiaxial stress difference at J = 1");

      // (b) full solve, nearly incompressible: the compressible answer
      // differs from the incompressible one by O(sigma/kappa), so only
      // compare where the stresses stay below 1e-5 kappa.
      if (std::max(std::abs(c.uniaxial(l)), std::abs(c.equibiaxial(l))) >
          1e-5 * 1e10)
      {
        deallog << "  stretch " << l
                << ": stresses exceed 1e-5 kappa, (b) not applicable"
                << std::endl;
        continue;
      }
      const auto u = HomogeneousLoading::uniaxial(*material, none, l);
      const auto b = HomogeneousLoading::equibiaxial(*material, none, l);
      SG_CHECK_CLOSE(u.nominal_stress,
                     c.uniaxial(l) / l,
                     1e-4,
                     1e-6 * mu,
                     c.name + ": uniaxial nominal stress");
      SG_CHECK_CLOSE(b.nominal_stress,
                     c.equibiaxial(l) / l,
                     1e-4,
                     1e-6 * mu,
                     c.name + ": equibiaxial nominal stress");
      SG_CHECK_CLOSE(u.stretches[1],
                     1 / std::sqrt(l),
                     1e-4,
                     0,
                     c.name + ": uniaxial lateral stretch");
      deallog << "  stretch " << l << ": uniaxial P = " << u.nominal_stress
              << " Pa (closed form " << c.uniaxial(l) / l
              << "), equibiaxial P = " << b.nominal_stress
              << " Pa (closed form " << c.equibiaxial(l) / l << ")"
              << std::endl;
    }
  }
  deallog << "OK" << std::endl;
}
