// Contact patch test: a flat rigid plate (a MuJoCo plane geom facing down)
// compresses a block by 10 % without friction, on randomly distorted
// meshes. The exact state is homogeneous uniaxial stress (3D) or plane
// strain (2D), so the contact pressure must be uniform to round-off:
//  - every closed node carries the same nominal pressure f_n / D_j
//    (D_j = int N_j dA, the dual mortar weight);
//  - in 3D that pressure is the nominal stress of the material library's
//    homogeneous uniaxial solution at stretch 0.9;
//  - the plate force balances the support reaction.
// Q1 and Q2, 2D and 3D; in 3D also with the plate as a triangle-mesh geom
// (a box read from an OBJ file) instead of a plane.
#include "../contact_factory.h"
#include "../material_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <fstream>
#include <softgrasp/materials/homogeneous_loading.h>

using namespace softgrasp_tests;

/// A 40 x 40 x 10 mm box as an OBJ file (a rigid platen as a mesh geom).
void
write_platen_obj()
{
  std::ofstream obj("platen.obj");
  for (unsigned int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? 0.02 : -0.02) << " " << (i & 2 ? 0.02 : -0.02)
        << " " << (i & 4 ? 0.005 : -0.005) << "\n";
  obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
}

template <int dim>
void
run(const unsigned int degree, const bool mesh_platen = false)
{
  const double stretch = 0.9;
  std::string  prm     = plate_compression_prm(dim, degree) +
                    "subsection Output\n set Directory = output-patch\nend\n";
  if (mesh_platen)
    prm += "subsection Rigid bodies\n subsection Body plate\n"
           "  set Trajectory = 0: 0, 0, 0.015, 1, 0, 0, 0; "
           "1: 0, 0, 0.014, 1, 0, 0, 0\n"
           "  subsection Geom face\n   set Type = mesh\n"
           "   set Mesh file = platen.obj\n   set Orientation = 1, 0, 0, 0\n"
           "  end\n end\nend\n";
  auto solver = make_solver<dim>(prm);
  solver->run();

  const auto [p_min, p_max] = closed_pressure_range(*solver);

  const auto   forces = solver->contact_output()->geom_forces(solver->system());
  const double plate  = forces[0][0].force[dim - 1];
  const auto  &history = solver->history();
  // the support's force on the body equals the body's force on the plate
  const double support = history.value(
      history.rows.size() - 1, dim == 3 ? "reaction_4_z" : "reaction_2_y");
  dealii::deallog << dim << "D Q" << degree
                  << (mesh_platen ? ", platen as an OBJ mesh" : "")
                  << ": nominal pressure " << 0.5 * (p_min + p_max)
                  << " Pa, spread " << ((p_max - p_min) / p_max < 1e-9)
                  << ", plate force " << plate << " N";
  SG_CHECK((p_max - p_min) / p_max < 1e-9, "uniform contact pressure");
  SG_CHECK_CLOSE(plate, support, 1e-9, 0, "plate force = support reaction");
  if (dim == 3)
  {
    const auto material =
        material_from_prm("set Model = neo-Hookean\nset Density = 1000\n"
                          "subsection neo-Hookean\nset Shear modulus = 1e4\n"
                          "end\nsubsection Volumetric\nset Poisson's ratio = "
                          "0.3\nend");
    const auto exact = softgrasp::HomogeneousLoading::uniaxial(
        *material, material->structural_directions({}), stretch);
    dealii::deallog << " (uniaxial solution " << -exact.nominal_stress
                    << " Pa)";
    SG_CHECK_CLOSE(p_max,
                   -exact.nominal_stress,
                   1e-9,
                   0,
                   "pressure = uniaxial nominal stress");
    SG_CHECK_CLOSE(
        plate, -exact.nominal_stress * 1e-4, 1e-9, 0, "plate force = P A_0");
  }
  dealii::deallog << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);
  for (const unsigned int degree : {1u, 2u})
  {
    run<2>(degree);
    run<3>(degree);
  }
  write_platen_obj();
  run<3>(1, true);
}
