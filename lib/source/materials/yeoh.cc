#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/yeoh.h>

namespace softgrasp
{
  void Yeoh::declare_parameters(dealii::ParameterHandler &prm)
  {
    CheckedSection::declare_number(
        prm,
        "Coefficients",
        "Comma-separated C10, C20, C30, ... of Psi_iso = sum_i Ci0 (I1bar - "
        "3)^i. Unit: Pa. Range: C10 in (0, inf); others any sign.");
  }

  void Yeoh::parse_parameters(dealii::ParameterHandler &prm,
                              const std::string        &path)
  {
    const CheckedSection section(prm, path);
    coefficients = section.get_number_list("Coefficients");
    if (coefficients[0] <= 0)
      throw InputError(
          "Parameter '" + section.path_of("Coefficients") +
          "' starts with C10 = " + std::to_string(coefficients[0]) +
          " Pa, but C10 must be positive, range (0, inf) Pa. "
          "Fix: give C10 = mu_0/2 > 0 first.");
  }

  double Yeoh::initial_shear_modulus() const
  {
    return 2.0 * coefficients[0];
  }

  std::string Yeoh::summary() const
  {
    std::string out = "Yeoh, C =";
    for (const double c : coefficients)
      out += " " + std::to_string(c);
    return out + " Pa";
  }

  template <typename Number>
  InvariantModel::Derivatives<Number> Yeoh::derivatives(const Number &I1,
                                                        const Number &) const
  {
    Derivatives<Number> d;
    const Number        x = I1 - 3.0;
    // powers by products: x^(i-2), x^(i-1), x^i
    Number x_i_minus_2 = 0.0, x_i_minus_1 = 1.0, x_i = x;
    for (unsigned int i = 1; i <= coefficients.size(); ++i)
    {
      const double c = coefficients[i - 1];
      d.W += c * x_i;
      d.W1 += (c * i) * x_i_minus_1;
      d.W11 += (c * i * (i - 1.0)) * x_i_minus_2;
      x_i_minus_2 = x_i_minus_1;
      x_i_minus_1 = x_i;
      x_i         = x_i * x;
    }
    return d;
  }

  template InvariantModel::Derivatives<double>
  Yeoh::derivatives(const double &, const double &) const;
  template InvariantModel::Derivatives<VectorizedDouble>
  Yeoh::derivatives(const VectorizedDouble &, const VectorizedDouble &) const;
  template InvariantModel::Derivatives<simd::Double>
  Yeoh::derivatives(const simd::Double &, const simd::Double &) const;

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(Yeoh,
                                     "Yeoh",
                                     "Psi_iso = sum_i Ci0 (I1bar - 3)^i")
} // namespace softgrasp
