// A link given as a triangle mesh presses the tissue as the primitive it
// triangulates does (issue 54), on the softgrasp program's squeezed ball
// (a rubber ball octant, R = 20 mm, Q2, pressed 2 mm by a rigid plate):
//  - the box plate and the same box as a 12-triangle OBJ mesh give the same
//    normal force to 1e-6 relative (the mesh is exact for a box);
//  - a capsule (r = 10 mm, its axis across the ball) and the capsule
//    triangulated with N = 48 segments around and 12 rings per cap: the
//    facets lie inside the capsule by up to s = r (1 - cos(pi/N)) = 21 um,
//    so the mesh presses up to s less deep into the 2 mm indentation; its
//    force lies below the capsule's by less than 2 s/d = 2.1 % (the force
//    grows at most as d^2 here) and not above it by more than 1e-6; with
//    twice the segments (s / 4) the difference falls below 0.35 times.
#include "../solver_factory.h"
#include "../tests.h"
#include "problem_file.h"

#include <cmath>
#include <fstream>

using namespace softgrasp_tests;

namespace
{
  /// The ball squeezed by the geom of @p geom (entries of 'Geom slab') on
  /// the trajectory @p trajectory: the normal force at the end (N).
  double squeeze(const std::string &geom,
                 const std::string &trajectory,
                 const std::string &directory)
  {
    auto solver = make_solver<3>(
        problem("squeezed_ball.prm",
                "subsection Rigid bodies\n subsection Body plate\n"
                "  set Trajectory = " +
                    trajectory + "\n  subsection Geom slab\n" + geom +
                    "  end\n end\nend\n"
                    "subsection Output\n set Directory = " +
                    directory +
                    "\n set VTU interval = 0\n set Verbose = false\nend\n"));
    solver->run();
    return solver->contact_force_history().back().forces[0][0].normal_force();
  }

  /// The box of half sizes @p h as 12 triangles (OBJ, outward).
  void write_box(const std::string &file, const Eigen::Vector3d &h)
  {
    std::ofstream out(file);
    out.precision(17);
    for (unsigned int i = 0; i < 8; ++i)
      out << "v " << (i & 1 ? h[0] : -h[0]) << ' ' << (i & 2 ? h[1] : -h[1])
          << ' ' << (i & 4 ? h[2] : -h[2]) << '\n';
    // each face as two triangles, counter-clockwise seen from outside
    const unsigned int faces[6][4] = {{1, 3, 7, 5},
                                      {0, 4, 6, 2},
                                      {2, 6, 7, 3},
                                      {0, 1, 5, 4},
                                      {4, 5, 7, 6},
                                      {0, 2, 3, 1}};
    for (const auto &f : faces)
      out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << "\nf "
          << f[0] + 1 << ' ' << f[2] + 1 << ' ' << f[3] + 1 << '\n';
  }

  /**
   * The capsule of radius @p r and half length @p h along z as a closed
   * triangle surface (OBJ): @p n vertices around each ring, @p k rings
   * per cap between pole and equator, vertices on the capsule.
   */
  void write_capsule(const std::string &file,
                     const double       r,
                     const double       h,
                     const unsigned int n,
                     const unsigned int k)
  {
    std::ofstream out(file);
    out.precision(17);
    // rings from the top pole down: cap rings 1..k (k at z = h), then the
    // bottom cap's rings k..1 (the first at z = -h)
    std::vector<std::pair<double, double>> rings; // (z, radius)
    for (unsigned int i = 1; i <= k; ++i)
    {
      const double t = M_PI / 2 * i / k;
      rings.emplace_back(h + r * std::cos(t), r * std::sin(t));
    }
    for (unsigned int i = k; i >= 1; --i)
    {
      const double t = M_PI / 2 * i / k;
      rings.emplace_back(-h - r * std::cos(t), r * std::sin(t));
    }
    out << "v 0 0 " << h + r << '\n';
    for (const auto &[z, rho] : rings)
      for (unsigned int j = 0; j < n; ++j)
        out << "v " << rho * std::cos(2 * M_PI * j / n) << ' '
            << rho * std::sin(2 * M_PI * j / n) << ' ' << z << '\n';
    out << "v 0 0 " << -h - r << '\n';
    const auto index = [&](unsigned int ring, unsigned int j)
    { return 2 + ring * n + j % n; }; // OBJ counts from 1
    const auto bottom = 2 + rings.size() * n;
    for (unsigned int j = 0; j < n; ++j)
      out << "f 1 " << index(0, j) << ' ' << index(0, j + 1) << '\n';
    for (unsigned int ring = 0; ring + 1 < rings.size(); ++ring)
      for (unsigned int j = 0; j < n; ++j)
        out << "f " << index(ring, j) << ' ' << index(ring + 1, j) << ' '
            << index(ring + 1, j + 1) << "\nf " << index(ring, j) << ' '
            << index(ring + 1, j + 1) << ' ' << index(ring, j + 1) << '\n';
    for (unsigned int j = 0; j < n; ++j)
      out << "f " << bottom << ' ' << index(rings.size() - 1, j + 1) << ' '
          << index(rings.size() - 1, j) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const std::string plate = "0: 0, 0, 0.025, 1, 0, 0, 0; 1: 0, 0, 0.023, "
                            "1, 0, 0, 0";
  write_box("box.obj", {0.03, 0.03, 0.005});
  const double box = squeeze("   set Type = box\n   set Size = 0.03, 0.03, "
                             "0.005\n",
                             plate,
                             "out-box");
  const double box_mesh =
      squeeze("   set Type = mesh\n   set Mesh file = box.obj\n",
              plate,
              "out-box-mesh");
  dealii::deallog << "box plate " << box << " N, as 12 triangles " << box_mesh
                  << " N" << std::endl;
  SG_CHECK(std::abs(box_mesh - box) <= 1e-6 * box,
           "the box and its 12 triangles press alike");
  dealii::deallog << "the box and its 12 triangles: the same force to 1e-6: 1"
                  << std::endl;

  // The capsule's axis along x: turned by 90 degrees about y; its lowest
  // line at the ball's top at t = 0, 2 mm into it at t = 1.
  const double      r = 0.01, h = 0.03, d = 0.002;
  const unsigned    n = 48, k = 12;
  const std::string axis_x = "   set Orientation = 0.70710678118654752, 0, "
                             "0.70710678118654752, 0\n";
  const std::string finger = "0: 0, 0, 0.03, 1, 0, 0, 0; 1: 0, 0, 0.028, "
                             "1, 0, 0, 0";
  write_capsule("capsule.obj", r, h, n, k);
  const double capsule =
      squeeze("   set Type = capsule\n   set Size = 0.01, 0.03\n" + axis_x,
              finger,
              "out-capsule");
  const double capsule_mesh =
      squeeze("   set Type = mesh\n   set Mesh file = capsule.obj\n" + axis_x,
              finger,
              "out-capsule-mesh");
  const double s = r * (1 - std::cos(M_PI / n));
  dealii::deallog << "capsule " << capsule << " N, as " << 2 * n * (2 * k - 1)
                  << " triangles " << capsule_mesh << " N (relative "
                  << (capsule_mesh - capsule) / capsule
                  << "), faceting bound 2 s/d = " << 2 * s / d << std::endl;
  SG_CHECK(capsule_mesh <= capsule * (1 + 1e-6) &&
               capsule - capsule_mesh <= 2 * s / d * capsule,
           "the triangulated capsule presses within the faceting error");
  dealii::deallog << "the triangulated capsule within the faceting error: 1"
                  << std::endl;
  // Twice the segments: a quarter of the faceting error.
  write_capsule("capsule96.obj", r, h, 2 * n, k);
  const double finer =
      squeeze("   set Type = mesh\n   set Mesh file = capsule96.obj\n" + axis_x,
              finger,
              "out-capsule-96");
  dealii::deallog << "with 96 segments " << finer << " N (relative "
                  << (finer - capsule) / capsule << ")" << std::endl;
  SG_CHECK(std::abs(finer - capsule) < 0.35 * std::abs(capsule_mesh - capsule),
           "the force converges with the faceting error");
  dealii::deallog << "twice the segments, under 0.35 times the difference: 1"
                  << std::endl;
}
