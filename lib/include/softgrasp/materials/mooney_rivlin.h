#ifndef softgrasp_materials_mooney_rivlin_h
#define softgrasp_materials_mooney_rivlin_h

#include <softgrasp/materials/invariant_model.h>

namespace softgrasp
{
  /**
   * Mooney-Rivlin solid, isochoric part
   *   Psi_iso = C10 (I1bar - 3) + C01 (I2bar - 3),
   * small-strain shear modulus mu_0 = 2 (C10 + C01).
   * Parameters: "C10" > 0 (Pa), "C01" >= 0 (Pa).
   */
  class MooneyRivlin : public InvariantModelImplementation<MooneyRivlin>
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm,
                                 const std::string        &path) override;
    double      initial_shear_modulus() const override;
    std::string summary() const override;

    /// W(I1bar, I2bar) and its partial derivatives, for double,
    /// VectorizedDouble and simd::Double.
    template <typename Number>
    Derivatives<Number> derivatives(const Number &I1, const Number &I2) const;

  private:
    double c10 = 0; ///< Pa
    double c01 = 0; ///< Pa
  };
} // namespace softgrasp

#endif
