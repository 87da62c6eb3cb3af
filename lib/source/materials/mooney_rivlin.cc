#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/mooney_rivlin.h>

namespace softgrasp
{
  void MooneyRivlin::declare_parameters(dealii::ParameterHandler &prm)
  {
    CheckedSection::declare_number(
        prm, "C10", "Coefficient of (I1bar - 3). Unit: Pa. Range: (0, inf).");
    CheckedSection::declare_number(
        prm, "C01", "Coefficient of (I2bar - 3). Unit: Pa. Range: [0, inf).");
  }

  void MooneyRivlin::parse_parameters(dealii::ParameterHandler &prm,
                                      const std::string        &path)
  {
    const CheckedSection section(prm, path);
    c10 = section.get_positive("C10", "Pa");
    c01 = section.get_positive("C01", "Pa", /*allow_zero=*/true);
  }

  double MooneyRivlin::initial_shear_modulus() const
  {
    return 2.0 * (c10 + c01);
  }

  std::string MooneyRivlin::summary() const
  {
    return "Mooney-Rivlin, C10 = " + std::to_string(c10) +
           " Pa, C01 = " + std::to_string(c01) + " Pa";
  }

  template <typename Number>
  InvariantModel::Derivatives<Number>
  MooneyRivlin::derivatives(const Number &I1, const Number &I2) const
  {
    Derivatives<Number> d;
    d.W  = c10 * (I1 - 3.0) + c01 * (I2 - 3.0);
    d.W1 = c10;
    d.W2 = c01;
    return d;
  }

  template InvariantModel::Derivatives<double>
  MooneyRivlin::derivatives(const double &, const double &) const;
  template InvariantModel::Derivatives<VectorizedDouble>
  MooneyRivlin::derivatives(const VectorizedDouble &,
                            const VectorizedDouble &) const;
  template InvariantModel::Derivatives<simd::Double>
  MooneyRivlin::derivatives(const simd::Double &, const simd::Double &) const;

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(
      MooneyRivlin,
      "Mooney-Rivlin",
      "Psi_iso = C10 (I1bar - 3) + C01 (I2bar - 3)")
} // namespace softgrasp
