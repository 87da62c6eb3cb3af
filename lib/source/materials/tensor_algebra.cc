#include <softgrasp/materials/tensor_algebra.h>

namespace softgrasp
{
  namespace TensorAlgebra
  {
    SymmetricTensor<4, 3> symmetric_product(const SymmetricTensor<2, 3> &A,
                                            const SymmetricTensor<2, 3> &B)
    {
      SymmetricTensor<4, 3> result;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k; l < 3; ++l)
              result[i][j][k][l] =
                  0.25 * (A[i][k] * B[j][l] + A[i][l] * B[j][k] +
                          B[i][k] * A[j][l] + B[i][l] * A[j][k]);
      return result;
    }

    SymmetricTensor<2, 3> symmetric_dyad(const Tensor<1, 3> &a,
                                         const Tensor<1, 3> &b)
    {
      SymmetricTensor<2, 3> result;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          result[i][j] = 0.5 * (a[i] * b[j] + a[j] * b[i]);
      return result;
    }

    double double_contract(const SymmetricTensor<2, 3> &A,
                           const SymmetricTensor<4, 3> &T,
                           const SymmetricTensor<2, 3> &B)
    {
      return A * (T * B);
    }
  } // namespace TensorAlgebra
} // namespace softgrasp
