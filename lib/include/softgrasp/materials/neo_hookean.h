#ifndef softgrasp_materials_neo_hookean_h
#define softgrasp_materials_neo_hookean_h

#include <softgrasp/materials/invariant_model.h>

namespace softgrasp
{
  /**
   * Compressible neo-Hookean solid, isochoric part
   *   Psi_iso = mu/2 (I1bar - 3).
   * Parameter: "Shear modulus" mu > 0 (Pa).
   */
  class NeoHookean : public InvariantModelImplementation<NeoHookean>
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
    double mu = 0; ///< shear modulus (Pa)
  };
} // namespace softgrasp

#endif
