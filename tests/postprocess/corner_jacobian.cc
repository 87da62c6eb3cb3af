// The smallest J = det F at the cell vertices (CornerJacobian) of a
// displacement interpolated on one Q1 cell [0, 1]^dim: a homogeneous
// stretch F gives det F; moving the vertex (1, ..., 1) to (s, ..., s)
// gives, by hand, J = 2 s - 1 (2D) or 3 s - 2 (3D) at that vertex (the
// edge vectors there are (s - 1) 1 1^T + I), negative for s = 0.45 (2D)
// and 0.6 (3D) while J stays positive at the 2 x 2 (x 2) Gauss points:
// the fold the solver's own check does not see.

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
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

/// u = (F - I) x, plus a shift of (s - 1) in every component at the
/// vertex (1, ..., 1).
template <int dim> class Displacement : public Function<dim>
{
public:
  Displacement(const Tensor<2, dim> &F, const double s)
      : Function<dim>(dim)
      , F(F)
      , s(s)
  {
  }
  double value(const Point<dim> &p, const unsigned int c) const override
  {
    double corner = 1;
    for (unsigned int d = 0; d < dim; ++d)
      corner *= p[d];
    const Tensor<1, dim> u = F * p - p;
    return u[c] + (corner > 0.999 ? s - 1 : 0.0);
  }

private:
  const Tensor<2, dim> F;
  const double         s;
};

/// CornerJacobian of the displacement; @p gauss_J: the smallest J at the
/// 2^dim Gauss points.
template <int dim>
CornerJacobian<dim>
on_one_cell(const Tensor<2, dim> &F, const double s, double &gauss_J)
{
  Triangulation<dim> tria;
  GridGenerator::hyper_cube(tria, 0, 1);
  const FESystem<dim> fe(FE_Q<dim>(1), dim);
  DoFHandler<dim>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<dim>           mapping(1);
  TrilinosWrappers::MPI::Vector u(complete_index_set(dof_handler.n_dofs()),
                                  MPI_COMM_WORLD);
  VectorTools::interpolate(mapping, dof_handler, Displacement<dim>(F, s), u);
  FEValues<dim> fe_values(mapping, fe, QGauss<dim>(2), update_gradients);
  fe_values.reinit(dof_handler.begin_active());
  std::vector<Tensor<2, dim>> grad_u(fe_values.n_quadrature_points);
  fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(u, grad_u);
  gauss_J = 1e300;
  for (const auto &g : grad_u)
    gauss_J = std::min(gauss_J, determinant(unit_symmetric_tensor<dim>() + g));
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
  const auto homogeneous = on_one_cell<dim>(F, 1, gauss_J);
  SG_CHECK_CLOSE(homogeneous.J, det, 1e-12, 0, "homogeneous: det F");
  SG_CHECK(!homogeneous.folded(), "homogeneous: not folded");

  const auto folded =
      on_one_cell<dim>(unit_symmetric_tensor<dim>(), s, gauss_J);
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
