// The vectorised internal-force kernel (explicit SIMD over cells, own sum
// factorisation, Material::first_piola_block()) against the reference
// kernel (deal.II's FEEvaluation, the material library's batch path), on
// randomly distorted meshes with every material model of the library at
// once (material id by cell, so that every model fills SIMD batches):
// Q1 and Q2, 2D (plane strain) and 3D, displacement and mean-dilatation
// (u-p-J) forms. Forces, strain energy and min det F agree to 1e-12, also
// for a displacement that inverts elements (inverted points carry no
// stress in both).
#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>
#include <softgrasp/explicit/internal_force_operator.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  template <int dim> class Displacement : public Function<dim>
  {
  public:
    /// @p inverting adds u_x = -1.5 x^2: F_xx = 1 - 3 x < 0 for x > 1/3.
    explicit Displacement(const bool inverting)
        : Function<dim>(dim)
        , inverting(inverting)
    {
    }
    double value(const Point<dim> &p, const unsigned int c) const override
    {
      return 0.08 * std::sin(1.3 * p[0] + 0.7 * c) * std::cos(0.9 * p[1]) +
             0.05 * p[(c + 1) % dim] + (dim == 3 ? 0.03 * p[2] * p[c] : 0) +
             (inverting && c == 0 ? -1.5 * p[0] * p[0] : 0);
    }
    const bool inverting;
  };

  /// The operator's volumetric form for a mean-dilatation flag.
  template <int dim>
  typename InternalForceOperator<dim>::Dilatation
  dilatation(const bool mean_dilatation)
  {
    using D = typename InternalForceOperator<dim>::Dilatation;
    return mean_dilatation ? D::element_constant : D::pointwise;
  }

  template <int dim>
  void compare(const unsigned int     degree,
               const bool             mean_dilatation,
               const bool             inverting,
               const MaterialLibrary &materials)
  {
    using Operator = InternalForceOperator<dim>;
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, dim == 2 ? 11 : 5, 0, 1);
    GridTools::distort_random(0.25, tria, true, 3);
    const unsigned int n_materials = materials.material_ids().size();
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->active_cell_index() % n_materials);

    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dofs(tria);
    dofs.distribute_dofs(fe);
    const MappingQ<dim>       mapping(1);
    AffineConstraints<double> none;
    none.close();
    const Operator                             vectorized(mapping,
                              dofs,
                              none,
                              materials,
                              dilatation<dim>(mean_dilatation),
                              Operator::Kernel::vectorized);
    const Operator                             reference(mapping,
                             dofs,
                             none,
                             materials,
                             dilatation<dim>(mean_dilatation),
                             Operator::Kernel::reference);
    LinearAlgebra::distributed::Vector<double> u, f, f_reference;
    vectorized.initialize_dof_vector(u);
    vectorized.initialize_dof_vector(f);
    vectorized.initialize_dof_vector(f_reference);
    VectorTools::interpolate(mapping, dofs, Displacement<dim>(inverting), u);
    const auto result  = vectorized.apply(u, f);
    const auto result0 = reference.apply(u, f_reference);

    const double scale = f_reference.linfty_norm();
    f -= f_reference;
    const double force_error = f.linfty_norm() / scale;
    // (equal when both overflow: near-flat points of the exponential
    // models make Psi infinite in both kernels)
    const double energy_error = result.energy == result0.energy
                                    ? 0.0
                                    : std::abs(result.energy - result0.energy) /
                                          std::abs(result0.energy);
    const double J_error      = std::abs(result.min_J - result0.min_J);
    dealii::deallog << dim << "D Q" << degree
                    << (mean_dilatation ? " mean dilatation" : " displacement")
                    << (inverting ? ", inverted elements" : "") << ", "
                    << dofs.n_dofs() << " dofs, " << n_materials
                    << " materials: forces agree to 1e-12: "
                    << (force_error < 1e-12)
                    << ", energy: " << (energy_error < 1e-12)
                    << ", min J: " << (J_error < 1e-12)
                    << ", inverted: " << (result0.min_J <= 0) << std::endl;
    SG_CHECK(force_error < 1e-12, "vectorised forces equal the reference");
    SG_CHECK(energy_error < 1e-12, "vectorised energy equals the reference");
    SG_CHECK(J_error < 1e-12, "vectorised min J equals the reference");
    SG_CHECK(inverting == (result0.min_J <= 0),
             "the inverting displacement inverts elements, the other not");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  std::vector<std::string> fragments;
  for (const auto &[name, fragment] :
       softgrasp_tests::model_fragments("Simo-Taylor", "0.45"))
    fragments.push_back(fragment);
  // the other volumetric energies too
  fragments.push_back(
      softgrasp_tests::model_fragments("quadratic", "0.49")[0].second);
  fragments.push_back(
      softgrasp_tests::model_fragments("logarithmic", "0.4999")[3].second);
  const MaterialLibrary materials =
      softgrasp_tests::library_from_prm(fragments);
  for (const unsigned int degree : {1, 2})
    for (const bool mean_dilatation : {false, true})
    {
      compare<2>(degree, mean_dilatation, false, materials);
      compare<3>(degree, mean_dilatation, false, materials);
    }
  compare<3>(1, false, true, materials);
  compare<3>(2, true, true, materials);
}
