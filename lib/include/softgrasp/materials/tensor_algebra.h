#ifndef softgrasp_materials_tensor_algebra_h
#define softgrasp_materials_tensor_algebra_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace softgrasp
{
  /**
   * Small tensor identities used by the hyperelastic chain rules. All are
   * three-dimensional: softgrasp evaluates materials in 3D and treats 2D
   * problems as plane strain (see PlaneStrain).
   */
  namespace TensorAlgebra
  {
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    /// (A (.) B)_IJKL = 1/4 (A_IK B_JL + A_IL B_JK + B_IK A_JL + B_IL A_JK);
    /// for A = B this is d(A^{-1})/dA up to sign, with A the inverse.
    SymmetricTensor<4, 3> symmetric_product(const SymmetricTensor<2, 3> &A,
                                            const SymmetricTensor<2, 3> &B);

    /// sym(a (x) b) for vectors a, b.
    SymmetricTensor<2, 3> symmetric_dyad(const Tensor<1, 3> &a,
                                         const Tensor<1, 3> &b);

    /// The contraction A : T : B for symmetric A, B.
    double double_contract(const SymmetricTensor<2, 3> &A,
                           const SymmetricTensor<4, 3> &T,
                           const SymmetricTensor<2, 3> &B);
  } // namespace TensorAlgebra
} // namespace softgrasp

#endif
