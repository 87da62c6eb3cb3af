// Principal strains of F = R Q diag(l1, l2, l3) Q^T (a rotation times a
// stretch with principal axes Q): e_i = l_i - 1 sorted descending, the
// principal directions are the columns of Q (up to sign), J = l1 l2 l3, and
// a pure rotation gives zero strain.

#include "../tests.h"

#include <deal.II/physics/transformations.h>
#include <softgrasp/postprocess/principal_strains.h>

using namespace dealii;
using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog();
  using Physics::Transformations::Rotations::rotation_matrix_3d;
  const Tensor<2, 3> R =
      rotation_matrix_3d(Tensor<1, 3>({1., 1., 1.}) / std::sqrt(3.), 0.9);
  const Tensor<2, 3> Q = rotation_matrix_3d(Tensor<1, 3>({0., 0.6, 0.8}), -0.4);
  const double       l[3] = {0.8, 1.3, 1.1}; // along Q's columns 0, 1, 2
  Tensor<2, 3>       D;
  for (unsigned int i = 0; i < 3; ++i)
    D[i][i] = l[i];
  const Tensor<2, 3>     F = R * Q * D * transpose(Q);
  const PrincipalStrains p = PrincipalStrains::compute(F);

  const double       expected[3] = {0.3, 0.1, -0.2};
  const unsigned int column[3]   = {1, 2, 0};
  for (unsigned int i = 0; i < 3; ++i)
  {
    SG_CHECK_CLOSE(p.strains[i], expected[i], 0, 1e-14, "principal strain");
    SG_CHECK_CLOSE(p.stretches[i], expected[i] + 1, 0, 1e-14, "stretch");
    Tensor<1, 3> q;
    for (unsigned int k = 0; k < 3; ++k)
      q[k] = Q[k][column[i]];
    SG_CHECK_CLOSE(std::abs(q * p.directions[i]),
                   1.0,
                   0,
                   1e-12,
                   "principal direction is a column of Q");
  }
  SG_CHECK_CLOSE(p.e_max(), 0.3, 0, 1e-14, "e_max");
  SG_CHECK_CLOSE(p.e_min(), -0.2, 0, 1e-14, "e_min");
  SG_CHECK_CLOSE(p.J, 0.8 * 1.3 * 1.1, 1e-14, 0, "J");
  deallog << "F = R Q diag(0.8, 1.3, 1.1) Q^T: e = " << p.strains[0] << ", "
          << p.strains[1] << ", " << p.strains[2] << "; J = " << p.J
          << std::endl;

  const PrincipalStrains r = PrincipalStrains::compute(R);
  for (unsigned int i = 0; i < 3; ++i)
    SG_CHECK_CLOSE(r.strains[i], 0, 0, 1e-14, "rigid rotation: zero strain");
  deallog << "pure rotation: zero principal strains" << std::endl;
  deallog << "OK" << std::endl;
}
