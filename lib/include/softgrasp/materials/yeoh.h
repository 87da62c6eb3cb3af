#ifndef softgrasp_materials_yeoh_h
#define softgrasp_materials_yeoh_h

#include <softgrasp/materials/invariant_model.h>
#include <vector>

namespace softgrasp
{
  /**
   * Yeoh solid, isochoric part Psi_iso = sum_{i=1}^{N} C_i0 (I1bar - 3)^i,
   * small-strain shear modulus mu_0 = 2 C10.
   * Parameter: "Coefficients" C10, C20, ... (Pa), C10 > 0.
   */
  class Yeoh : public InvariantModelImplementation<Yeoh>
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
    std::vector<double> coefficients; ///< C10, C20, ... (Pa)
  };
} // namespace softgrasp

#endif
