#ifndef softgrasp_materials_homogeneous_loading_h
#define softgrasp_materials_homogeneous_loading_h

#include <deal.II/base/tensor.h>
#include <softgrasp/materials/material.h>

namespace softgrasp
{
  /**
   * Homogeneous stress states of a compressible material: the deformation
   * F = diag(l1, l2, l3) with prescribed stretch(es) and the free stretches
   * found by Newton's method (with the material's consistent tangent) so
   * that the free normal stresses vanish. Used to plot stress-stretch curves
   * and to check materials against closed forms. The structural directions
   * must be aligned with the coordinate axes (or be absent), otherwise the
   * state has shear stresses and an InputError is thrown.
   */
  class HomogeneousLoading
  {
  public:
    struct State
    {
      dealii::Tensor<1, 3> stretches;  ///< l1, l2, l3 (1)
      double       nominal_stress = 0; ///< P_11 (Pa), force/reference area
      double       cauchy_stress  = 0; ///< sigma_11 (Pa)
      double       energy         = 0; ///< Psi (Pa)
      unsigned int iterations     = 0; ///< Newton iterations used
    };

    /// Uniaxial stress along x with stretch @p stretch: sigma_22 = sigma_33 =
    /// 0.
    static State uniaxial(const Material             &material,
                          const StructuralDirections &directions,
                          const double                stretch);

    /// Equibiaxial stress in the x-y plane with l1 = l2 = @p stretch: sigma_33
    /// = 0.
    static State equibiaxial(const Material             &material,
                             const StructuralDirections &directions,
                             const double                stretch);
  };
} // namespace softgrasp

#endif
