#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/ogden.h>
#include <softgrasp/materials/tensor_algebra.h>

namespace softgrasp
{
  using namespace dealii;

  void Ogden::declare_parameters(ParameterHandler &prm)
  {
    CheckedSection::declare_number(
        prm,
        "Moduli",
        "Comma-separated mu_p of Psi_iso = sum_p mu_p/alpha_p (sum_i "
        "lbar_i^alpha_p - 3). Unit: Pa. Range: mu_p alpha_p > 0.");
    CheckedSection::declare_number(
        prm,
        "Exponents",
        "Comma-separated alpha_p, as many as Moduli. Unit: 1. Range: nonzero, "
        "mu_p alpha_p > 0.");
  }

  void Ogden::parse_parameters(ParameterHandler &prm, const std::string &path)
  {
    const CheckedSection section(prm, path);
    moduli    = section.get_number_list("Moduli");
    exponents = section.get_number_list("Exponents");
    if (moduli.size() != exponents.size())
      throw InputError("Parameters '" + section.path_of("Moduli") + "' (" +
                       std::to_string(moduli.size()) + " values) and '" +
                       section.path_of("Exponents") + "' (" +
                       std::to_string(exponents.size()) +
                       " values) must have the same length. Fix: give one "
                       "exponent per modulus.");
    for (unsigned int p = 0; p < moduli.size(); ++p)
      if (!(moduli[p] * exponents[p] > 0))
        throw InputError(
            "Ogden term " + std::to_string(p + 1) + " in '" + path +
            "' has mu_p = " + std::to_string(moduli[p]) +
            " Pa and alpha_p = " + std::to_string(exponents[p]) +
            ", but mu_p alpha_p must be positive, range (0, inf) Pa. Fix: give "
            "mu_p the sign of alpha_p (Ogden's stability condition).");
  }

  double Ogden::phi(const double c, const unsigned int derivative) const
  {
    double value = 0;
    for (unsigned int p = 0; p < moduli.size(); ++p)
    {
      const double a = 0.5 * exponents[p];
      switch (derivative)
      {
      case 0:
        value += moduli[p] / exponents[p] * (std::pow(c, a) - 1.0);
        break;
      case 1:
        value += 0.5 * moduli[p] * std::pow(c, a - 1.0);
        break;
      default:
        value += 0.5 * moduli[p] * (a - 1.0) * std::pow(c, a - 2.0);
      }
    }
    return value;
  }

  void Ogden::evaluate(const SymmetricTensor<2, 3> &Cbar,
                       const StructuralDirections &,
                       const bool with_second_derivative,
                       Response  &response) const
  {
    const auto eig =
        eigenvectors(Cbar, SymmetricTensorEigenvectorMethod::jacobi);

    std::array<SymmetricTensor<2, 3>, 3> M;
    std::array<double, 3>                c, d1;
    response.energy           = 0;
    response.first_derivative = 0;
    for (unsigned int i = 0; i < 3; ++i)
    {
      c[i]  = eig[i].first;
      M[i]  = symmetrize(outer_product(eig[i].second, eig[i].second));
      d1[i] = phi(c[i], 1);
      response.energy += phi(c[i], 0);
      response.first_derivative += d1[i] * M[i];
    }
    if (!with_second_derivative)
      return;

    response.second_derivative = 0;
    for (unsigned int i = 0; i < 3; ++i)
      response.second_derivative += phi(c[i], 2) * outer_product(M[i], M[i]);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i + 1; j < 3; ++j)
      {
        const double                scale = std::max(1.0, std::max(c[i], c[j]));
        const double                theta = std::abs(c[i] - c[j]) > 1e-6 * scale
                                                ? (d1[i] - d1[j]) / (c[i] - c[j])
                                                : phi(0.5 * (c[i] + c[j]), 2);
        const SymmetricTensor<2, 3> G =
            TensorAlgebra::symmetric_dyad(eig[i].second, eig[j].second);
        response.second_derivative += 2.0 * theta * outer_product(G, G);
      }
  }

  double Ogden::initial_shear_modulus() const
  {
    double mu = 0;
    for (unsigned int p = 0; p < moduli.size(); ++p)
      mu += 0.5 * moduli[p] * exponents[p];
    return mu;
  }

  std::string Ogden::summary() const
  {
    std::string out = "Ogden, (mu_p Pa, alpha_p) =";
    for (unsigned int p = 0; p < moduli.size(); ++p)
      out += " (" + std::to_string(moduli[p]) + ", " +
             std::to_string(exponents[p]) + ")";
    return out;
  }

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(
      Ogden, "Ogden", "Psi_iso = sum_p mu_p/alpha_p (sum_i lbar_i^alpha_p - 3)")
} // namespace softgrasp
