#include <cmath>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/veronda_westmann.h>

namespace softgrasp
{
  void VerondaWestmann::declare_parameters(dealii::ParameterHandler &prm)
  {
    CheckedSection::declare_number(
        prm, "C1", "Stress scale C1. Unit: Pa. Range: (0, inf).");
    CheckedSection::declare_number(
        prm, "C2", "Exponential stiffening C2. Unit: 1. Range: (0, inf).");
  }

  void VerondaWestmann::parse_parameters(dealii::ParameterHandler &prm,
                                         const std::string        &path)
  {
    const CheckedSection section(prm, path);
    c1 = section.get_positive("C1", "Pa");
    c2 = section.get_positive("C2", "");
  }

  double VerondaWestmann::initial_shear_modulus() const
  {
    return c1 * c2;
  }

  std::string VerondaWestmann::summary() const
  {
    return "Veronda-Westmann, C1 = " + std::to_string(c1) +
           " Pa, C2 = " + std::to_string(c2);
  }

  template <typename Number>
  InvariantModel::Derivatives<Number>
  VerondaWestmann::derivatives(const Number &I1, const Number &I2) const
  {
    using std::exp; // and simd::stdx::exp by argument-dependent lookup
    Derivatives<Number> d;
    const Number        e = exp(c2 * (I1 - 3.0));
    d.W                   = c1 * (e - 1.0) - 0.5 * c1 * c2 * (I2 - 3.0);
    d.W1                  = c1 * c2 * e;
    d.W2                  = -0.5 * c1 * c2;
    d.W11                 = c1 * c2 * c2 * e;
    return d;
  }

  template InvariantModel::Derivatives<double>
  VerondaWestmann::derivatives(const double &, const double &) const;
  template InvariantModel::Derivatives<VectorizedDouble>
  VerondaWestmann::derivatives(const VectorizedDouble &,
                               const VectorizedDouble &) const;
  template InvariantModel::Derivatives<simd::Double>
  VerondaWestmann::derivatives(const simd::Double &,
                               const simd::Double &) const;

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(
      VerondaWestmann,
      "Veronda-Westmann",
      "Psi_iso = C1 (exp(C2 (I1bar - 3)) - 1) - C1 C2/2 (I2bar - 3)")
} // namespace softgrasp
