// Shared helpers of softgrasp's tests (deal.II test-suite conventions):
// output goes to the file "output" through deallog and is compared with the
// golden <name>.output by numdiff; physics checks abort the test on failure,
// so a wrong golden file cannot hide a wrong result.
#ifndef softgrasp_tests_h
#define softgrasp_tests_h

#include <cmath>
#include <cstdlib>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>

namespace softgrasp_tests
{
  inline std::ofstream &logfile()
  {
    static std::ofstream file;
    return file;
  }

  /// Send deallog to the file "output" (on MPI rank 0 only).
  inline void initlog(const unsigned int precision = 6)
  {
    if (dealii::Utilities::MPI::job_supports_mpi() &&
        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    logfile().open("output");
    dealii::deallog.attach(logfile());
    dealii::deallog.depth_console(0);
    logfile() << std::setprecision(precision);
  }

  [[noreturn]] inline void
  fail(const std::string &what, const char *file, const int line)
  {
    std::cerr << "PHYSICS CHECK FAILED at " << file << ":" << line << ": "
              << what << std::endl;
    std::abort();
  }

  /// |a - b| <= rtol |b| + atol
  inline bool close(const double a,
                    const double b,
                    const double rtol,
                    const double atol = 0)
  {
    return std::abs(a - b) <= rtol * std::abs(b) + atol;
  }
} // namespace softgrasp_tests

/// Abort the test with a message if @p cond is false.
#define SG_CHECK(cond, what)                                                   \
  do                                                                           \
  {                                                                            \
    if (!(cond))                                                               \
      softgrasp_tests::fail(                                                   \
          std::string(what) + "  [" #cond "]", __FILE__, __LINE__);            \
  } while (false)

/// Abort unless |a - b| <= rtol |b| + atol.
#define SG_CHECK_CLOSE(a, b, rtol, atol, what)                                 \
  do                                                                           \
  {                                                                            \
    const double sg_a = (a), sg_b = (b);                                       \
    if (!softgrasp_tests::close(sg_a, sg_b, (rtol), (atol)))                   \
      softgrasp_tests::fail(std::string(what) + ": got " +                     \
                                std::to_string(sg_a) + ", expected " +         \
                                std::to_string(sg_b),                          \
                            __FILE__,                                          \
                            __LINE__);                                         \
  } while (false)

#endif
