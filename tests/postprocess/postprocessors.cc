// The DataOut postprocessors and the per-material-id extremes on a
// distributed mesh (runs on 1 and 2 MPI ranks) with two materials and a
// homogeneous deformation u = (F - I) X, which Q1 elements represent
// exactly: every point must show the analytic principal strains, J,
// and the Cauchy/von Mises stress of its material. The VTU output is
// written; the extremes table must equal the analytic values.

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/postprocess/material_id_extremes.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/postprocess/strain_postprocessor.h>
#include <softgrasp/postprocess/stress_postprocessor.h>

using namespace dealii;
using namespace softgrasp;

class HomogeneousDisplacement : public Function<3>
{
public:
  explicit HomogeneousDisplacement(const Tensor<2, 3> &F)
      : Function<3>(3)
      , F(F)
  {
  }
  double value(const Point<3> &X, const unsigned int c) const override
  {
    return (F * X)[c] - X[c];
  }

private:
  const Tensor<2, 3> F;
};

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const MPI_Comm comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<3> tria(comm);
  GridGenerator::hyper_cube(tria, 0, 0.01); // a 10 mm cube
  tria.refine_global(2);
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[2] < 0.005 ? 1 : 2);

  ParameterHandler prm;
  MaterialLibrary::declare_parameters(prm);
  MaterialLibrary::parse_input_from_string(
      prm,
      "subsection Materials\nset Material ids = 1, 2\nsubsection Material "
      "1\nset "
      "Preset = skin\nend\nsubsection Material 2\nset Preset = subcutaneous "
      "fat\nend\nend\n");
  MaterialLibrary materials;
  materials.parse_parameters(prm);

  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
  LinearAlgebra::distributed::Vector<double> u(
      dof_handler.locally_owned_dofs(), relevant, comm);
  Tensor<2, 3> F;
  F[0][0] = 1.2;
  F[0][1] = 0.1;
  F[1][1] = 0.9;
  F[2][2] = 0.95;
  F[2][0] = -0.05;
  VectorTools::interpolate(dof_handler, HomogeneousDisplacement(F), u);
  u.update_ghost_values();

  const PrincipalStrains expected = PrincipalStrains::compute(F);
  MaterialIdExtremes<3>  extremes;
  extremes.compute(dof_handler, u, materials, QGauss<3>(2));
  for (const auto &[id, e] : extremes.extremes())
  {
    const Material &m  = materials.get(id);
    const double    vm = von_mises_stress(m.cauchy_stress(F, {}));
    SG_CHECK_CLOSE(e.e_max, expected.e_max(), 1e-10, 1e-12, "e_max");
    SG_CHECK_CLOSE(e.e_min, expected.e_min(), 1e-10, 1e-12, "e_min");
    SG_CHECK_CLOSE(e.J_min, expected.J, 1e-10, 0, "J_min");
    SG_CHECK_CLOSE(e.J_max, expected.J, 1e-10, 0, "J_max");
    SG_CHECK_CLOSE(e.von_mises_max, vm, 1e-8, 0, "von Mises");
    SG_CHECK(e.n_points == 32 * 8, "each material has 32 cells x 8 points");
  }
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    extremes.table(materials).write_text(softgrasp_tests::logfile());

  // DataOut with both postprocessors, checked at the output points.
  StrainPostprocessor<3> strain;
  StressPostprocessor<3> stress(materials);
  DataOut<3>             data_out;
  data_out.attach_dof_handler(dof_handler);
  data_out.add_data_vector(u, strain);
  data_out.add_data_vector(u, stress);
  data_out.build_patches();
  data_out.write_vtu_with_pvtu_record("./", "postprocessors", 0, comm, 2);

  // Spot-check the postprocessors directly on one point.
  DataPostprocessorInputs::Vector<3> inputs;
  inputs.solution_gradients.assign(1, std::vector<Tensor<1, 3>>(3));
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      inputs.solution_gradients[0][i][j] = F[i][j] - (i == j);
  inputs.evaluation_points = {Point<3>(0.001, 0.001, 0.001)};
  bool has_skin_cell       = false;
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned() && cell->material_id() == 1)
    {
      inputs.template set_cell<3>(cell);
      has_skin_cell = true;
      break;
    }
  std::vector<Vector<double>> strain_out(1, Vector<double>(11)),
      stress_out(1, Vector<double>(11));
  strain.evaluate_vector_field(inputs, strain_out);
  SG_CHECK_CLOSE(strain_out[0][0], expected.e_max(), 1e-12, 0, "e_max output");
  SG_CHECK_CLOSE(strain_out[0][2], expected.e_min(), 1e-12, 0, "e_min output");
  SG_CHECK_CLOSE(strain_out[0][3], expected.J, 1e-12, 0, "J output");
  // Green-Lagrange and logarithmic principal strains of the same stretches
  const double l_max = 1 + expected.e_max(), l_min = 1 + expected.e_min();
  SG_CHECK_CLOSE(
      strain_out[0][7], (l_max * l_max - 1) / 2, 1e-12, 0, "E_GL_max output");
  SG_CHECK_CLOSE(
      strain_out[0][8], (l_min * l_min - 1) / 2, 1e-12, 0, "E_GL_min output");
  SG_CHECK_CLOSE(
      strain_out[0][9], std::log(l_max), 1e-12, 0, "log_strain_max output");
  SG_CHECK_CLOSE(
      strain_out[0][10], std::log(l_min), 1e-12, 0, "log_strain_min output");
  if (has_skin_cell)
  {
    stress.evaluate_vector_field(inputs, stress_out);
    const auto sigma = materials.get(1).cauchy_stress(F, {});
    SG_CHECK_CLOSE(stress_out[0][1], sigma[0][1], 1e-12, 0, "sigma_01 output");
    SG_CHECK_CLOSE(stress_out[0][9],
                   von_mises_stress(sigma),
                   1e-12,
                   0,
                   "von Mises output");
  }
  deallog << "postprocessor outputs equal the analytic values" << std::endl;
  deallog << "OK" << std::endl;
}
