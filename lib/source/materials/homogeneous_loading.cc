#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/homogeneous_loading.h>
#include <sstream>
#include <vector>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /**
     * Solve S_kk = 0 for the stretches of the components in @p free by
     * Newton's method, starting from the isochoric guess.
     */
    HomogeneousLoading::State solve(const Material                  &material,
                                    const StructuralDirections      &directions,
                                    Tensor<1, 3>                     stretches,
                                    const std::vector<unsigned int> &free)
    {
      const unsigned int n = free.size();
      Material::Response response;
      unsigned int       it = 0;
      for (; it < 50; ++it)
      {
        Tensor<2, 3> F;
        for (unsigned int i = 0; i < 3; ++i)
          F[i][i] = stretches[i];
        material.evaluate_material(F, directions, true, response);
        // in Kirchhoff stresses tau_aa = l_a^2 S_aa: relative to S_00 a
        // stretch that runs away (S_aa = tau_aa / l_a^2 small) looked
        // converged
        double residual = 0, scale = std::abs(response.stress[0][0]) *
                                     stretches[0] * stretches[0];
        for (unsigned int a = 0; a < n; ++a)
          residual = std::max(residual,
                              std::abs(response.stress[free[a]][free[a]]) *
                                  stretches[free[a]] * stretches[free[a]]);
        scale = std::max(scale, material.initial_shear_modulus());
        // round-off in the stress grows with the bulk modulus
        if (residual <=
            std::max(1e-12 * scale, 1e-14 * material.bulk_modulus()))
          break;
        // Newton on tau_aa = l_a^2 S_aa = 0 in the unknowns ln l_a:
        // d tau_aa / d ln l_b = l_a^2 CC_aabb l_b^2 + 2 delta_ab tau_aa.
        // (On S_aa = 0 in l a compressed state could step the free stretch
        // away to infinity, where S_aa = tau_aa / l_a^2 falls.)
        FullMatrix<double> K(n, n);
        Vector<double>     r(n), dlog(n);
        for (unsigned int a = 0; a < n; ++a)
        {
          const unsigned int A = free[a];
          const double       tau =
              stretches[A] * stretches[A] * response.stress[A][A];
          r[a] = -tau;
          for (unsigned int b = 0; b < n; ++b)
          {
            const unsigned int B = free[b];
            K(a, b)              = stretches[A] * stretches[A] *
                      response.tangent[A][A][B][B] * stretches[B] *
                      stretches[B];
          }
          K(a, a) += 2 * tau;
        }
        K.gauss_jordan();
        K.vmult(dlog, r);
        // at most a factor of 2 per step
        for (unsigned int a = 0; a < n; ++a)
          stretches[free[a]] *= std::exp(
              std::max(-std::log(2.0), std::min(std::log(2.0), dlog[a])));
      }
      if (it == 50)
      {
        std::ostringstream state;
        state << stretches[0] << ", " << stretches[1] << ", " << stretches[2];
        throw InputError("Homogeneous loading of material '" + material.name() +
                         "' did not converge in 50 Newton iterations (last "
                         "stretches " +
                         state.str() + "). Fix: use a smaller stretch.");
      }
      const double off_diagonal = std::max({std::abs(response.stress[0][1]),
                                            std::abs(response.stress[0][2]),
                                            std::abs(response.stress[1][2])});
      if (off_diagonal > 1e-8 * std::max(response.stress.norm(), 1.0))
        throw InputError("Material '" + material.name() +
                         "' develops shear stress under axis-aligned "
                         "stretch: its fibre directions are not aligned with "
                         "the coordinate axes. Fix: align them with x, y or "
                         "z for homogeneous loading curves.");

      HomogeneousLoading::State state;
      state.stretches      = stretches;
      state.nominal_stress = stretches[0] * response.stress[0][0];
      state.cauchy_stress  = stretches[0] * stretches[0] *
                            response.stress[0][0] /
                            (stretches[0] * stretches[1] * stretches[2]);
      state.energy     = response.energy;
      state.iterations = it;
      return state;
    }
  } // namespace

  HomogeneousLoading::State
  HomogeneousLoading::uniaxial(const Material             &material,
                               const StructuralDirections &directions,
                               const double                stretch)
  {
    const double lateral = 1.0 / std::sqrt(stretch);
    return solve(material,
                 directions,
                 Tensor<1, 3>({stretch, lateral, lateral}),
                 {1, 2});
  }

  HomogeneousLoading::State
  HomogeneousLoading::equibiaxial(const Material             &material,
                                  const StructuralDirections &directions,
                                  const double                stretch)
  {
    return solve(material,
                 directions,
                 Tensor<1, 3>({stretch, stretch, 1.0 / (stretch * stretch)}),
                 {2});
  }
} // namespace softgrasp
