#ifndef softgrasp_materials_veronda_westmann_h
#define softgrasp_materials_veronda_westmann_h

#include <softgrasp/materials/invariant_model.h>

namespace softgrasp
{
  /**
   * Veronda-Westmann solid (Veronda and Westmann 1970, skin), isochoric part
   *   Psi_iso = C1 (exp(C2 (I1bar - 3)) - 1) - C1 C2 / 2 (I2bar - 3),
   * small-strain shear modulus mu_0 = C1 C2.
   * Parameters: "C1" > 0 (Pa), "C2" > 0 (dimensionless).
   */
  class VerondaWestmann : public InvariantModelImplementation<VerondaWestmann>
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
    double c1 = 0; ///< Pa
    double c2 = 0; ///< dimensionless
  };
} // namespace softgrasp

#endif
