// Material frame indifference: for a rotation Q, the second Piola-Kirchhoff
// stress, material tangent and energy are unchanged under F -> QF, and the
// Kirchhoff stress rotates, tau(QF) = Q tau(F) Q^T, for every model.

#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/physics/transformations.h>

using namespace dealii;
using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog();
  const Tensor<2, 3> Q =
      Physics::Transformations::Rotations::rotation_matrix_3d(
          Tensor<1, 3>({2., -1., 2.}) / 3.0, 1.1);
  Tensor<2, 3> F;
  F[0][0] = 1.3;
  F[0][1] = 0.2;
  F[1][1] = 0.9;
  F[1][2] = -0.15;
  F[2][0] = 0.1;
  F[2][2] = 1.05;

  for (const auto &[label, fragment] : softgrasp_tests::model_fragments())
  {
    const auto         material = softgrasp_tests::material_from_prm(fragment);
    const auto         d        = material->structural_directions(Point<3>());
    Material::Response m, mq, s, sq;
    material->evaluate_material(F, d, true, m);
    material->evaluate_material(Q * F, d, true, mq);
    material->evaluate_spatial(F, d, false, s);
    material->evaluate_spatial(Q * F, d, false, sq);
    const SymmetricTensor<2, 3> rotated =
        symmetrize(Q * Tensor<2, 3>(s.stress) * transpose(Q));
    SG_CHECK((mq.stress - m.stress).norm() <= 1e-12 * m.stress.norm(),
             label + ": S(QF) = S(F)");
    SG_CHECK((mq.tangent - m.tangent).norm() <= 1e-12 * m.tangent.norm(),
             label + ": CC(QF) = CC(F)");
    SG_CHECK_CLOSE(mq.energy, m.energy, 1e-12, 0, label + ": Psi(QF)");
    SG_CHECK((sq.stress - rotated).norm() <= 1e-12 * s.stress.norm(),
             label + ": tau(QF) = Q tau(F) Q^T");
    deallog << label << ": objective" << std::endl;
  }
  deallog << "OK" << std::endl;
}
