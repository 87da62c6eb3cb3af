#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/neo_hookean.h>

namespace softgrasp
{
  void NeoHookean::declare_parameters(dealii::ParameterHandler &prm)
  {
    CheckedSection::declare_number(prm,
                                   "Shear modulus",
                                   "Shear modulus mu of Psi_iso = mu/2 "
                                   "(I1bar - 3). Unit: Pa. Range: (0, inf).");
  }

  void NeoHookean::parse_parameters(dealii::ParameterHandler &prm,
                                    const std::string        &path)
  {
    mu = CheckedSection(prm, path).get_positive("Shear modulus", "Pa");
  }

  double NeoHookean::initial_shear_modulus() const
  {
    return mu;
  }

  std::string NeoHookean::summary() const
  {
    return "neo-Hookean, mu = " + std::to_string(mu) + " Pa";
  }

  template <typename Number>
  InvariantModel::Derivatives<Number>
  NeoHookean::derivatives(const Number &I1, const Number &) const
  {
    Derivatives<Number> d;
    d.W  = 0.5 * mu * (I1 - 3.0);
    d.W1 = 0.5 * mu;
    return d;
  }

  template InvariantModel::Derivatives<double>
  NeoHookean::derivatives(const double &, const double &) const;
  template InvariantModel::Derivatives<VectorizedDouble>
  NeoHookean::derivatives(const VectorizedDouble &,
                          const VectorizedDouble &) const;
  template InvariantModel::Derivatives<simd::Double>
  NeoHookean::derivatives(const simd::Double &, const simd::Double &) const;

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(NeoHookean,
                                     "neo-Hookean",
                                     "Psi_iso = mu/2 (I1bar - 3)")
} // namespace softgrasp
