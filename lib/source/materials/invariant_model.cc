#include <softgrasp/materials/invariant_model.h>
#include <softgrasp/materials/simd_block.h>

namespace softgrasp
{
  using namespace dealii;

  void InvariantModel::evaluate(const SymmetricTensor<2, 3> &Cbar,
                                const StructuralDirections &,
                                const bool with_second_derivative,
                                Response  &response) const
  {
    const SymmetricTensor<2, 3> I  = unit_symmetric_tensor<3>();
    const double                I1 = trace(Cbar);
    const double                I2 = 0.5 * (I1 * I1 - Cbar * Cbar);
    const Derivatives<double>   d  = invariant_derivatives(I1, I2);

    const SymmetricTensor<2, 3> g2 = I1 * I - Cbar;
    response.energy                = d.W;
    response.first_derivative      = d.W1 * I + d.W2 * g2;
    if (with_second_derivative)
      response.second_derivative =
          d.W11 * outer_product(I, I) +
          d.W12 * (outer_product(I, g2) + outer_product(g2, I)) +
          d.W22 * outer_product(g2, g2) +
          d.W2 * (outer_product(I, I) - identity_tensor<3>());
  }

  void InvariantModel::evaluate_batch(
      const SymmetricTensor<2, 3, VectorizedDouble> &Cbar,
      const StructuralDirections *,
      const unsigned int,
      VectorizedDouble                        &energy,
      SymmetricTensor<2, 3, VectorizedDouble> &first_derivative) const
  {
    const auto             I  = unit_symmetric_tensor<3, VectorizedDouble>();
    const VectorizedDouble I1 = trace(Cbar);
    const VectorizedDouble I2 = 0.5 * (I1 * I1 - Cbar * Cbar);
    const auto             d  = invariant_derivatives(I1, I2);
    energy                    = d.W;
    first_derivative          = d.W1 * I + d.W2 * (I1 * I - Cbar);
  }

  void InvariantModel::evaluate_block(IsochoricPointBlock &block) const
  {
    using V = simd::Double;
    InvariantBlock invariants;
    invariants.n_points = block.n_points;
    const auto &C       = block.Cbar;
    for (unsigned int k = 0; k < block.n_points; k += simd::width)
    {
      const V c0 = simd::load(&C[0][k]), c1 = simd::load(&C[1][k]),
              c2 = simd::load(&C[2][k]), c3 = simd::load(&C[3][k]),
              c4 = simd::load(&C[4][k]), c5 = simd::load(&C[5][k]);
      const V I1 = c0 + c1 + c2;
      // Cbar : Cbar with the off-diagonal entries counted twice
      const V CC =
          c0 * c0 + c1 * c1 + c2 * c2 + 2.0 * (c3 * c3 + c4 * c4 + c5 * c5);
      simd::store(I1, &invariants.I1[k]);
      simd::store(0.5 * (I1 * I1 - CC), &invariants.I2[k]);
    }
    invariant_derivatives(invariants);
    // dW/dCbar = W1 I + W2 (I1 I - Cbar)
    for (unsigned int k = 0; k < block.n_points; k += simd::width)
    {
      const V               W1       = simd::load(&invariants.W1[k]);
      const V               W2       = simd::load(&invariants.W2[k]);
      const V               diagonal = W1 + W2 * simd::load(&invariants.I1[k]);
      simd::SymmetricTensor X;
      for (unsigned int c = 0; c < 6; ++c)
        X[c] = (c < 3 ? diagonal : V(0.0)) - W2 * simd::load(&C[c][k]);
      simd::store_result(simd::load(&invariants.W[k]), X, block, k);
    }
  }
} // namespace softgrasp
