// Shared by the tests of the deep 3D drag against CalculiX and across
// integrators (doc/contact.md, "Agreement with CalculiX"): the shipped
// example on mesh A of that comparison, and the contact record at a given
// millimetre of pull.
#ifndef softgrasp_tests_contact_deep_drag_h
#define softgrasp_tests_contact_deep_drag_h

#include "../tests.h"
#include "problem_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace softgrasp_tests
{
  /// examples/frictional_drag/deep_drag_3d.prm with the quadratic
  /// volumetric energy (CalculiX's NEO HOOKE) on mesh A (20 x 8 cells of
  /// 4 mm, a 12 mm zone of 3 cells under the top) and the node-wise
  /// potential (the example's is on faces), output to @p directory,
  /// followed by @p overrides.
  inline std::string deep_drag_mesh_a(const std::string &directory,
                                      const std::string &overrides)
  {
    return problem_text(
        EXAMPLE_DIR "/frictional_drag/deep_drag_3d.prm",
        "subsection Materials\n subsection Material 0\n"
        "  subsection Volumetric\n   set Energy = quadratic\n  end\n"
        " end\nend\n"
        "subsection Mesh\n subsection Block\n  set Subdivisions = 20, 8, 3\n"
        "  set Grading = 1, 1, 1.3\n"
        "  set Fine zone = -0.04, 0, -0.012; 0.04, 0.03, 0\n end\nend\n"
        "subsection Contact\n set Potential integration = nodes\n"
        " set Penalty factor = 100\nend\n"
        "subsection Output\n set Directory = " +
            directory + "\n set VTU interval = 0\n set Verbose = false\nend\n" +
            overrides);
  }

  /// The first geom's contact force at @p mm of pull (the press ends at
  /// 0.5 s, then 20 mm/s).
  template <typename Records>
  const auto &deep_drag_record(const Records &records, const double mm)
  {
    const double time   = 0.5 + mm / 20.0;
    const auto   record = std::find_if(
        records.begin(),
        records.end(),
        [&](const auto &r) { return std::abs(r.time - time) < 1e-9; });
    SG_CHECK(record != records.end(), "a record at every millimetre");
    return record->forces[0][0];
  }

  /// Normal force (N, +z on the finger) and drag (N, -x) of the first geom
  /// at @p mm of pull.
  template <typename Records>
  std::array<double, 2> deep_drag_forces(const Records &records,
                                         const double   mm)
  {
    const auto &force = deep_drag_record(records, mm).force;
    return {{force[2], -force[0]}};
  }

  /// The largest relative differences of @p run against @p reference
  /// (normal force and drag, N, per millimetre from 0): normal force, drag
  /// from @p first_drag_mm on and drag/normal ratio from @p first_ratio_mm
  /// on.
  inline std::array<double, 3>
  largest_differences(const std::vector<std::array<double, 2>> &run,
                      const std::vector<std::array<double, 2>> &reference,
                      const unsigned int first_drag_mm  = 1,
                      const unsigned int first_ratio_mm = 0)
  {
    std::array<double, 3> w = {{0, 0, 0}};
    for (std::size_t mm = 0; mm < run.size(); ++mm)
    {
      const auto &a = run[mm], &b = reference[mm];
      w[0] = std::max(w[0], std::abs(a[0] / b[0] - 1));
      if (mm >= first_drag_mm)
        w[1] = std::max(w[1], std::abs(a[1] / b[1] - 1));
      if (mm >= first_ratio_mm)
        w[2] = std::max(w[2], std::abs((a[1] / a[0]) / (b[1] / b[0]) - 1));
    }
    return w;
  }
} // namespace softgrasp_tests
#endif
