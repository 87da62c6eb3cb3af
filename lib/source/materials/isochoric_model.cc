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
} // namespace softgrasp
