#include <cmath>
#include <deal.II/lac/vector.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/holzapfel_gasser_ogden.h>
#include <softgrasp/materials/simd_block.h>
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
    check_directions(directions.n_directions);
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
      double                      energy, slope;
      fibre_response(E, energy, slope);
      response.energy += energy;
      response.first_derivative += slope * D;
      if (with_second) // d(slope)/dE = k1 e (1 + 2 k2 E^2), k1 e = slope/E
        response.second_derivative +=
            (slope / E) * (1.0 + 2.0 * k2 * E * E) * outer_product(D, D);
    }
  }

  template <typename Number>
  void HolzapfelGasserOgden::fibre_response(const Number &E,
                                            Number       &energy,
                                            Number       &slope) const
  {
    using std::exp; // and simd::stdx::exp by argument-dependent lookup
    const Number e = exp(k2 * E * E);
    energy         = (0.5 * k1 / k2) * (e - 1.0);
    slope          = k1 * E * e;
  }

  void HolzapfelGasserOgden::check_directions(const unsigned int n) const
  {
    AssertThrow(n == n_fibres,
                ExcMessage("HGO material evaluated with " + std::to_string(n) +
                           " structural directions, but it has " +
                           std::to_string(n_fibres) + " fibre families."));
  }

  void HolzapfelGasserOgden::evaluate_block(IsochoricPointBlock &block) const
  {
    check_directions(block.n_directions);
    using V           = simd::Double;
    const auto  &C    = block.Cbar;
    const auto  &dirs = block.directions;
    const double beta = 1.0 - 3.0 * kappa;
    for (unsigned int k = 0; k < block.n_points; k += simd::width)
    {
      std::array<V, 6>      c;
      simd::SymmetricTensor X;
      for (unsigned int i = 0; i < 6; ++i)
        c[i] = simd::load(&C[i][k]);
      const V I1 = c[0] + c[1] + c[2];
      V       W  = (0.5 * mu) * (I1 - 3.0);
      for (unsigned int i = 0; i < 6; ++i)
        X[i] = i < 3 ? V(0.5 * mu) : V(0.0);
      for (unsigned int a = 0; a < n_fibres; ++a)
      {
        const V n0 = simd::load(&dirs[3 * a][k]);
        const V n1 = simd::load(&dirs[3 * a + 1][k]);
        const V n2 = simd::load(&dirs[3 * a + 2][k]);
        const V I4 = c[0] * n0 * n0 + c[1] * n1 * n1 + c[2] * n2 * n2 +
                     2.0 * (c[3] * n0 * n1 + c[4] * n0 * n2 + c[5] * n1 * n2);
        // Macaulay bracket: a compressed family carries no load
        const V E =
            simd::stdx::max(kappa * (I1 - 3.0) + beta * (I4 - 1.0), V(0.0));
        V energy, slope;
        fibre_response(E, energy, slope);
        W += energy;
        // X += slope (kappa I + beta n (x) n)
        for (unsigned int i = 0; i < 3; ++i)
          X[i] += slope * kappa;
        simd::add_outer_product(X, slope * beta, n0, n1, n2);
      }
      simd::store_result(W, X, block, k);
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
