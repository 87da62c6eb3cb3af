// Links softgrasp through its CMake package: evaluates a tissue preset, and
// finds the time steppers that the shared library registers by name (the
// run loop's layout, solvers/).
#include <cmath>
#include <iostream>
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/solvers/simulation.h>

int
main()
{
  const auto material = softgrasp::MaterialLibrary::create_preset("skin");
  const auto state    = softgrasp::HomogeneousLoading::uniaxial(
      *material, softgrasp::StructuralDirections(), 1.0);
  std::cout << material->summary() << std::endl;
  const std::string steppers =
      softgrasp::TimeStepperRegistry<3>::names_separated_by(", ");
  std::cout << "Time steppers: " << steppers << std::endl;
  dealii::ParameterHandler prm;
  softgrasp::Simulation<3>::declare_parameters(prm);
  prm.enter_subsection("Time");
  const bool default_integrator = prm.get("Integrator") == "quasi-static";
  prm.leave_subsection();
  // no load at stretch 1; the three built-in steppers, quasi-static first
  return std::abs(state.nominal_stress) < 1e-6 &&
                 steppers ==
                     "explicit dynamic, implicit dynamic, quasi-static" &&
                 default_integrator
             ? 0
             : 1;
}
