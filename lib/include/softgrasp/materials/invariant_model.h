#ifndef softgrasp_materials_invariant_model_h
#define softgrasp_materials_invariant_model_h

#include <softgrasp/base/simd.h>
#include <softgrasp/materials/isochoric_model.h>

namespace softgrasp
{
  /**
   * Base of isotropic models written in the isochoric invariants
   * I1bar = tr Cbar and I2bar = (I1bar^2 - tr Cbar^2)/2. A derived class
   * gives W(I1bar, I2bar) and its first and second partial derivatives;
   * this class assembles dPsi/dCbar and d2Psi/dCbar2 from
   *   dI1/dCbar = I,  dI2/dCbar = I1 I - Cbar,  d2I2/dCbar2 = I(x)I - II,
   * for single points (evaluate()) and for SIMD batches (evaluate_batch()).
   * Derive through InvariantModelImplementation, which takes one templated
   * formula for both.
   */
  class InvariantModel : public IsochoricModel
  {
  public:
    /// W and its partial derivatives with respect to I1bar and I2bar.
    template <typename Number> struct Derivatives
    {
      Number W = 0, W1 = 0, W2 = 0, W11 = 0, W12 = 0, W22 = 0;
    };

    void evaluate(const dealii::SymmetricTensor<2, 3> &Cbar,
                  const StructuralDirections          &directions,
                  const bool                           with_second_derivative,
                  Response                            &response) const final;

    void
    evaluate_batch(const dealii::SymmetricTensor<2, 3, VectorizedDouble> &Cbar,
                   const StructuralDirections *directions,
                   const unsigned int          n_lanes,
                   VectorizedDouble           &energy,
                   dealii::SymmetricTensor<2, 3, VectorizedDouble>
                       &first_derivative) const final;

    void evaluate_block(IsochoricPointBlock &block) const final;

  protected:
    /// Invariants in, W and its first partial derivatives out, for a block
    /// of points (structure of arrays; see IsochoricPointBlock for padding).
    struct InvariantBlock
    {
      unsigned int n_points = 0;
      PointValues  I1, I2, W, W1, W2;
    };

    virtual Derivatives<double>
    invariant_derivatives(const double &I1, const double &I2) const = 0;
    virtual Derivatives<VectorizedDouble>
                 invariant_derivatives(const VectorizedDouble &I1,
                                       const VectorizedDouble &I2) const = 0;
    virtual void invariant_derivatives(InvariantBlock &block) const      = 0;
  };

  /**
   * An invariant model from one formula: @p Model defines
   *   template <typename Number>
   *   Derivatives<Number> derivatives(const Number &I1, const Number &I2)
   * const; for double, VectorizedDouble and simd::Double, and this class
   * makes the virtual overrides of it (curiously recurring template
   * pattern). The library, its tests and its consumers are built with the
   * same SIMD flags (the CMake target carries them), so simd::Double is the
   * same type everywhere.
   */
  template <typename Model>
  class InvariantModelImplementation : public InvariantModel
  {
  protected:
    Derivatives<double> invariant_derivatives(const double &I1,
                                              const double &I2) const final
    {
      return static_cast<const Model &>(*this).derivatives(I1, I2);
    }

    Derivatives<VectorizedDouble>
    invariant_derivatives(const VectorizedDouble &I1,
                          const VectorizedDouble &I2) const final
    {
      return static_cast<const Model &>(*this).derivatives(I1, I2);
    }

    void invariant_derivatives(InvariantBlock &b) const final
    {
      for (unsigned int k = 0; k < b.n_points; k += simd::width)
      {
        const Derivatives<simd::Double> d =
            static_cast<const Model &>(*this).derivatives(simd::load(&b.I1[k]),
                                                          simd::load(&b.I2[k]));
        simd::store(d.W, &b.W[k]);
        simd::store(d.W1, &b.W1[k]);
        simd::store(d.W2, &b.W2[k]);
      }
    }
  };
} // namespace softgrasp

#endif
