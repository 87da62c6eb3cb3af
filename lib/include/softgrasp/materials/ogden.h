#ifndef softgrasp_materials_ogden_h
#define softgrasp_materials_ogden_h

#include <softgrasp/materials/isochoric_model.h>
#include <vector>

namespace softgrasp
{
  /**
   * Ogden solid with N terms on the isochoric principal stretches,
   *   Psi_iso = sum_p mu_p/alpha_p (lb1^alpha_p + lb2^alpha_p + lb3^alpha_p -
   * 3), lb_i = J^{-1/3} lambda_i, small-strain shear modulus mu_0 = 1/2 sum_p
   * mu_p alpha_p (Ogden 1972 convention).
   *
   * Written in the eigenvalues c_i = lb_i^2 of Cbar as a separable sum
   * Psi = sum_i phi(c_i). The second derivative carries the divided
   * differences (phi'(c_i) - phi'(c_j))/(c_i - c_j); when two eigenvalues
   * coincide to a relative 1e-6 the divided difference is replaced by
   * phi''((c_i + c_j)/2), which is its limit and second-order accurate, so
   * the model is robust for coincident stretches (the undeformed state,
   * equibiaxial and uniaxial deformations).
   *
   * Parameters: "Moduli" mu_p (Pa) and "Exponents" alpha_p (1), lists of
   * equal length, each mu_p alpha_p > 0 (Ogden's stability condition).
   */
  class Ogden : public IsochoricModel
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm,
                                 const std::string        &path) override;
    void        evaluate(const dealii::SymmetricTensor<2, 3> &Cbar,
                         const StructuralDirections          &directions,
                         const bool                           with_second_derivative,
                         Response                            &response) const override;
    /// Explicit SIMD over the points: eigenvalues and eigenvectors of Cbar
    /// by cyclic Jacobi rotations to round-off, then the same phi().
    void        evaluate_block(IsochoricPointBlock &block) const override;
    double      initial_shear_modulus() const override;
    std::string summary() const override;

  private:
    /// phi(c) = sum_p mu_p/alpha_p (c^{alpha_p/2} - 1) and phi'(c), for
    /// double and simd::Double.
    template <typename Number>
    void phi_and_slope(const Number &c, Number &value, Number &slope) const;
    /// phi''(c).
    double phi_second(const double c) const;

    std::vector<double> moduli;    ///< mu_p (Pa)
    std::vector<double> exponents; ///< alpha_p (1)
  };
} // namespace softgrasp

#endif
