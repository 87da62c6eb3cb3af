#include <softgrasp/materials/isochoric_model.h>

namespace softgrasp
{
  unsigned int IsochoricModel::n_structural_directions() const
  {
    return 0;
  }

  StructuralDirections
  IsochoricModel::structural_directions(const dealii::Point<3> &) const
  {
    return StructuralDirections();
  }

  void IsochoricModel::evaluate_batch(
      const dealii::SymmetricTensor<2, 3, VectorizedDouble> &Cbar,
      const StructuralDirections                            *directions,
      const unsigned int                                     n_lanes,
      VectorizedDouble                                      &energy,
      dealii::SymmetricTensor<2, 3, VectorizedDouble> &first_derivative) const
  {
    energy           = 0;
    first_derivative = dealii::SymmetricTensor<2, 3, VectorizedDouble>();
    Response response;
    for (unsigned int lane = 0; lane < n_lanes; ++lane)
    {
      dealii::SymmetricTensor<2, 3> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          C[i][j] = Cbar[i][j][lane];
      evaluate(C, directions[lane], false, response);
      energy[lane] = response.energy;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          first_derivative[i][j][lane] = response.first_derivative[i][j];
    }
  }

  void IsochoricModel::evaluate_block(IsochoricPointBlock &block) const
  {
    StructuralDirections point;
    point.n_directions = block.n_directions;
    Response response;
    for (unsigned int k = 0; k < block.n_points; ++k)
    {
      dealii::SymmetricTensor<2, 3> C;
      for (unsigned int c = 0; c < 6; ++c)
        C.access_raw_entry(c) = block.Cbar[c][k];
      for (unsigned int a = 0; a < block.n_directions; ++a)
        for (unsigned int d = 0; d < 3; ++d)
          point.direction[a][d] = block.directions[3 * a + d][k];
      evaluate(C, point, false, response);
      block.energy[k] = response.energy;
      for (unsigned int c = 0; c < 6; ++c)
        block.X[c][k] = response.first_derivative.access_raw_entry(c);
    }
  }
} // namespace softgrasp
