#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <softgrasp/postprocess/principal_strains.h>

namespace softgrasp
{
  using namespace dealii;

  PrincipalStrains PrincipalStrains::compute(const Tensor<2, 3> &F)
  {
    const SymmetricTensor<2, 3> E =
        0.5 * (symmetrize(transpose(F) * F) - unit_symmetric_tensor<3>());
    // eigenvectors() returns the eigenpairs sorted by descending eigenvalue.
    const auto eig = eigenvectors(E, SymmetricTensorEigenvectorMethod::jacobi);
    PrincipalStrains result;
    for (unsigned int i = 0; i < 3; ++i)
    {
      result.stretches[i]  = std::sqrt(std::max(0.0, 1.0 + 2.0 * eig[i].first));
      result.strains[i]    = result.stretches[i] - 1.0;
      result.directions[i] = eig[i].second;
    }
    result.J = determinant(F);
    return result;
  }

  double von_mises_stress(const SymmetricTensor<2, 3> &sigma)
  {
    const SymmetricTensor<2, 3> s = deviator(sigma);
    return std::sqrt(1.5 * (s * s));
  }
} // namespace softgrasp
