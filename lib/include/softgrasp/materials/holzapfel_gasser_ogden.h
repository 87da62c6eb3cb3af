#ifndef softgrasp_materials_holzapfel_gasser_ogden_h
#define softgrasp_materials_holzapfel_gasser_ogden_h

#include <array>
#include <deal.II/base/parsed_function.h>
#include <memory>
#include <softgrasp/materials/isochoric_model.h>

namespace softgrasp
{
  /**
   * Holzapfel-Gasser-Ogden fibre-reinforced solid (Holzapfel, Gasser and
   * Ogden 2000; with the dispersion kappa of Gasser, Ogden and Holzapfel
   * 2006), isochoric part
   *   Psi_iso = mu/2 (I1bar - 3)
   *           + sum_a k1/(2 k2) (exp(k2 <E_a>^2) - 1),
   *   E_a = kappa (I1bar - 3) + (1 - 3 kappa) (I4bar_a - 1),
   *   I4bar_a = a_a . Cbar a_a,
   * with one or two fibre families a_a (unit reference directions, from a
   * direction field over the reference configuration). The Macaulay bracket
   * <E> = max(E, 0) switches a family off unless it is stretched: fibres
   * carry load only in tension (for kappa = 0 exactly when I4bar_a > 1).
   *
   * Parameters: "Shear modulus" mu > 0 (Pa), "k1" >= 0 (Pa), "k2" > 0 (1),
   * "Dispersion kappa" in [0, 1/3] (1), "Number of fibre families" 1 or 2,
   * and per family a subsection "Fibre direction <a>" holding a deal.II
   * function expression of the reference position x, y, z (m) with three
   * components; it is normalised at every point.
   */
  class HolzapfelGasserOgden : public IsochoricModel
  {
  public:
    HolzapfelGasserOgden();
    ~HolzapfelGasserOgden() override;

    static void  declare_parameters(dealii::ParameterHandler &prm);
    void         parse_parameters(dealii::ParameterHandler &prm,
                                  const std::string        &path) override;
    void         evaluate(const dealii::SymmetricTensor<2, 3> &Cbar,
                          const StructuralDirections          &directions,
                          const bool                           with_second_derivative,
                          Response                            &response) const override;
    void         evaluate_block(IsochoricPointBlock &block) const override;
    double       initial_shear_modulus() const override;
    unsigned int n_structural_directions() const override;
    StructuralDirections
                structural_directions(const dealii::Point<3> &X) const override;
    std::string summary() const override;

  private:
    /// A fibre family's energy k1/(2 k2) (exp(k2 E^2) - 1) and dPsi/dE =
    /// k1 E exp(k2 E^2) at a stretched state E >= 0, for double and
    /// simd::Double.
    template <typename Number>
    void fibre_response(const Number &E, Number &energy, Number &slope) const;
    /// Throws unless @p n equals the number of fibre families.
    void check_directions(const unsigned int n) const;

    double       mu       = 0; ///< matrix shear modulus (Pa)
    double       k1       = 0; ///< fibre stress scale (Pa)
    double       k2       = 0; ///< fibre exponential stiffening (1)
    double       kappa    = 0; ///< dispersion (1), 0 = aligned, 1/3 = isotropic
    unsigned int n_fibres = 1;
    std::array<std::unique_ptr<dealii::Functions::ParsedFunction<3>>, 2>
                fibre_field;
    std::string path;
  };
} // namespace softgrasp

#endif
