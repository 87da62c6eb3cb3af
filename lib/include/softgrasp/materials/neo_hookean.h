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
  class NeoHookean : public InvariantModel
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm,
                                 const std::string        &path) override;
    double      initial_shear_modulus() const override;
    std::string summary() const override;

  protected:
    Derivatives invariant_derivatives(const double I1,
                                      const double I2) const override;

  private:
    double mu = 0; ///< shear modulus (Pa)
  };
} // namespace softgrasp

#endif
