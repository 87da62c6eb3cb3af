#ifndef softgrasp_postprocess_principal_strains_h
#define softgrasp_postprocess_principal_strains_h

#include <array>
#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace softgrasp
{
  /**
   * Principal strains as in the source paper (Sec. II-C): from
   * F = I + Grad u, the Green-Lagrange strain E = (F^T F - I)/2 is
   * decomposed as E = sum_i (lambda_i^2 - 1)/2 n_i (x) n_i, giving the
   * principal stretches lambda_i = sqrt(1 + 2 E_i), the principal
   * (reference) directions n_i and the principal strains
   * e_i = lambda_i - 1, sorted so that e_max = e[0] >= e[1] >= e[2] = e_min.
   */
  struct PrincipalStrains
  {
    std::array<double, 3>               stretches;  ///< lambda_i (1)
    std::array<double, 3>               strains;    ///< e_i = lambda_i - 1 (1)
    std::array<dealii::Tensor<1, 3>, 3> directions; ///< n_i, reference frame
    double                              J = 1;      ///< det F (1)

    static PrincipalStrains compute(const dealii::Tensor<2, 3> &F);

    double e_max() const
    {
      return strains[0];
    }
    double e_min() const
    {
      return strains[2];
    }
  };

  /// The Green-Lagrange principal strain (lambda^2 - 1)/2 of the principal
  /// strain @p e = lambda - 1 (both 1). Monotone in e, so an extreme of e
  /// over a tissue is also an extreme of this measure, at the same point.
  inline double green_lagrange_strain(const double e)
  {
    return ((1 + e) * (1 + e) - 1) / 2;
  }

  /// The logarithmic (Hencky) principal strain ln lambda of @p e =
  /// lambda - 1 (both 1); monotone in e.
  inline double logarithmic_strain(const double e)
  {
    return std::log1p(e);
  }

  /// Von Mises equivalent stress sqrt(3/2 dev(sigma):dev(sigma)) (Pa).
  double von_mises_stress(const dealii::SymmetricTensor<2, 3> &sigma);
} // namespace softgrasp

#endif
