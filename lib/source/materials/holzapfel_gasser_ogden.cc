#include <cmath>
#include <deal.II/lac/vector.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/holzapfel_gasser_ogden.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  HolzapfelGasserOgden::HolzapfelGasserOgden()  = default;
  HolzapfelGasserOgden::~HolzapfelGasserOgden() = default;

  void HolzapfelGasserOgden::declare_parameters(ParameterHandler &prm)
  {
    CheckedSection::declare_number(
        prm,
        "Shear modulus",
        "Shear modulus mu of the isotropic matrix. Unit: Pa. Range: (0, inf).");
    CheckedSection::declare_number(
        prm, "k1", "Fibre stress scale k1. Unit: Pa. Range: [0, inf).");
    CheckedSection::declare_number(
        prm,
        "k2",
        "Fibre exponential stiffening k2. Unit: 1. Range: (0, inf).");
    prm.declare_entry("Dispersion kappa",
                      "0",
                      Patterns::Anything(),
                      "Fibre dispersion kappa: 0 for perfectly aligned "
                      "fibres, 1/3 for isotropically dispersed ones. Unit: 1. "
                      "Range: [0, 1/3].");
    prm.declare_entry("Number of fibre families",
                      "1",
                      Patterns::Integer(1, 2),
                      "How many fibre families (1 for muscle fibres or a "
                      "ligament, 2 for crossed fibres). Range: 1 or 2.");
    for (unsigned int a = 0; a < 2; ++a)
    {
      prm.enter_subsection("Fibre direction " + std::to_string(a + 1));
      Functions::ParsedFunction<3>::declare_parameters(prm, 3);
      prm.set("Function expression", a == 0 ? "1; 0; 0" : "0; 1; 0");
      prm.leave_subsection();
    }
  }

  void HolzapfelGasserOgden::parse_parameters(ParameterHandler  &prm,
                                              const std::string &path_)
  {
    path = path_;
    const CheckedSection section(prm, path);
    mu       = section.get_positive("Shear modulus", "Pa");
    k1       = section.get_positive("k1", "Pa", /*allow_zero=*/true);
    k2       = section.get_positive("k2", "");
    kappa    = section.get_in_range("Dispersion kappa", 0, 1. / 3., true, "");
    n_fibres = prm.get_integer("Number of fibre families");
    for (unsigned int a = 0; a < 2; ++a)
    {
      prm.enter_subsection("Fibre direction " + std::to_string(a + 1));
      fibre_field[a] = std::make_unique<Functions::ParsedFunction<3>>(3);
      fibre_field[a]->parse_parameters(prm);
      prm.leave_subsection();
    }
  }

  void HolzapfelGasserOgden::evaluate(const SymmetricTensor<2, 3> &Cbar,
                                      const StructuralDirections  &directions,
                                      const bool                   with_second,
                                      Response &response) const
  {
    AssertThrow(directions.n_directions == n_fibres,
                ExcMessage("HGO material evaluated with " +
                           std::to_string(directions.n_directions) +
                           " structural directions, but it has " +
                           std::to_string(n_fibres) + " fibre families."));
    const SymmetricTensor<2, 3> I  = unit_symmetric_tensor<3>();
    const double                I1 = trace(Cbar);

    response.energy           = 0.5 * mu * (I1 - 3.0);
    response.first_derivative = 0.5 * mu * I;
    if (with_second)
      response.second_derivative = 0;

    for (unsigned int a = 0; a < n_fibres; ++a)
    {
      const Tensor<1, 3>         &n  = directions.direction[a];
      const SymmetricTensor<2, 3> A  = symmetrize(outer_product(n, n));
      const double                I4 = n * (Cbar * n);
      const double E = kappa * (I1 - 3.0) + (1.0 - 3.0 * kappa) * (I4 - 1.0);
      if (E <= 0)
        continue; // a compressed fibre family carries no load
      const SymmetricTensor<2, 3> D = kappa * I + (1.0 - 3.0 * kappa) * A;
      const double                e = std::exp(k2 * E * E);
      response.energy += 0.5 * k1 / k2 * (e - 1.0);
      response.first_derivative += k1 * E * e * D;
      if (with_second)
        response.second_derivative +=
            k1 * e * (1.0 + 2.0 * k2 * E * E) * outer_product(D, D);
    }
  }

  double HolzapfelGasserOgden::initial_shear_modulus() const
  {
    return mu;
  }

  unsigned int HolzapfelGasserOgden::n_structural_directions() const
  {
    return n_fibres;
  }

  StructuralDirections
  HolzapfelGasserOgden::structural_directions(const Point<3> &X) const
  {
    StructuralDirections result;
    result.n_directions = n_fibres;
    for (unsigned int a = 0; a < n_fibres; ++a)
    {
      Vector<double> value(3);
      fibre_field[a]->vector_value(X, value);
      Tensor<1, 3> d;
      for (unsigned int i = 0; i < 3; ++i)
        d[i] = value[i];
      const double norm = d.norm();
      if (!(norm > 1e-12) || !std::isfinite(norm))
      {
        std::ostringstream msg;
        msg << "The fibre direction field '" << path << "/Fibre direction "
            << a + 1 << "' is zero or not finite at the reference point (" << X
            << ") m. Fix: give a nonzero direction everywhere in the "
            << "body.";
        throw InputError(msg.str());
      }
      result.direction[a] = d / norm;
    }
    return result;
  }

  std::string HolzapfelGasserOgden::summary() const
  {
    std::ostringstream out;
    out << "Holzapfel-Gasser-Ogden, mu = " << mu << " Pa, k1 = " << k1
        << " Pa, k2 = " << k2 << ", kappa = " << kappa << ", " << n_fibres
        << " fibre famil" << (n_fibres == 1 ? "y" : "ies");
    return out.str();
  }

  SOFTGRASP_REGISTER_ISOCHORIC_MODEL(
      HolzapfelGasserOgden,
      "Holzapfel-Gasser-Ogden",
      "neo-Hookean matrix + k1/(2k2) (exp(k2 <E_a>^2) - 1) per fibre family")
} // namespace softgrasp
