// Benchmark: the explicit solver's kernel, internal forces f_int(u) of a
// hyperelastic (neo-Hookean) block, matrix-free (InternalForceOperator)
// with the vectorised kernel (explicit SIMD over cells) and the reference
// kernel (FEEvaluation with sum factorisation, deal.II's vectorisation
// width), against a cell-by-cell FEValues assembly of the same residual
// (what a matrix-based code does per step), for Q1 and Q2 at about 20k,
// 200k and 1M displacement DoFs, all in the same run.
//
// Reports per case: DoFs, cells, time per evaluation and DoF-evaluations
// per second (in total over all ranks) of each kernel, time per element,
// and the peak resident memory; for Q2 also the u-p-J elements Q2-P0
// (vectorised) and Q2-P1 (reference kernel). Results in doc/benchmarks.md.
//
// Run: ./internal_force_throughput [max DoFs, default 1.2e6]
//      mpirun -np 2 ./internal_force_throughput
#include "peak_memory.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/explicit/internal_force_operator.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  class Displacement : public Function<3>
  {
  public:
    Displacement()
        : Function<3>(3)
    {
    }
    double value(const Point<3> &p, const unsigned int c) const override
    {
      return 0.05 * std::sin(2 * p[0] + c) * std::cos(1.5 * p[1]) +
             0.02 * p[2] * p[c];
    }
  };

  MaterialLibrary neo_hookean()
  {
    ParameterHandler prm;
    MaterialLibrary::declare_parameters(prm);
    MaterialLibrary::parse_input_from_string(
        prm,
        "subsection Materials\n set Material ids = 0\n subsection Material 0\n"
        "  set Model = neo-Hookean\n  set Density = 1000\n"
        "  subsection neo-Hookean\n   set Shear modulus = 1e4\n  end\n"
        "  subsection Volumetric\n   set Poisson's ratio = 0.45\n  end\n"
        " end\nend\n");
    MaterialLibrary library;
    library.parse_parameters(prm);
    return library;
  }

  void run(const unsigned int     degree,
           const unsigned int     n,
           const MaterialLibrary &materials)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    parallel::distributed::Triangulation<3> tria(comm);
    GridGenerator::subdivided_hyper_rectangle(
        tria, {n, n, n}, Point<3>(), Point<3>(1, 1, 1));
    const FESystem<3> fe(FE_Q<3>(degree), 3);
    DoFHandler<3>     dofs(tria);
    dofs.distribute_dofs(fe);
    const MappingQ<3>         mapping(1);
    AffineConstraints<double> none;
    none.close();
    using Kernel     = InternalForceOperator<3>::Kernel;
    using Dilatation = InternalForceOperator<3>::Dilatation;
    const InternalForceOperator<3>             op(mapping,
                                      dofs,
                                      none,
                                      materials,
                                      Dilatation::pointwise,
                                      Kernel::vectorized);
    const InternalForceOperator<3>             op_reference(mapping,
                                                dofs,
                                                none,
                                                materials,
                                                Dilatation::pointwise,
                                                Kernel::reference);
    LinearAlgebra::distributed::Vector<double> u, f;
    op.initialize_dof_vector(u);
    op.initialize_dof_vector(f);
    VectorTools::interpolate(mapping, dofs, Displacement(), u);

    // Matrix-free, each kernel: repeat for at least 1 s.
    Timer      timer(comm, true);
    const auto seconds_per_apply = [&](const InternalForceOperator<3> &o)
    {
      o.apply(u, f);
      timer.restart();
      unsigned int repeats = 0;
      do
      {
        o.apply(u, f);
        ++repeats;
      } while (timer.wall_time() < 1.0 || repeats < 3);
      timer.stop();
      return timer.last_wall_time() / repeats;
    };
    const double mf0 = seconds_per_apply(op_reference);
    const double mf  = seconds_per_apply(op);

    // FEValues assembly of the same vector (once or twice).
    u.update_ghost_values();
    const QGauss<3> quadrature(degree + 1);
    FEValues<3>     fe_values(
        mapping, fe, quadrature, update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<2, 3>>            grad_u(quadrature.size());
    Vector<double>                       local(fe.dofs_per_cell);
    std::vector<types::global_dof_index> indices(fe.dofs_per_cell);
    const Material                      &material = materials.get(0);
    timer.restart();
    unsigned int assembled = 0;
    do
    {
      f = 0;
      for (const auto &cell : dofs.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, grad_u);
        local = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          Tensor<2, 3> F = grad_u[q];
          for (unsigned int d = 0; d < 3; ++d)
            F[d][d] += 1;
          Material::Response r;
          material.evaluate_material(F, {}, false, r);
          const Tensor<2, 3> P = F * Tensor<2, 3>(r.stress);
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            local(i) +=
                scalar_product(P, fe_values[displacement].gradient(i, q)) *
                fe_values.JxW(q);
        }
        cell->get_dof_indices(indices);
        none.distribute_local_to_global(local, indices, f);
      }
      f.compress(VectorOperation::add);
      ++assembled;
    } while (timer.wall_time() < 1.0);
    timer.stop();
    const double fev = timer.last_wall_time() / assembled;

    const double n_dofs  = dofs.n_dofs();
    const double n_cells = tria.n_global_active_cells();
    const double memory  = Utilities::MPI::max(peak_memory_mb(), comm);
    if (root)
      std::cout << "Q" << degree << std::setw(9) << dofs.n_dofs() << " DoFs "
                << std::setw(8) << tria.n_global_active_cells() << " cells | "
                << "vectorised " << std::setw(9) << std::setprecision(4)
                << mf * 1e3 << " ms, " << std::setw(7) << n_dofs / mf / 1e6
                << " M DoF/s, " << std::setw(6) << mf / n_cells * 1e9
                << " ns/cell | reference " << std::setw(9) << mf0 * 1e3
                << " ms, " << std::setw(7) << n_dofs / mf0 / 1e6
                << " M DoF/s | FEValues " << std::setw(9) << fev * 1e3
                << " ms, " << std::setw(7) << n_dofs / fev / 1e6
                << " M DoF/s | speed-up over reference " << std::setw(5)
                << mf0 / mf << ", over FEValues " << std::setw(5) << fev / mf
                << " | peak memory " << std::setw(6) << memory << " MB"
                << std::endl;
    if (degree == 2)
    {
      // The u-p-J elements of the explicit solver: Q2-P0 (mean dilatation,
      // vectorised) and Q2-P1 (linear projections, reference kernel).
      const InternalForceOperator<3> p0(mapping,
                                        dofs,
                                        none,
                                        materials,
                                        Dilatation::element_constant,
                                        Kernel::vectorized);
      const InternalForceOperator<3> p1(mapping,
                                        dofs,
                                        none,
                                        materials,
                                        Dilatation::element_linear,
                                        Kernel::vectorized);
      const double t0 = seconds_per_apply(p0), t1 = seconds_per_apply(p1);
      if (root)
        std::cout << "   u-p-J: Q2-P0 vectorised " << std::setw(9) << t0 * 1e3
                  << " ms | Q2-P1 (reference kernel) " << std::setw(9)
                  << t1 * 1e3 << " ms | P1/P0 " << t1 / t0 << std::endl;
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double max_dofs  = argc > 1 ? std::stod(argv[1]) : 1.2e6;
  const auto   materials = neo_hookean();
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "Internal forces of a neo-Hookean block, "
              << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
              << " rank(s), SIMD width: deal.II " << VectorizedDouble::size()
              << ", vectorised kernel " << VectorizedForceKernel<3>::n_lanes()
              << std::endl;
  // subdivisions for about 20k, 200k, 1M DoFs: Q1 3 (n+1)^3, Q2 3 (2n+1)^3
  for (const auto &[degree, n] :
       std::vector<std::pair<unsigned int, unsigned int>>{
           {1, 18}, {1, 40}, {1, 68}, {2, 9}, {2, 20}, {2, 34}})
  {
    const double estimate = 3.0 * std::pow(degree * n + 1.0, 3);
    if (estimate <= max_dofs)
      run(degree, n, materials);
  }
}
