// Links softgrasp through its CMake package and evaluates a tissue preset.
#include <cmath>
#include <iostream>
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/materials/material_library.h>

int
main()
{
  const auto material = softgrasp::MaterialLibrary::create_preset("skin");
  const auto state    = softgrasp::HomogeneousLoading::uniaxial(
      *material, softgrasp::StructuralDirections(), 1.0);
  std::cout << material->summary() << std::endl;
  // no load at stretch 1
  return std::abs(state.nominal_stress) < 1e-6 ? 0 : 1;
}
