// Throughput of the material library: stress + consistent tangent
// evaluations per second on one core, per model (and stress alone), at a
// fixed non-trivial deformation gradient, and the first Piola stress of the
// explicit solver's batch (deal.II's SIMD width) and block (explicit SIMD)
// paths. Results: doc/benchmarks.md.
//
//   build/benchmarks/material_throughput --benchmark_min_time=0.5

#include <benchmark/benchmark.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  const char *vol = "set Density = 1000\nsubsection Volumetric\nset Poisson's "
                    "ratio = 0.45\nend\n";

  Tensor<2, 3> deformation()
  {
    Tensor<2, 3> F;
    F[0][0] = 1.15;
    F[0][1] = 0.08;
    F[1][1] = 0.93;
    F[1][2] = -0.05;
    F[2][0] = 0.03;
    F[2][2] = 0.97;
    return F;
  }

  void
  run(benchmark::State &state, const std::string &fragment, const bool tangent)
  {
    const auto material =
        MaterialLibrary::create_from_fragment(fragment, "benchmark");
    const auto         d = material->structural_directions(Point<3>());
    const Tensor<2, 3> F = deformation();
    Material::Response r;
    for (auto _ : state)
    {
      material->evaluate_spatial(F, d, tangent, r);
      benchmark::DoNotOptimize(r);
    }
    state.SetItemsProcessed(state.iterations());
  }

  /// First Piola stress of a SIMD batch (the explicit solver's kernel);
  /// items are points, i.e. lanes.
  void run_batch(benchmark::State &state, const std::string &fragment)
  {
    const auto material =
        MaterialLibrary::create_from_fragment(fragment, "benchmark");
    constexpr unsigned int                  width = VectorizedDouble::size();
    const std::vector<StructuralDirections> d(
        width, material->structural_directions(Point<3>()));
    const Tensor<2, 3>             F1 = deformation();
    Tensor<2, 3, VectorizedDouble> F;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int lane = 0; lane < width; ++lane)
          F[i][j][lane] = F1[i][j] * (1.0 + 1e-3 * lane);
    Tensor<2, 3, VectorizedDouble> P;
    VectorizedDouble               energy;
    for (auto _ : state)
    {
      material->first_piola_batch(F, d.data(), width, P, energy);
      benchmark::DoNotOptimize(P);
      benchmark::DoNotOptimize(energy);
    }
    state.SetItemsProcessed(state.iterations() * width);
  }

  /// First Piola stress of a block of points with explicit SIMD (the
  /// explicit solver's vectorised kernel); items are points.
  void run_block(benchmark::State &state, const std::string &fragment)
  {
    const auto material =
        MaterialLibrary::create_from_fragment(fragment, "benchmark");
    const StructuralDirections d  = material->structural_directions(Point<3>());
    const Tensor<2, 3>         F1 = deformation();
    MaterialPointBlock         block;
    block.n_points               = point_block_size;
    block.isochoric.n_directions = d.n_directions;
    for (unsigned int k = 0; k < point_block_size; ++k)
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          block.F[3 * i + j][k] = F1[i][j] * (1.0 + 1e-3 * k);
      for (unsigned int a = 0; a < d.n_directions; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          block.isochoric.directions[3 * a + c][k] = d.direction[a][c];
    }
    for (auto _ : state)
    {
      material->first_piola_block(block);
      benchmark::DoNotOptimize(block.P);
      benchmark::DoNotOptimize(block.energy);
    }
    state.SetItemsProcessed(state.iterations() * point_block_size);
  }

  const std::vector<std::pair<std::string, std::string>> models = {
      {"neo-Hookean",
       std::string("set Model = neo-Hookean\n") + vol +
           "subsection neo-Hookean\nset Shear modulus = 1e4\nend"},
      {"Mooney-Rivlin",
       std::string("set Model = Mooney-Rivlin\n") + vol +
           "subsection Mooney-Rivlin\nset C10 = 4e3\nset C01 = 1e3\nend"},
      {"Ogden-3",
       std::string("set Model = Ogden\n") + vol +
           "subsection Ogden\nset Moduli = 6.3e3, 0.012e3, -0.1e3\nset "
           "Exponents "
           "= 1.3, 5.0, -2.0\nend"},
      {"Yeoh-3",
       std::string("set Model = Yeoh\n") + vol +
           "subsection Yeoh\nset Coefficients = 5e3, -1e2, 20\nend"},
      {"Veronda-Westmann",
       std::string("set Model = Veronda-Westmann\n") + vol +
           "subsection Veronda-Westmann\nset C1 = 2e3\nset C2 = 5\nend"},
      {"HGO-2-families",
       std::string("set Model = Holzapfel-Gasser-Ogden\n") + vol +
           "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = 1e4\nset k1 "
           "= "
           "5e4\nset k2 = 2\nset Number of fibre families = 2\nsubsection "
           "Fibre "
           "direction 1\nset Function expression = 1; 0.2; 0\nend\nsubsection "
           "Fibre direction 2\nset Function expression = 1; -0.2; "
           "0\nend\nend"}};

  const bool registered = []
  {
    for (const auto &[name, fragment] : models)
    {
      benchmark::RegisterBenchmark(
          ("stress+tangent/" + name).c_str(), run, fragment, true);
      benchmark::RegisterBenchmark(
          ("stress/" + name).c_str(), run, fragment, false);
      benchmark::RegisterBenchmark(
          ("first-Piola-batch/" + name).c_str(), run_batch, fragment);
      benchmark::RegisterBenchmark(
          ("first-Piola-block/" + name).c_str(), run_block, fragment);
    }
    return true;
  }();
} // namespace

BENCHMARK_MAIN();
