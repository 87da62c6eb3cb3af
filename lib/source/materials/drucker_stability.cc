#include <algorithm>
#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <iomanip>
#include <softgrasp/materials/drucker_stability.h>
#include <softgrasp/materials/homogeneous_loading.h>
#include <sstream>
#include <vector>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// Principal Kirchhoff stresses tau_i (Pa) at F = diag(l).
    Tensor<1, 3> principal_kirchhoff(const Material             &material,
                                     const StructuralDirections &directions,
                                     const Tensor<1, 3>         &l)
    {
      Tensor<2, 3> F;
      for (unsigned int i = 0; i < 3; ++i)
        F[i][i] = l[i];
      Material::Response response;
      material.evaluate_spatial(F, directions, false, response);
      Tensor<1, 3> tau;
      for (unsigned int i = 0; i < 3; ++i)
        tau[i] = response.stress[i][i];
      return tau;
    }

    /// The smallest of the eigenvalues of H and the shear terms at the
    /// principal stretches @p l (Pa).
    double smallest_modulus(const Material             &material,
                            const StructuralDirections &directions,
                            const Tensor<1, 3>         &l)
    {
      const double          h   = 1e-6; // in ln l
      const Tensor<1, 3>    tau = principal_kirchhoff(material, directions, l);
      SymmetricTensor<2, 3> H;
      std::array<Tensor<1, 3>, 3> column;
      for (unsigned int j = 0; j < 3; ++j)
      {
        Tensor<1, 3> plus = l, minus = l;
        plus[j] *= std::exp(h);
        minus[j] *= std::exp(-h);
        column[j] = (principal_kirchhoff(material, directions, plus) -
                     principal_kirchhoff(material, directions, minus)) /
                    (2 * h);
      }
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          H[i][j] = 0.5 * (column[j][i] + column[i][j]);
      const auto eigenvalues = dealii::eigenvalues(H);
      double     smallest    = eigenvalues[2]; // descending order
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i + 1; j < 3; ++j)
        {
          const double dl    = std::log(l[i]) - std::log(l[j]);
          const double shear = std::abs(dl) > 1e-4
                                   ? (tau[i] - tau[j]) / dl
                                   : 0.5 * (H[i][i] + H[j][j]) - H[i][j];
          smallest           = std::min(smallest, shear);
        }
      return smallest;
    }
  } // namespace

  DruckerStability
  DruckerStability::check(const Material                     &material,
                          const double                        min_stretch,
                          const double                        max_stretch,
                          const unsigned int                  n,
                          const std::vector<HomogeneousTest> &tests)
  {
    // the stretches by distance from 1, each with both tests
    std::vector<double> stretches;
    for (unsigned int k = 0; k < n; ++k)
      stretches.push_back(min_stretch + (max_stretch - min_stretch) * k /
                                            std::max(1u, n - 1));
    std::stable_sort(stretches.begin(),
                     stretches.end(),
                     [](const double a, const double b)
                     { return std::abs(std::log(a)) < std::abs(std::log(b)); });
    const StructuralDirections directions =
        material.structural_directions(Point<3>());
    const double     mu0 = material.initial_shear_modulus();
    DruckerStability result;
    result.smallest = 1e300;
    for (const double stretch : stretches)
      for (const auto test : tests)
      {
        const auto state =
            test == HomogeneousTest::uniaxial
                ? HomogeneousLoading::uniaxial(material, directions, stretch)
                : HomogeneousLoading::equibiaxial(
                      material, directions, stretch);
        const double s =
            smallest_modulus(material, directions, state.stretches) / mu0;
        if (s <= 0)
        {
          result.stable   = false;
          result.test     = test;
          result.stretch  = stretch;
          result.smallest = s;
          return result;
        }
        result.smallest = std::min(result.smallest, s);
      }
    return result;
  }

  std::string DruckerStability::summary(const double min_stretch,
                                        const double max_stretch) const
  {
    std::ostringstream out;
    out << std::setprecision(3);
    if (stable)
      out << "Drucker-stable in uniaxial and equibiaxial stress from l = "
          << min_stretch << " to " << max_stretch << " (smallest modulus "
          << smallest << " mu_0)";
    else
      out << "not Drucker-stable: in " << MaterialFit::name(test)
          << " stress at l = " << stretch << " a modulus is " << smallest
          << " mu_0";
    return out.str();
  }
} // namespace softgrasp
