// Volumetric locking on Cook's membrane in plane strain.
//  1. nu = 0.3: Q1 and Q2 displacement elements converge to the same tip
//     deflection (13.77 mm in plane strain).
//  2. nu = 0.4999: the pure displacement Q1 element locks (far too stiff on
//     coarse meshes), while the mixed u-p-J elements Q1-P0 and Q2-P1
//     converge under refinement to a common value.
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

double
tip(const unsigned int degree,
    const unsigned int n,
    const std::string &formulation,
    const double       nu)
{
  const double uy = run_and_get<2>(
      cook_membrane_prm(
          2, degree, n, formulation, nu, "direct", "output-cook-locking"),
      "u0_y");
  dealii::deallog << "nu = " << nu << ", Q" << degree << " " << formulation
                  << ", " << n << " elements per edge: tip u_y = " << uy * 1e3
                  << " mm" << std::endl;
  return uy;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(5);

  // 1. compressible
  const double q1 = tip(1, 32, "displacement", 0.3);
  const double q2 = tip(2, 16, "displacement", 0.3);
  SG_CHECK(close(q1, q2, 0.005), "Q1 and Q2 agree within 0.5 %");

  // 2. nearly incompressible
  std::vector<double> locking, q1p0, q2p1;
  for (const unsigned int n : {2u, 4u, 8u, 16u})
  {
    locking.push_back(tip(1, n, "displacement", 0.4999));
    q1p0.push_back(tip(1, n, "mixed u-p-J", 0.4999));
    q2p1.push_back(tip(2, n, "mixed u-p-J", 0.4999));
  }
  q1p0.push_back(tip(1, 32, "mixed u-p-J", 0.4999));

  for (unsigned int i = 0; i < locking.size(); ++i)
    SG_CHECK(locking[i] < 0.6 * q2p1.back(),
             "the displacement formulation locks: below 60 % of the "
             "converged mixed value");
  const double reference = q2p1.back();
  for (unsigned int i = 1; i < q2p1.size(); ++i)
    SG_CHECK(std::abs(q2p1[i] - reference) <= std::abs(q2p1[i - 1] - reference),
             "Q2-P1 converges monotonically");
  const double mixed_gap = std::abs(q1p0.back() - q2p1.back()) / reference;
  dealii::deallog << "Q1-P0 (32) vs Q2-P1 (16): " << 100 * mixed_gap << " %"
                  << std::endl;
  SG_CHECK(mixed_gap < 0.01, "both mixed elements converge to one value");
  SG_CHECK(close(q2p1[2], q2p1[3], 0.005), "Q2-P1 converged to 0.5 %");
}
