// Cook's membrane against the published tip deflections of the deal.II code
// gallery entry "Quasi-Static Finite-Strain Compressible Elasticity"
// (3D, 1 mm thick, one element layer): Q2 14.22/14.30/14.32/14.33 mm at
// 4/8/16/32 elements per edge, Q1 14.13/14.28/14.32 mm at 16/32/64.
// Checks: each mesh equals the published value to its rounding; monotone
// convergence from below, and within 1 % of the converged values 14.33 mm (Q2)
// and 14.32 mm (Q1) on the finest mesh run here.
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);

  struct Case
  {
    unsigned int              degree;
    std::vector<unsigned int> meshes;
    std::vector<double>       published; // mm, rounded to 0.01 mm
    double                    converged; // m
  };
  for (const Case &c :
       {Case{2, {2, 4, 8, 16}, {13.83, 14.22, 14.30, 14.32}, 14.33e-3},
        Case{1, {8, 16, 32}, {13.61, 14.13, 14.28}, 14.32e-3}})
  {
    double previous = 0;
    for (unsigned int i = 0; i < c.meshes.size(); ++i)
    {
      const unsigned int n = c.meshes[i];
      const double       uy =
          run_and_get<3>(cook_membrane_prm(3,
                                           c.degree,
                                           n,
                                           "displacement",
                                           0.3,
                                           "direct",
                                           "output-cook-reference"),
                         "u0_y");
      dealii::deallog << "Q" << c.degree << " " << n
                      << " elements per edge: tip u_y = " << uy * 1e3
                      << " mm (published: " << c.published[i] << " mm)"
                      << std::endl;
      SG_CHECK(std::abs(uy * 1e3 - c.published[i]) <= 0.0051,
               "equals the published value on the same mesh to its 0.01 mm "
               "rounding");
      SG_CHECK(uy > previous, "tip deflection grows under refinement");
      SG_CHECK(uy < c.converged * 1.002, "converges from below");
      previous = uy;
    }
    const double error = std::abs(previous - c.converged) / c.converged;
    dealii::deallog << "Q" << c.degree << " finest mesh: " << 100 * error
                    << " % from " << c.converged * 1e3 << " mm" << std::endl;
    SG_CHECK(error < 0.01, "within 1 % of the published converged value");
  }
}
