#include <array>
#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/simd.h>
#include <softgrasp/materials/volumetric_energy.h>
#include <utility>

namespace softgrasp
{
  namespace
  {
    const std::array<std::pair<VolumetricEnergy::Type, const char *>, 3>
        type_names = {{{VolumetricEnergy::Type::quadratic, "quadratic"},
                       {VolumetricEnergy::Type::logarithmic, "logarithmic"},
                       {VolumetricEnergy::Type::simo_taylor, "Simo-Taylor"}}};
  }

  VolumetricEnergy::VolumetricEnergy(const Type type, const double bulk_modulus)
      : type(type)
      , kappa(bulk_modulus)
  {
  }

  std::string VolumetricEnergy::names()
  {
    std::string out;
    for (const auto &entry : type_names)
      out += (out.empty() ? "" : "|") + std::string(entry.second);
    return out;
  }

  VolumetricEnergy::Type
  VolumetricEnergy::type_from_name(const std::string &name)
  {
    for (const auto &entry : type_names)
      if (name == entry.second)
        return entry.first;
    throw InputError("Unknown volumetric energy '" + name +
                     "'. Valid names are: " + names() + ".");
  }

  std::string VolumetricEnergy::name() const
  {
    for (const auto &entry : type_names)
      if (entry.first == type)
        return entry.second;
    return "";
  }

  double VolumetricEnergy::bulk_modulus() const
  {
    return kappa;
  }

  template <typename Number>
  Number VolumetricEnergy::energy_of(const Number &J) const
  {
    using std::log; // and simd::stdx::log by argument-dependent lookup
    switch (type)
    {
    case Type::quadratic:
      return (0.5 * kappa) * (J - 1.0) * (J - 1.0);
    case Type::logarithmic:
      return (0.5 * kappa) * log(J) * log(J);
    case Type::simo_taylor:
      return (0.25 * kappa) * (J * J - 1.0 - 2.0 * log(J));
    }
    return Number(0.0);
  }

  template <typename Number>
  Number VolumetricEnergy::first_derivative_of(const Number &J) const
  {
    using std::log;
    switch (type)
    {
    case Type::quadratic:
      return kappa * (J - 1.0);
    case Type::logarithmic:
      return kappa * log(J) / J;
    case Type::simo_taylor:
      return (0.5 * kappa) * (J - 1.0 / J);
    }
    return Number(0.0);
  }

  double VolumetricEnergy::energy(const double J) const
  {
    return energy_of(J);
  }

  double VolumetricEnergy::first_derivative(const double J) const
  {
    return first_derivative_of(J);
  }

  void VolumetricEnergy::evaluate_block(const unsigned int n_points,
                                        const PointValues &J,
                                        PointValues       &U,
                                        PointValues       &dU) const
  {
    for (unsigned int k = 0; k < n_points; k += simd::width)
    {
      const simd::Double j = simd::load(&J[k]);
      simd::store(energy_of(j), &U[k]);
      simd::store(first_derivative_of(j), &dU[k]);
    }
  }

  double VolumetricEnergy::second_derivative(const double J) const
  {
    switch (type)
    {
    case Type::quadratic:
      return kappa;
    case Type::logarithmic:
      return kappa * (1.0 - std::log(J)) / (J * J);
    case Type::simo_taylor:
      return 0.5 * kappa * (1.0 + 1.0 / (J * J));
    }
    return 0;
  }
} // namespace softgrasp
