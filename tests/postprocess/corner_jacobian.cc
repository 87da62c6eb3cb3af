// The smallest J = det F at the cell vertices (CornerJacobian) of a
// displacement interpolated on [0, 1]^dim cut into 2^dim Q1 cells (on one
// or, in the mpirun=2 variant, two ranks): a homogeneous
// stretch F gives det F; moving the vertex (1, ..., 1) of the corner cell
// [1/2, 1]^dim to s in the cell's own unit coordinates (to (1 + s)/2 in
// every coordinate) gives, by hand, J = 2 s - 1 (2D) or 3 s - 2 (3D) at
// that vertex (the edge vectors there, in unit coordinates, are
// (s - 1) 1 1^T + I), negative for s = 0.45 (2D)
// and 0.6 (3D) while J stays positive at the 2 x 2 (x 2) Gauss points:
// the fold the solver's own check does not see.

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>
#include <softgrasp/postprocess/corner_jacobian.h>

using namespace dealii;
using namespace softgrasp;

/// u = (F - I) x, plus a shift of (s - 1) h in every component at the
/// vertex (1, ..., 1), the corner of a cell of size h.
template <int dim> class Displacement : public Function<dim>
{
public:
  Displacement(const Tensor<2, dim> &F, const double s, const double h)
      : Function<dim>(dim)
      , F(F)
      , shift((s - 1) * h)
  {
  }
  double value(const Point<dim> &p, const unsigned int c) const override
  {
    double corner = 1;
    for (unsigned int d = 0; d < dim; ++d)
      corner *= p[d];
    const Tensor<1, dim> u = F * p - p;
    return u[c] + (corner > 0.999 ? shift : 0.0);
  }

private:
  const Tensor<2, dim> F;
  const double         shift;
};

/// CornerJacobian of the displacement on [0, 1]^dim cut into 2^dim cells
/// of size h = 1/2, distributed over the ranks (so the corner cell's
/// vertex is found on one rank and broadcast); @p gauss_J: the smallest J
/// at the 2^dim Gauss points of all cells.
template <int dim>
CornerJacobian<dim>
on_cells(const Tensor<2, dim> &F, const double s, double &gauss_J)
{
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(tria, 0, 1);
  tria.refine_global(1);
  const FESystem<dim> fe(FE_Q<dim>(1), dim);
  DoFHandler<dim>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
  const MappingQ<dim>           mapping(1);
  TrilinosWrappers::MPI::Vector owned(dof_handler.locally_owned_dofs(),
                                      MPI_COMM_WORLD);
  VectorTools::interpolate(
      mapping, dof_handler, Displacement<dim>(F, s, 0.5), owned);
  TrilinosWrappers::MPI::Vector u(
      dof_handler.locally_owned_dofs(), relevant, MPI_COMM_WORLD);
  u = owned;
  FEValues<dim> fe_values(mapping, fe, QGauss<dim>(2), update_gradients);
  std::vector<Tensor<2, dim>> grad_u(fe_values.n_quadrature_points);
  gauss_J = 1e300;
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      fe_values.reinit(cell);
      fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(u,
                                                                      grad_u);
      for (const auto &g : grad_u)
        gauss_J =
            std::min(gauss_J, determinant(unit_symmetric_tensor<dim>() + g));
    }
  gauss_J = Utilities::MPI::min(gauss_J, MPI_COMM_WORLD);
  return smallest_corner_jacobian(mapping, dof_handler, u, MPI_COMM_WORLD);
}

template <int dim>
void
check(const double s)
{
  Tensor<2, dim> F;
  const double   stretch[3] = {1.2, 0.7, 0.9};
  double         det        = 1;
  for (unsigned int d = 0; d < dim; ++d)
  {
    F[d][d] = stretch[d];
    det *= stretch[d];
  }
  double     gauss_J;
  const auto homogeneous = on_cells<dim>(F, 1, gauss_J);
  SG_CHECK_CLOSE(homogeneous.J, det, 1e-12, 0, "homogeneous: det F");
  SG_CHECK(!homogeneous.folded(), "homogeneous: not folded");

  const auto folded = on_cells<dim>(unit_symmetric_tensor<dim>(), s, gauss_J);
  SG_CHECK(gauss_J > 0, "folded corner: positive at the Gauss points");
  const double expected = dim == 2 ? 2 * s - 1 : 3 * s - 2;
  SG_CHECK_CLOSE(folded.J, expected, 1e-12, 0, "folded corner: J by hand");
  SG_CHECK(folded.folded(), "folded corner: folded");
  for (unsigned int d = 0; d < dim; ++d)
    SG_CHECK_CLOSE(folded.position[d], 1, 0, 1e-12, "at the moved vertex");
  deallog << dim << "D: homogeneous J = " << homogeneous.J
          << ", vertex moved to s = " << s << ": J = " << folded.J << " at "
          << folded.position << " (smallest J at the Gauss points " << gauss_J
          << ")" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  check<2>(0.45);
  check<3>(0.6);
  deallog << "OK" << std::endl;
}
