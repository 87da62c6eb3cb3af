// The problems shipped with the softgrasp program, run from their own .prm
// files: the sphere pressed into a block with a fine zone gives Hertz's
// force (within 2 %), its patch-mean reference normal is not tilted by
// the symmetry planes of the quarter model, a reference normal in the
// geom's frame turns with the geom, and the tube drag without friction gives no
// drag: a frictionless finger sliding along a straight tube meets the same
// tissue everywhere (translation invariance), so the force along the tube is a
// discretisation error that falls under refinement, while the normal force
// stays constant.
#include "../solver_factory.h"
#include "../tests.h"
#include "problem_file.h"

#include <cmath>
#include <sstream>

using namespace softgrasp_tests;

namespace
{
  void sphere_into_block()
  {
    auto solver =
        make_solver<3>(problem("sphere_into_block.prm",
                               "subsection Output\n set Directory = out-hertz\n"
                               " set VTU interval = 0\n set Verbose = false\n"
                               "end\n"));
    solver->run();
    // Hertz's values from the file's parameters: R = 10 mm, d = 0.25 mm,
    // G = 10 kPa, nu = 0.45; the model is a quarter.
    const double G = 10e3, nu = 0.45, R = 0.01, d = 0.25e-3;
    const double E = 2 * G * (1 + nu);
    const double F_hertz =
        4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R) * std::pow(d, 1.5) / 4;
    const auto &f = solver->contact_force_history().back().forces[0][0];
    dealii::deallog << "Sphere into block: normal force " << f.normal_force()
                    << " N, Hertz " << F_hertz << " N, ratio "
                    << f.normal_force() / F_hertz << "; vertical force "
                    << f.force[2] << " N" << std::endl;
    SG_CHECK(close(f.normal_force(), F_hertz, 0.02),
             "Hertz's force within 2 %");
    SG_CHECK(close(f.normal_force(), f.force[2], 1e-12),
             "the reference normal -z gives the vertical force");
    // the KKT conditions hold at the nodes: no node inside the sphere
    const auto &history = solver->history();
    double      deepest = 0;
    for (unsigned int i = 0; i < history.rows.size(); ++i)
      deepest = std::max(deepest, history.value(i, "penetration"));
    dealii::deallog << "deepest penetration below 1e-12 m: "
                    << (deepest < 1e-12 ? "yes" : "no") << std::endl;
    SG_CHECK(deepest < 1e-12, "no penetration");
  }

  /// The reference normal of the sphere pressed into the block, set as
  /// @p choice (and the sphere turned by @p orientation, which does not
  /// change its contact), after half the indentation: the normal and the
  /// normal force.
  std::pair<Eigen::Vector3d, double>
  reference_normal(const std::string &choice, const std::string &orientation)
  {
    auto solver = make_solver<3>(
        problem("sphere_into_block.prm",
                "subsection Rigid bodies\n subsection Body indenter\n"
                "  subsection Geom sphere\n   set Reference normal = " +
                    choice + "\n   set Orientation = " + orientation +
                    "\n  end\n end\nend\n"
                    "subsection Time\n set End time = 0.5\nend\n"
                    "subsection Output\n set Directory = out-normal\n"
                    " set VTU interval = 0\n set Verbose = false\nend\n"));
    solver->run();
    const auto &f = solver->contact_force_history().back().forces[0][0];
    dealii::deallog << "Reference normal '" << choice << "': n = ("
                    << f.normal[0] << ", " << f.normal[1] << ", " << f.normal[2]
                    << "), normal force " << f.normal_force()
                    << " N, vertical force " << f.force[2] << " N" << std::endl;
    SG_CHECK(close(f.normal_force(), f.force[2], 1e-12),
             "the normal force is the vertical force");
    return {f.normal, f.normal_force()};
  }

  /// The largest drag along the tube during a frictionless pull of 4 mm
  /// (0.5 mm steps, quasi-static) with @p axial_cells cells over the 40 mm
  /// fine zone, relative to the smallest normal force.
  double frictionless_tube_drag(const unsigned int axial_cells)
  {
    auto solver =
        make_solver<3>(frictionless_tube_pull(axial_cells, "out-tube"));
    solver->run();
    const auto &records      = solver->contact_force_history();
    double      largest_drag = 0, n_min = 1e30, n_max = 0;
    for (const auto &record : records)
      if (record.time > 0.5 + 1e-9) // during the pull
      {
        const auto &f = record.forces[0][0];
        largest_drag  = std::max(largest_drag, std::abs(f.force[0]));
        n_min         = std::min(n_min, f.normal_force());
        n_max         = std::max(n_max, f.normal_force());
      }
    dealii::deallog << "Frictionless tube drag, " << 40 / axial_cells
                    << " mm axial cells: normal force " << n_min << " to "
                    << n_max << " N, largest drag " << largest_drag << " N ("
                    << largest_drag / n_min << " of the normal force)"
                    << std::endl;
    SG_CHECK(records.back().time > 1 - 1e-9, "the pull ran to the end");
    SG_CHECK(n_min > 1, "the finger is pressed into the tube");
    SG_CHECK(n_max - n_min < 0.02 * n_min, "a steady normal force");
    return largest_drag / n_min;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(3);
  sphere_into_block();
  // The patch's mean normal with the symmetry planes x = 0 and y = 0
  // removed is the whole model's (vertical); so is a normal fixed in the
  // frame of the sphere turned by 90 degrees about x (its -y is world -z).
  const auto mean = reference_normal("patch mean", "1, 0, 0, 0");
  const auto geom = reference_normal("geom: 0, -1, 0", "1, 1, 0, 0");
  SG_CHECK((mean.first - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12 &&
               (geom.first - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12,
           "both are the vertical");
  // The drag is a discretisation error: it depends on where the finger is
  // between nodes, and it falls when the axial cells are halved.
  const double coarse = frictionless_tube_drag(10);
  const double fine   = frictionless_tube_drag(20);
  SG_CHECK(fine < 0.5 * coarse && fine < 5e-3,
           "the drag vanishes under refinement");
}
