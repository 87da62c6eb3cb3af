// Benchmark: the roofline of this machine, per MPI rank and in total:
//  - memory bandwidth: the STREAM triad a = b + s c on arrays far larger
//    than the caches (3 x 128 MB per rank), best of 10 repetitions, counted
//    as 3 x 8 bytes per entry (write-allocate traffic not counted, as in
//    STREAM);
//  - peak double-precision arithmetic: independent fused multiply-add
//    chains on the SIMD type of the vectorised stress kernel
//    (softgrasp/base/simd.h), 2 flops per lane per FMA.
// Results, with the explicit kernel's place on the roofline, in
// doc/benchmarks.md.
//
// Run: ./roofline; mpirun -np 2 ./roofline
#include <chrono>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/simd.h>
#include <vector>

using namespace dealii;

namespace
{
  double seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
        .count();
  }

  /// Triad bandwidth of this rank (bytes/s), all ranks running at once.
  double triad_bandwidth(const MPI_Comm comm)
  {
    const std::size_t   n = std::size_t(1) << 24; // 128 MB per array
    std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
    double              best = 1e30;
    for (unsigned int repeat = 0; repeat < 10; ++repeat)
    {
      MPI_Barrier(comm);
      const auto   start = std::chrono::steady_clock::now();
      const double s     = 1.0 + 1e-3 * repeat;
      for (std::size_t i = 0; i < n; ++i)
        a[i] = b[i] + s * c[i];
      best = std::min(best, seconds_since(start));
    }
    if (a[n / 2] < 0) // keep the loop
      std::cout << a[n / 2];
    return 3.0 * sizeof(double) * n / best;
  }

  /// Double-precision flop/s of this rank with independent FMA chains.
  double fma_peak(const MPI_Comm comm)
  {
    using V                       = softgrasp::simd::Double;
    constexpr unsigned int chains = 12;
    const std::size_t      steps  = 50'000'000;
    V                      x[chains];
    for (unsigned int i = 0; i < chains; ++i)
      x[i] = 1.0 + 1e-9 * i;
    const V a = 1.0 - 1e-12, b = 1e-12;
    MPI_Barrier(comm);
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t s = 0; s < steps; ++s)
      for (unsigned int i = 0; i < chains; ++i)
        x[i] = x[i] * a + b;
    const double time = seconds_since(start);
    V            sum  = 0.0;
    for (unsigned int i = 0; i < chains; ++i)
      sum += x[i];
    if (softgrasp::simd::stdx::reduce(sum) < 0)
      std::cout << "";
    return 2.0 * softgrasp::simd::width * chains * steps / time;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int ranks              = Utilities::MPI::n_mpi_processes(comm);
  const double bandwidth = Utilities::MPI::sum(triad_bandwidth(comm), comm);
  const double flops     = Utilities::MPI::sum(fma_peak(comm), comm);
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::cout << std::setprecision(3) << ranks << " rank(s), SIMD width "
              << softgrasp::simd::width << ": triad bandwidth "
              << bandwidth / 1e9 << " GB/s, FMA peak " << flops / 1e9
              << " GFlop/s, ridge point " << flops / bandwidth
              << " flop/byte (totals over the ranks)" << std::endl;
}
