// The batch (SIMD) stress path of the material library equals the scalar
// one: for every model (neo-Hookean, Mooney-Rivlin, Ogden, Yeoh,
// Veronda-Westmann, HGO with one and two fibre families) and every
// volumetric energy, Material::first_piola_batch() gives P = F S and Psi of
// evaluate_material() in every lane, for random deformations up to 40 %
// strain, with fewer active lanes than the SIMD width too (padding lanes
// give zero). Both paths share one formula per model
// (InvariantModelImplementation); the models without a batch formula fall
// back to lane-by-lane evaluation.
#include "../material_factory.h"
#include "../tests.h"

#include <random>

using namespace softgrasp;
using dealii::Tensor;

int
main()
{
  softgrasp_tests::initlog();
  constexpr unsigned int                 width = VectorizedDouble::size();
  std::mt19937                           random(3);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  unsigned int                           checked = 0;
  for (const std::string volumetric :
       {"quadratic", "logarithmic", "Simo-Taylor"})
    for (const auto &[name, fragment] :
         softgrasp_tests::model_fragments(volumetric, "0.45"))
    {
      const auto material = softgrasp_tests::material_from_prm(fragment);
      double     worst    = 0;
      for (unsigned int trial = 0; trial < 20; ++trial)
      {
        const unsigned int                n_lanes = 1 + trial % width;
        Tensor<2, 3, VectorizedDouble>    F;
        std::vector<Tensor<2, 3>>         Fs(width);
        std::vector<StructuralDirections> directions(width);
        for (unsigned int lane = 0; lane < width; ++lane)
        {
          Tensor<2, 3> f = dealii::unit_symmetric_tensor<3>();
          if (lane < n_lanes)
            f = softgrasp_tests::random_deformation(random, u);
          Fs[lane]         = f;
          directions[lane] = material->structural_directions(
              dealii::Point<3>(u(random), u(random), u(random)));
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              F[i][j][lane] = f[i][j];
        }
        Tensor<2, 3, VectorizedDouble> P;
        VectorizedDouble               energy;
        material->first_piola_batch(F, directions.data(), n_lanes, P, energy);
        for (unsigned int lane = 0; lane < width; ++lane)
        {
          Material::Response response;
          material->evaluate_material(
              Fs[lane], directions[lane], false, response);
          const Tensor<2, 3> expected =
              lane < n_lanes
                  ? Tensor<2, 3>(Fs[lane] * Tensor<2, 3>(response.stress))
                  : Tensor<2, 3>();
          const double scale = std::max(1.0, expected.norm());
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              worst = std::max(
                  worst, std::abs(P[i][j][lane] - expected[i][j]) / scale);
          const double W = lane < n_lanes ? response.energy : 0.0;
          worst          = std::max(
              worst, std::abs(energy[lane] - W) / std::max(1.0, std::abs(W)));
          ++checked;
        }
      }
      dealii::deallog << name << ", " << volumetric
                      << ": batch equals scalar to 1e-12: " << (worst < 1e-12)
                      << std::endl;
      SG_CHECK(worst < 1e-12, "batch stress equals scalar stress");
    }
  SG_CHECK(checked > 0, "lanes checked");
}
