// A Gmsh file's material ids (physical volumes 1 and 2) and boundary ids
// (physical surfaces 10: x = 0, 11: x = 2 cm, 12: y = 0, 13: z = 0) are
// kept, and the file's centimetres are scaled to metres: two hexahedra,
// both mapped to the same neo-Hookean material, are stretched uniaxially by
// 20 % through boundary 11 with rollers on 10, 12 and 13. The reaction force
// equals P_11(1.2) A_0 of the material library's homogeneous solution.
#include "../solver_factory.h"
#include "../tests.h"

#include <softgrasp/materials/homogeneous_loading.h>

using namespace softgrasp_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(8);
  const std::string material = R"(
    set Model = neo-Hookean
    set Density = 1000
    subsection neo-Hookean
      set Shear modulus = 2e4
    end
    subsection Volumetric
      set Poisson's ratio = 0.4
    end
)";
  std::string       prm =
      "subsection Mesh\n set Type = file\n subsection File\n"
      "  set File name = " SOURCE_DIR "/two_hexes.msh\n"
      "  set Scale = 0.01\n end\nend\n"
      "subsection Finite element\n set Polynomial degree = 1\n"
      " set Formulation = displacement\nend\n"
      "subsection Materials\n set Material ids = 1, 2\n"
      " subsection Material 1\n" +
      material +
      " end\n"
      " subsection Material 2\n" +
      material +
      " end\nend\n"
      "subsection Boundary conditions\n"
      " set Dirichlet boundary ids = 10, 11, 12, 13\n"
      " subsection Dirichlet boundary 10\n  set Components = x\n end\n"
      " subsection Dirichlet boundary 11\n  set Components = x\n"
      "  set Displacement = 0.004 * t; 0; 0\n end\n"
      " subsection Dirichlet boundary 12\n  set Components = y\n end\n"
      " subsection Dirichlet boundary 13\n  set Components = z\n end\n"
      "end\n"
      "subsection Time\n set Time step = 0.5\nend\n"
      "subsection Newton\n set Relative tolerance = 1e-12\nend\n"
      "subsection Linear solver\n set Type = direct\nend\n"
      "subsection Output\n set Directory = output-gmsh\n"
      " set Verbose = false\nend\n";
  auto solver = make_solver<3>(prm);
  solver->run();

  std::set<unsigned int> material_ids, boundary_ids;
  for (const auto &cell : solver->system()
                              .dof_handler()
                              .get_triangulation()
                              .active_cell_iterators())
  {
    material_ids.insert(cell->material_id());
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        boundary_ids.insert(cell->face(f)->boundary_id());
  }
  dealii::deallog << "material ids:";
  for (const auto id : material_ids)
    dealii::deallog << " " << id;
  dealii::deallog << std::endl << "boundary ids:";
  for (const auto id : boundary_ids)
    dealii::deallog << " " << id;
  dealii::deallog << std::endl;
  SG_CHECK(material_ids == (std::set<unsigned int>{1, 2}), "material ids kept");
  SG_CHECK(boundary_ids.count(10) && boundary_ids.count(11) &&
               boundary_ids.count(12) && boundary_ids.count(13),
           "boundary ids kept");

  const auto exact = softgrasp::HomogeneousLoading::uniaxial(
      solver->materials().get(1), {}, 1.2);
  const auto  &history = solver->history();
  const double force = history.value(history.rows.size() - 1, "reaction_11_x");
  const double expected = exact.nominal_stress * 0.01 * 0.01;
  dealii::deallog << "reaction " << force << " N, exact " << expected << " N"
                  << std::endl;
  SG_CHECK(close(force, expected, 1e-9), "uniaxial force on the imported mesh");
}
