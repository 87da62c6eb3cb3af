// The block stress path of the explicit solver's vectorised kernel
// (Material::first_piola_block(), explicit SIMD over points) equals the
// scalar reference: for every model (neo-Hookean, Mooney-Rivlin, Ogden,
// Yeoh, Veronda-Westmann, HGO with one and two fibre families) and every
// volumetric energy, P = F S and Psi of evaluate_material() at every point,
// and with a given pressure those of evaluate_material_with_pressure()
// (the mean-dilatation form, isochoric energy only), for random
// deformations up to 40 % strain and blocks of 1 to 64 points (so that
// the padding past the last point is exercised at every SIMD width).
#include "../material_factory.h"
#include "../tests.h"

#include <random>

using namespace softgrasp;
using dealii::Tensor;

namespace
{
  /// Largest relative difference of the block path from the scalar one on
  /// one random block of @p n points.
  double block_error(const Material    &material,
                     const unsigned int n,
                     const bool         given_pressure,
                     std::mt19937      &random)
  {
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    MaterialPointBlock                     block;
    block.n_points       = n;
    block.given_pressure = given_pressure;
    std::vector<Tensor<2, 3>>         Fs(n);
    std::vector<StructuralDirections> directions(n);
    std::vector<double>               pressures(n);
    for (unsigned int k = 0; k < n; ++k)
    {
      const Tensor<2, 3> f = softgrasp_tests::random_deformation(random, u);
      Fs[k]                = f;
      directions[k]        = material.structural_directions(
          dealii::Point<3>(u(random), u(random), u(random)));
      pressures[k] = 4e4 * u(random);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          block.F[3 * i + j][k] = f[i][j];
      block.pressure[k]            = pressures[k];
      block.isochoric.n_directions = directions[k].n_directions;
      for (unsigned int a = 0; a < directions[k].n_directions; ++a)
        for (unsigned int d = 0; d < 3; ++d)
          block.isochoric.directions[3 * a + d][k] =
              directions[k].direction[a][d];
    }
    material.first_piola_block(block);
    double worst = 0;
    for (unsigned int k = 0; k < n; ++k)
    {
      Material::Response r;
      if (given_pressure)
        material.evaluate_material_with_pressure(
            Fs[k], directions[k], pressures[k], false, r);
      else
        material.evaluate_material(Fs[k], directions[k], false, r);
      const Tensor<2, 3> P     = Fs[k] * Tensor<2, 3>(r.stress);
      const double       scale = std::max(1.0, P.norm());
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          worst = std::max(worst,
                           std::abs(block.P[3 * i + j][k] - P[i][j]) / scale);
      worst = std::max(worst,
                       std::abs(block.energy[k] - r.energy) /
                           std::max(1.0, std::abs(r.energy)));
    }
    return worst;
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  std::mt19937 random(5);
  for (const std::string volumetric :
       {"quadratic", "logarithmic", "Simo-Taylor"})
    for (const auto &[name, fragment] :
         softgrasp_tests::model_fragments(volumetric, "0.45"))
    {
      const auto material = softgrasp_tests::material_from_prm(fragment);
      double     worst = 0, worst_pressure = 0;
      for (unsigned int n = 1; n <= point_block_size; n += 7)
      {
        worst = std::max(worst, block_error(*material, n, false, random));
        worst_pressure =
            std::max(worst_pressure, block_error(*material, n, true, random));
      }
      dealii::deallog << name << ", " << volumetric
                      << ": block equals scalar to 1e-12: " << (worst < 1e-12)
                      << ", with a given pressure: " << (worst_pressure < 1e-12)
                      << std::endl;
      SG_CHECK(worst < 1e-12, "block stress equals scalar stress");
      SG_CHECK(worst_pressure < 1e-12,
               "block stress with pressure equals scalar stress");
    }
}
