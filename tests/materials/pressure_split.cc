// The displacement block of the mixed u-p-J formulation:
// Material::evaluate_material_with_pressure(F, p) returns S_iso + p J C^-1
// with the tangent at fixed p. Checks, for every model, at random F:
//  1. with p = U'(J) the stress equals evaluate_material()'s (1e-12);
//  2. the tangent equals central finite differences of S(C) at fixed p
//     (1e-6), and with p = U'(J) it differs from the full tangent by exactly
//     the U'' term J^2 U''(J) C^-1 (x) C^-1 (1e-10);
//  3. the spatial variant is the push-forward of the material one (1e-12).
#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/physics/transformations.h>
#include <random>

using namespace dealii;
using namespace softgrasp;
using softgrasp_tests::stretch_from_C;

int
main()
{
  softgrasp_tests::initlog();
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> uniform(-0.2, 0.2);
  for (const auto &[label, fragment] : softgrasp_tests::model_fragments())
  {
    const auto  material = softgrasp_tests::material_from_prm(fragment);
    const auto  d        = material->structural_directions(Point<3>());
    const auto &U        = material->volumetric_energy();
    double      e1 = 0, e2 = 0, e3 = 0, e4 = 0;
    for (unsigned int sample = 0; sample < 4; ++sample)
    {
      Tensor<2, 3> F = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          F[i][j] += uniform(rng);
      const double                J    = determinant(F);
      const SymmetricTensor<2, 3> C    = symmetrize(transpose(F) * F);
      const SymmetricTensor<2, 3> Cinv = invert(C);
      const double                p    = U.first_derivative(J);

      Material::Response full, split;
      material->evaluate_material(F, d, true, full);
      material->evaluate_material_with_pressure(F, d, p, true, split);
      e1 = std::max(e1,
                    (full.stress - split.stress).norm() / full.stress.norm());
      const SymmetricTensor<4, 3> u2 =
          J * J * U.second_derivative(J) * outer_product(Cinv, Cinv);
      e2 = std::max(
          e2, (full.tangent - split.tangent - u2).norm() / full.tangent.norm());

      // finite differences of S(C) at fixed p
      const double          h = 1e-6 * C.norm();
      SymmetricTensor<4, 3> fd;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = k; l < 3; ++l)
        {
          SymmetricTensor<2, 3> dC;
          dC[k][l] = h;
          Material::Response plus, minus;
          material->evaluate_material_with_pressure(
              stretch_from_C(C + dC), d, p, false, plus);
          material->evaluate_material_with_pressure(
              stretch_from_C(C - dC), d, p, false, minus);
          const double                factor = (k == l) ? 1.0 : 0.5;
          const SymmetricTensor<2, 3> dS =
              (plus.stress - minus.stress) / (2 * h);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              fd[i][j][k][l] = 2.0 * factor * dS[i][j];
        }
      e3 = std::max(e3, (fd - split.tangent).norm() / split.tangent.norm());

      Material::Response spatial;
      material->evaluate_spatial_with_pressure(F, d, p, true, spatial);
      const auto tau = Physics::Transformations::Contravariant::push_forward(
          split.stress, F);
      const auto Jc = Physics::Transformations::Contravariant::push_forward(
          split.tangent, F);
      e4 = std::max(e4,
                    (tau - spatial.stress).norm() / tau.norm() +
                        (Jc - spatial.tangent).norm() / Jc.norm());
    }
    SG_CHECK(e1 < 1e-12, label + ": stress with p = U'(J)");
    SG_CHECK(e2 < 1e-10, label + ": tangent differs by the U'' term only");
    SG_CHECK(e3 < 1e-6, label + ": tangent at fixed p vs finite differences");
    SG_CHECK(e4 < 1e-12, label + ": spatial = push-forward");
    deallog << label << ": pressure split consistent" << std::endl;
  }
}
