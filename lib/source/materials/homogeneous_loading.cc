#include <cmath>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/homogeneous_loading.h>
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
        double residual = 0, scale = std::abs(response.stress[0][0]);
        for (unsigned int a = 0; a < n; ++a)
          residual =
              std::max(residual, std::abs(response.stress[free[a]][free[a]]));
        scale = std::max(scale, material.initial_shear_modulus());
        // round-off in the stress grows with the bulk modulus
        if (residual <=
            std::max(1e-12 * scale, 1e-14 * material.bulk_modulus()))
          break;
        // dS_aa/dl_b = CC_aabb l_b
        FullMatrix<double> K(n, n);
        Vector<double>     r(n), dl(n);
        for (unsigned int a = 0; a < n; ++a)
        {
          r[a] = -response.stress[free[a]][free[a]];
          for (unsigned int b = 0; b < n; ++b)
            K(a, b) = response.tangent[free[a]][free[a]][free[b]][free[b]] *
                      stretches[free[b]];
        }
        K.gauss_jordan();
        K.vmult(dl, r);
        for (unsigned int a = 0; a < n; ++a)
        {
          // keep stretches positive: never step more than half way to 0
          double step = dl[a];
          if (stretches[free[a]] + step < 0.5 * stretches[free[a]])
            step = -0.5 * stretches[free[a]];
          stretches[free[a]] += step;
        }
      }
      if (it == 50)
        throw InputError("Homogeneous loading of material '" + material.name() +
                         "' did not converge in 50 Newton iterations. Fix: "
                         "use a smaller stretch.");
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
