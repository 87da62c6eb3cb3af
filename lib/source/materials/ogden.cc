#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/materials/ogden.h>
#include <softgrasp/materials/simd_block.h>
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

  template <typename Number>
  void Ogden::phi_and_slope(const Number &c, Number &value, Number &slope) const
  {
    using std::pow; // and simd::stdx::pow by argument-dependent lookup
    value = 0.0;
    slope = 0.0;
    for (unsigned int p = 0; p < moduli.size(); ++p)
    {
      const double a = 0.5 * exponents[p];
      const Number q = pow(c, a - 1.0); // one power per term: c^a = q c
      value += moduli[p] / exponents[p] * (q * c - 1.0);
      slope += 0.5 * moduli[p] * q;
    }
  }

  double Ogden::phi_second(const double c) const
  {
    double value = 0;
    for (unsigned int p = 0; p < moduli.size(); ++p)
    {
      const double a = 0.5 * exponents[p];
      value += 0.5 * moduli[p] * (a - 1.0) * std::pow(c, a - 2.0);
    }
    return value;
  }

  namespace
  {
    using V = simd::Double;

    /// A symmetric 3x3 matrix (00, 11, 22, 01, 02, 12) being diagonalised
    /// and the accumulated rotation Q (row-major), A_0 = Q diag Q^T.
    struct Jacobi
    {
      std::array<V, 6> A;
      std::array<V, 9> Q;

      /// Entry (i, j) of A.
      V &a(const unsigned int i, const unsigned int j)
      {
        static constexpr unsigned int index[3][3] = {
            {0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
        return A[index[i][j]];
      }

      /// The rotation in the (p, q) plane that annihilates A_pq (Golub and
      /// Van Loan, sec. 8.5.2), lanes with A_pq = 0 unchanged.
      void rotate(const unsigned int p, const unsigned int q)
      {
        const unsigned int r           = 3 - p - q;
        const V            apq         = a(p, q);
        const auto         zero        = apq == 0.0;
        V                  theta       = (a(q, q) - a(p, p)) / (2.0 * apq);
        simd::stdx::where(zero, theta) = 0.0;
        V t                            = 1.0 /
              (simd::stdx::abs(theta) + simd::stdx::sqrt(theta * theta + 1.0));
        simd::stdx::where(theta < 0.0, t) = -t;
        simd::stdx::where(zero, t)        = 0.0;
        const V c = 1.0 / simd::stdx::sqrt(t * t + 1.0), s = t * c;
        a(p, p) -= t * apq;
        a(q, q) += t * apq;
        a(p, q)     = 0.0;
        const V arp = a(r, p), arq = a(r, q);
        a(r, p) = c * arp - s * arq;
        a(r, q) = s * arp + c * arq;
        for (unsigned int i = 0; i < 3; ++i)
        {
          const V qp = Q[3 * i + p], qq = Q[3 * i + q];
          Q[3 * i + p] = c * qp - s * qq;
          Q[3 * i + q] = s * qp + c * qq;
        }
      }

      /// Cyclic sweeps until the off-diagonal part is at round-off.
      void diagonalise()
      {
        for (unsigned int sweep = 0; sweep < 12; ++sweep)
        {
          const V off      = A[3] * A[3] + A[4] * A[4] + A[5] * A[5];
          const V diagonal = A[0] * A[0] + A[1] * A[1] + A[2] * A[2];
          if (simd::stdx::all_of(off <= 1e-36 * diagonal))
            return;
          rotate(0, 1);
          rotate(0, 2);
          rotate(1, 2);
        }
      }
    };
  } // namespace

  void Ogden::evaluate_block(IsochoricPointBlock &block) const
  {
    for (unsigned int k = 0; k < block.n_points; k += simd::width)
    {
      Jacobi jacobi;
      for (unsigned int i = 0; i < 6; ++i)
        jacobi.A[i] = simd::load(&block.Cbar[i][k]);
      for (unsigned int i = 0; i < 9; ++i)
        jacobi.Q[i] = (i % 4 == 0) ? 1.0 : 0.0;
      jacobi.diagonalise();
      // Psi = sum_i phi(c_i), dPsi/dCbar = sum_i phi'(c_i) q_i (x) q_i
      V                     W = 0.0;
      simd::SymmetricTensor X;
      X.fill(0.0);
      for (unsigned int i = 0; i < 3; ++i)
      {
        const V c = jacobi.A[i];
        V       value, d1;
        phi_and_slope(c, value, d1);
        W += value;
        simd::add_outer_product(
            X, d1, jacobi.Q[i], jacobi.Q[3 + i], jacobi.Q[6 + i]);
      }
      simd::store_result(W, X, block, k);
    }
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
      c[i] = eig[i].first;
      M[i] = symmetrize(outer_product(eig[i].second, eig[i].second));
      double value;
      phi_and_slope(c[i], value, d1[i]);
      response.energy += value;
      response.first_derivative += d1[i] * M[i];
    }
    if (!with_second_derivative)
      return;

    response.second_derivative = 0;
    for (unsigned int i = 0; i < 3; ++i)
      response.second_derivative +=
          phi_second(c[i]) * outer_product(M[i], M[i]);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i + 1; j < 3; ++j)
      {
        const double                scale = std::max(1.0, std::max(c[i], c[j]));
        const double                theta = std::abs(c[i] - c[j]) > 1e-6 * scale
                                                ? (d1[i] - d1[j]) / (c[i] - c[j])
                                                : phi_second(0.5 * (c[i] + c[j]));
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
