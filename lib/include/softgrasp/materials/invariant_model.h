#ifndef softgrasp_materials_invariant_model_h
#define softgrasp_materials_invariant_model_h

#include <softgrasp/materials/isochoric_model.h>

namespace softgrasp
{
  /**
   * Base of isotropic models written in the isochoric invariants
   * I1bar = tr Cbar and I2bar = (I1bar^2 - tr Cbar^2)/2. A derived class
   * gives W(I1bar, I2bar) and its first and second partial derivatives;
   * this class assembles dPsi/dCbar and d2Psi/dCbar2 from
   *   dI1/dCbar = I,  dI2/dCbar = I1 I - Cbar,  d2I2/dCbar2 = I(x)I - II.
   */
  class InvariantModel : public IsochoricModel
  {
  public:
    /// W and its partial derivatives with respect to I1bar and I2bar.
    struct Derivatives
    {
      double W = 0, W1 = 0, W2 = 0, W11 = 0, W12 = 0, W22 = 0;
    };

    void evaluate(const dealii::SymmetricTensor<2, 3> &Cbar,
                  const StructuralDirections          &directions,
                  const bool                           with_second_derivative,
                  Response                            &response) const final;

  protected:
    virtual Derivatives invariant_derivatives(const double I1,
                                              const double I2) const = 0;
  };
} // namespace softgrasp

#endif
