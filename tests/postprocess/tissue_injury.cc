// The per-tissue injury assessment against an analytic field (runs on 1 and
// 2 MPI ranks): a 10 mm cube of two tissues (z below and above 5 mm) with
// u = (-a x^2, b y^2, 0), which Q2 elements represent exactly, so that
// lambda_x = 1 - 2 a x (compression growing along x) and lambda_y =
// 1 + 2 b y (stretch growing along y). Analytic values: e_min = -2 a L at
// x = L, e_max = 2 b L at y = L; the volume compressed beyond t is
// L^2 (L - t / 2a) / 2 per tissue, the volume stretched beyond s is
// L^2 (L - s / 2b) / 2. The quadrature-point measures converge to them:
// the extremes sit at the Gauss point nearest the face (O(h)), the
// volumes are exact once a cell face falls on the threshold's plane and
// otherwise within one cell layer.

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/postprocess/tissue_injury.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  constexpr double L = 0.01, a = 25, b = 10; // m, 1/m, 1/m

  class Field : public Function<3>
  {
  public:
    Field()
        : Function<3>(3)
    {
    }
    double value(const Point<3> &X, const unsigned int c) const override
    {
      return c == 0 ? -a * X[0] * X[0] : c == 1 ? b * X[1] * X[1] : 0.0;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const MPI_Comm comm = MPI_COMM_WORLD;

  ParameterHandler prm;
  MaterialLibrary::declare_parameters(prm);
  MaterialLibrary::parse_input_from_string(
      prm,
      "subsection Materials\nset Material ids = 1, 2\nsubsection Material "
      "1\nset Preset = skin\nend\nsubsection Material 2\nset Preset = "
      "subcutaneous fat\nend\nend\n");
  MaterialLibrary materials;
  materials.parse_parameters(prm);

  // Thresholds through the parameter file, as a user sets them.
  ParameterHandler thresholds_prm;
  thresholds_prm.enter_subsection("Study");
  InjuryThresholds::declare_parameters(thresholds_prm);
  thresholds_prm.leave_subsection();
  InjuryThresholds thresholds;
  {
    ParameterReader reader;
    reader.read_string(thresholds_prm,
                       "subsection Study\nsubsection Injury assessment\nset "
                       "Compressive strain thresholds = 0.4, 0.65\nset "
                       "Tensile strain thresholds = 0.1, 0.13\nend\nend\n",
                       "test");
    thresholds_prm.enter_subsection("Study");
    thresholds.parse_parameters(thresholds_prm, "Study");
    thresholds_prm.leave_subsection();
  }
  const double V_compressed   = L * L * (L - 0.4 / (2 * a)) / 2;
  const double V_stretched[2] = {L * L * (L - 0.1 / (2 * b)) / 2,
                                 L * L * (L - 0.13 / (2 * b)) / 2};

  double last_error = 1;
  for (unsigned int refinement = 1; refinement <= 3; ++refinement)
  {
    parallel::distributed::Triangulation<3> tria(comm);
    GridGenerator::hyper_cube(tria, 0, L);
    tria.refine_global(refinement);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[2] < L / 2 ? 1 : 2);
    const double h = L / (1 << refinement);

    FESystem<3>   fe(FE_Q<3>(2), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    LinearAlgebra::distributed::Vector<double> u(
        dof_handler.locally_owned_dofs(), relevant, comm);
    MappingQ<3> mapping(1);
    VectorTools::interpolate(mapping, dof_handler, Field(), u);
    u.update_ghost_values();

    TissueInjury<3> injury;
    injury.compute_strains(dof_handler, mapping, u, materials, thresholds);
    SG_CHECK(injury.tissues().size() == 2, "two tissues");
    double error = 0;
    for (const auto &t : injury.tissues())
    {
      SG_CHECK_CLOSE(t.volume, L * L * L / 2, 1e-12, 0, "tissue volume");
      // extremes at the Gauss point nearest the face x = L (y = L)
      SG_CHECK(std::abs(t.e_min.value + 2 * a * L) < 2 * a * h,
               "e_min within a cell of -2 a L");
      SG_CHECK(std::abs(t.e_max.value - 2 * b * L) < 2 * b * h,
               "e_max within a cell of 2 b L");
      SG_CHECK_CLOSE(t.e_min.value,
                     -2 * a * t.e_min.reference[0],
                     1e-10,
                     1e-12,
                     "e_min = -2 a X at its location");
      SG_CHECK_CLOSE(t.e_min.current[0],
                     t.e_min.reference[0] -
                         a * std::pow(t.e_min.reference[0], 2),
                     1e-10,
                     1e-14,
                     "deformed position x = X + u");
      SG_CHECK(t.e_min.nearest_geom.empty(), "no rigid bodies");
      // the volumes
      SG_CHECK(t.volume_compressed[1] == 0, "nothing compressed beyond 0.65");
      SG_CHECK_CLOSE(t.volume_stretched[0],
                     V_stretched[0],
                     1e-10,
                     0,
                     "stretched beyond 0.1: exact (y = 5 mm is a face)");
      error = std::max(
          {error,
           std::abs(t.volume_compressed[0] - V_compressed) / V_compressed,
           std::abs(t.volume_stretched[1] - V_stretched[1]) / V_stretched[1]});
      SG_CHECK(std::abs(t.volume_compressed[0] - V_compressed) <
                   L * L * h / 2 + 1e-15,
               "compressed beyond 0.4 within one cell layer");
    }
    dealii::deallog << "refinement " << refinement << ": e_min "
                    << injury.tissues()[0].e_min.value << " (exact -0.5), "
                    << "e_max " << injury.tissues()[0].e_max.value
                    << " (exact 0.2), largest volume error " << error
                    << std::endl;
    if (refinement == 3 && Utilities::MPI::this_mpi_process(comm) == 0)
    {
      // The table's Green-Lagrange and logarithmic strains at the extremes'
      // locations: lambda = 1 + 2 b Y (stretch) and 1 - 2 a X (compression).
      injury.write_csv("injury.csv", "pressure.csv");
      std::ifstream in("injury.csv");
      std::string   header, row;
      std::getline(in, header);
      std::getline(in, row);
      const auto names  = Utilities::split_string_list(header, ',');
      const auto values = Utilities::split_string_list(row, ',');
      const auto column = [&](const std::string &name)
      {
        const auto it = std::find(names.begin(), names.end(), name);
        SG_CHECK(it != names.end(), "the column exists");
        return std::stod(values[it - names.begin()]);
      };
      const auto  &t     = injury.tissues()[0];
      const double l_max = 1 + 2 * b * t.e_max.reference[1];
      const double l_min = 1 - 2 * a * t.e_min.reference[0];
      bool         exact = true;
      for (const auto &[name, value] :
           std::vector<std::pair<std::string, double>>{
               {"E_GL_max", (l_max * l_max - 1) / 2},
               {"E_GL_min", (l_min * l_min - 1) / 2},
               {"log_strain_max", std::log(l_max)},
               {"log_strain_min", std::log(l_min)}})
        exact = exact && std::abs(column(name) - value) < 1e-7;
      dealii::deallog << "CSV: Green-Lagrange and logarithmic strains of the "
                         "extremes equal their closed forms: "
                      << exact << std::endl;
      SG_CHECK(exact, "strain measures in the table");
    }
    SG_CHECK(error <= last_error, "the volume errors do not grow");
    last_error = error;
  }
  SG_CHECK(last_error < 0.1, "volumes within 10 % on the finest mesh");

  // Bad thresholds stop with the parameter's path.
  try
  {
    ParameterReader reader;
    reader.read_string(thresholds_prm,
                       "subsection Study\nsubsection Injury assessment\nset "
                       "Compressive strain thresholds = 1.5\nend\nend\n",
                       "test");
    softgrasp_tests::fail(
        "a compressive strain of 1.5 is refused", __FILE__, __LINE__);
  }
  catch (const std::exception &e)
  {
    dealii::deallog << "compressive strain 1.5 refused: "
                    << (std::string(e.what()).find("Compressive strain") !=
                        std::string::npos)
                    << std::endl;
  }
}
