// The consistent tangent CC = 2 dS/dC equals central finite differences of
// the stress S(C), and S = 2 dPsi/dC equals finite differences of the
// energy, to 1e-6 relative, at random non-trivial deformation gradients,
// for every model and volumetric energy; also for the Ogden model at
// coincident principal stretches (equibiaxial and near-identity states),
// where its spectral formula needs the limit of the divided differences.

#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/physics/transformations.h>
#include <random>
#include <softgrasp/materials/material_library.h>

using namespace dealii;
using namespace softgrasp;
using softgrasp_tests::stretch_from_C;

// Returns the relative errors of tangent and stress against differences.
std::pair<double, double>
errors(const Material             &material,
       const Tensor<2, 3>         &F,
       const StructuralDirections &d)
{
  const SymmetricTensor<2, 3> C = symmetrize(transpose(F) * F);
  Material::Response          r;
  material.evaluate_material(F, d, true, r);

  const double          h = 1e-6 * C.norm();
  SymmetricTensor<4, 3> fd_tangent;
  SymmetricTensor<2, 3> fd_stress;
  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int l = k; l < 3; ++l)
    {
      SymmetricTensor<2, 3> dC;
      dC[k][l] = h; // symmetric storage: perturbs C_kl and C_lk together
      Material::Response plus, minus;
      material.evaluate_material(stretch_from_C(C + dC), d, false, plus);
      material.evaluate_material(stretch_from_C(C - dC), d, false, minus);
      const double                factor = (k == l) ? 1.0 : 0.5;
      const SymmetricTensor<2, 3> dS = (plus.stress - minus.stress) / (2 * h);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          fd_tangent[i][j][k][l] = 2.0 * factor * dS[i][j];
      fd_stress[k][l] = 2.0 * factor * (plus.energy - minus.energy) / (2 * h);
    }
  return {(fd_tangent - r.tangent).norm() / r.tangent.norm(),
          (fd_stress - r.stress).norm() / r.stress.norm()};
}

int
main()
{
  softgrasp_tests::initlog();
  std::mt19937                           rng(20261123);
  std::uniform_real_distribution<double> uniform(-0.25, 0.25);

  for (const std::string volumetric :
       {"quadratic", "logarithmic", "Simo-Taylor"})
    for (const auto &[label, fragment] :
         softgrasp_tests::model_fragments(volumetric))
    {
      const auto material = softgrasp_tests::material_from_prm(fragment);
      const auto d = material->structural_directions(Point<3>(0.1, 0.2, 0.3));
      double     worst_tangent = 0, worst_stress = 0;
      for (unsigned int sample = 0; sample < 5; ++sample)
      {
        Tensor<2, 3> F = unit_symmetric_tensor<3>();
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            F[i][j] += uniform(rng);
        // stretch along the first fibre so fibre terms are active
        F += 0.3 * outer_product(d.n_directions > 0 ? d.direction[0]
                                                    : Tensor<1, 3>({1, 0, 0}),
                                 d.n_directions > 0 ? d.direction[0]
                                                    : Tensor<1, 3>({1, 0, 0}));
        SG_CHECK(determinant(F) > 0.2, "random F must not be near-singular");
        const auto [e_tangent, e_stress] = errors(*material, F, d);
        worst_tangent                    = std::max(worst_tangent, e_tangent);
        worst_stress                     = std::max(worst_stress, e_stress);
      }
      SG_CHECK(worst_tangent < 1e-6,
               label + "/" + volumetric + ": tangent vs finite differences: " +
                   std::to_string(worst_tangent));
      SG_CHECK(worst_stress < 1e-6,
               label + "/" + volumetric + ": stress vs finite differences: " +
                   std::to_string(worst_stress));
      deallog << label << " / " << volumetric
              << ": tangent and stress agree with finite differences to 1e-6"
              << std::endl;
    }

  // Ogden at coincident principal stretches.
  const auto ogden = softgrasp_tests::material_from_prm(
      softgrasp_tests::model_fragments()[2].second);
  const StructuralDirections none;
  const Tensor<2, 3>         rotation =
      Physics::Transformations::Rotations::rotation_matrix_3d(
          Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.), 0.7);
  for (const double l : {1.0 + 1e-9, 1.2})
  {
    Tensor<2, 3> U;
    U[0][0] = U[1][1]    = l;
    U[2][2]              = 1.0 / (l * l);
    const Tensor<2, 3> F = rotation * U;
    Material::Response r;
    ogden->evaluate_material(F, none, true, r);
    SG_CHECK(r.tangent.norm() > 0 && std::isfinite(r.tangent.norm()),
             "Ogden tangent finite at coincident stretches");
    const auto [e_tangent, e_stress] = errors(*ogden, F, none);
    SG_CHECK(e_tangent < 1e-6, "Ogden tangent at coincident stretches");
    (void)e_stress;
    deallog << "Ogden, two equal stretches l = " << l
            << ": tangent agrees with finite differences to 1e-6" << std::endl;
  }
  deallog << "OK" << std::endl;
}
