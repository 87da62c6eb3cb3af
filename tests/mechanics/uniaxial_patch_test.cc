// Patch test: uniaxial stretch (lambda = 1.5) of a block on a randomly
// distorted mesh, with symmetry (roller) conditions on three faces and the
// stretch prescribed on the face x = L. The exact solution is homogeneous,
// so every element type must reproduce it to round-off on any mesh:
//  - the reaction force equals P_11 A_0, with P_11 the nominal stress of the
//    material library's homogeneous uniaxial solution;
//  - the lateral displacements equal (lambda_2 - 1) W and (lambda_3 - 1) H.
// All isotropic models and a fibre-reinforced HGO material (fibres along
// x), in the displacement and mixed u-p-J formulations, Q1 and Q2.
#include "../material_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/materials/homogeneous_loading.h>

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);

  const double L = 0.02, W = 0.01, H = 0.01, stretch = 1.5;
  auto         materials = model_fragments("Simo-Taylor", "0.45");
  materials.resize(5); // the isotropic models
  materials.emplace_back(
      "HGO, fibres along x",
      "set Model = Holzapfel-Gasser-Ogden\nset Density = 1000\n"
      "subsection Volumetric\nset Poisson's ratio = 0.45\nend\n"
      "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = 1e4\n"
      "set k1 = 5e4\nset k2 = 2\nset Dispersion kappa = 0.1\n"
      "subsection Fibre direction 1\nset Function expression = 1; 0; 0\n"
      "end\nend");

  for (const auto &[name, fragment] : materials)
  {
    const auto material = material_from_prm(fragment);
    const auto exact    = softgrasp::HomogeneousLoading::uniaxial(
        *material, material->structural_directions({}), stretch);
    for (const std::string formulation : {"displacement", "mixed u-p-J"})
      for (const unsigned int degree : {1u, 2u})
      {
        std::ostringstream prm;
        prm << "subsection Mesh\n set Type = block\n set Distortion = 0.25\n"
            << " subsection Block\n  set Lower corner = 0, 0, 0\n"
            << "  set Upper corner = " << L << ", " << W << ", " << H
            << "\n  set Subdivisions = 3, 2, 2\n end\nend\n"
            << "subsection Finite element\n set Polynomial degree = " << degree
            << "\n set Formulation = " << formulation << "\nend\n"
            << "subsection Materials\n set Material ids = 0\n"
            << " subsection Material 0\n"
            << fragment << "\n end\nend\n"
            << "subsection Boundary conditions\n"
            << " set Dirichlet boundary ids = 0, 1, 2, 4\n"
            << " subsection Dirichlet boundary 0\n  set Components = x\n end\n"
            << " subsection Dirichlet boundary 2\n  set Components = y\n end\n"
            << " subsection Dirichlet boundary 4\n  set Components = z\n end\n"
            << " subsection Dirichlet boundary 1\n  set Components = x\n"
            << "  set Displacement = " << (stretch - 1) * L << " * t; 0; 0\n"
            << " end\nend\n"
            << "subsection Time\n set End time = 1\n set Time step = "
               "0.25\nend\n"
            << "subsection Newton\n set Relative tolerance = 1e-12\nend\n"
            << "subsection Linear solver\n set Type = direct\nend\n"
            << "subsection Output\n set Directory = output-patch\n"
            << " set VTU interval = 0\n set Verbose = false\n"
            << " set Monitor points = " << L << ", " << W << ", " << H
            << "\nend\n";
        auto solver = make_solver<3>(prm.str());
        solver->run();
        const auto       &history  = solver->history();
        const std::size_t last     = history.rows.size() - 1;
        const double      force    = history.value(last, "reaction_1_x");
        const double      uy       = history.value(last, "u0_y");
        const double      uz       = history.value(last, "u0_z");
        const double      expected = exact.nominal_stress * W * H;
        const double      e_force  = std::abs(force - expected) / expected;
        const double      e_y = std::abs(uy - (exact.stretches[1] - 1) * W) / W;
        const double      e_z = std::abs(uz - (exact.stretches[2] - 1) * H) / H;
        dealii::deallog << name << ", Q" << degree << " " << formulation
                        << ": F = " << force << " N (exact " << expected
                        << " N), lateral stretch " << 1 + uy / W << " (exact "
                        << exact.stretches[1] << ")" << std::endl;
        SG_CHECK(e_force < 1e-9, "reaction force equals P_11 A_0");
        SG_CHECK(e_y < 1e-9 && e_z < 1e-9, "lateral contraction exact");
      }
  }
}
