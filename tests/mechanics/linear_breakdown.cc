// A linear solver that breaks down reports it, so that Newton's step fails
// and the load step is cut back (it must not throw or return garbage):
//  - a singular matrix: MUMPS fails, the result says "MUMPS" and is not
//    converged;
//  - a matrix with a NaN entry: the direct solve returns NaN, which is a
//    breakdown, not a solution;
//  - a regular matrix still solves (2 x = b gives x = b/2).
#include "../tests.h"

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <softgrasp/mechanics/linear_solver.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  /// The solve of a diagonal 6 x 6 system with the given diagonal.
  LinearSolver::Result solve_diagonal(const std::vector<double> &diagonal,
                                      double                    &x0)
  {
    const IndexSet                    owned = complete_index_set(6);
    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < 6; ++i)
      pattern.add(i, i);
    pattern.compress();
    TrilinosWrappers::SparseMatrix A;
    A.reinit(pattern);
    for (unsigned int i = 0; i < 6; ++i)
      A.set(i, i, diagonal[i]);
    A.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b);
    b = 1.0;
    LinearSolverParameters parameters;
    parameters.type = LinearSolverType::direct;
    LinearSolver         solver(parameters);
    LinearSolver::Result result = solver.solve(A, x, b, true);
    x0                          = x[0];
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  double x0 = 0;

  const auto singular = solve_diagonal({2, 2, 0, 2, 2, 2}, x0);
  SG_CHECK(!singular.converged, "a singular matrix is not solved");
  SG_CHECK(singular.breakdown.find("MUMPS") != std::string::npos,
           "the breakdown names MUMPS: " + singular.breakdown);
  deallog << "singular: converged " << singular.converged << ", breakdown "
          << (singular.breakdown.empty() ? "none" : "reported") << std::endl;

  const auto nan = solve_diagonal({2, 2, std::nan(""), 2, 2, 2}, x0);
  SG_CHECK(!nan.converged, "NaN in the matrix is not a solution");
  SG_CHECK(!nan.breakdown.empty(), "NaN is reported as a breakdown");
  deallog << "NaN entry: converged " << nan.converged << ", breakdown "
          << (nan.breakdown.empty() ? "none" : "reported") << std::endl;

  const auto regular = solve_diagonal({2, 2, 2, 2, 2, 2}, x0);
  SG_CHECK(regular.converged && regular.breakdown.empty(), "a regular solve");
  SG_CHECK_CLOSE(x0, 0.5, 1e-14, 0, "x = b / 2");
  deallog << "regular: converged " << regular.converged << ", x_0 = " << x0
          << std::endl;
}
