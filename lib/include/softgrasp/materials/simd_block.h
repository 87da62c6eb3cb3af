#ifndef softgrasp_materials_simd_block_h
#define softgrasp_materials_simd_block_h

#include <array>
#include <softgrasp/base/simd.h>
#include <softgrasp/materials/isochoric_model.h>

namespace softgrasp
{
  /// Helpers of the isochoric models' block paths (evaluate_block()): a
  /// symmetric tensor in SIMD registers, components 00, 11, 22, 01, 02, 12.
  namespace simd
  {
    using SymmetricTensor = std::array<Double, 6>;

    /// X += s n (x) n.
    inline void add_outer_product(SymmetricTensor &X,
                                  const Double    &s,
                                  const Double    &n0,
                                  const Double    &n1,
                                  const Double    &n2)
    {
      X[0] += s * n0 * n0;
      X[1] += s * n1 * n1;
      X[2] += s * n2 * n2;
      X[3] += s * n0 * n1;
      X[4] += s * n0 * n2;
      X[5] += s * n1 * n2;
    }

    /// W and X of the points from @p k of @p block.
    inline void store_result(const Double          &W,
                             const SymmetricTensor &X,
                             IsochoricPointBlock   &block,
                             const unsigned int     k)
    {
      store(W, &block.energy[k]);
      for (unsigned int i = 0; i < 6; ++i)
        store(X[i], &block.X[i][k]);
    }
  } // namespace simd
} // namespace softgrasp

#endif
