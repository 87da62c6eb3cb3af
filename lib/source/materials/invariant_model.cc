#include <softgrasp/materials/invariant_model.h>

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
} // namespace softgrasp
