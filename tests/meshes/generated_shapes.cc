// The generated meshes a user sets up contact problems with, against their
// exact geometry: parts of a ball (half, quarter, octant; solid and on a
// core; 2D and 3D) and of a tube (full, half, quarter; placed by a rotation
// and a translation) converge under refinement to the exact volume and to
// the exact area of every boundary id, including the cut (symmetry) planes;
// a block's fine zone has uniform cells and grows by at most its ratio
// outside; bad input is refused with a message naming the entry.
#include "../tests.h"
#include "measure.h"

#include <deal.II/grid/tria.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/block_mesh.h>
#include <softgrasp/meshes/mesh_factory.h>

using namespace dealii;
using namespace softgrasp;
using namespace softgrasp_tests;

namespace
{
  template <int dim>
  MeshFactory<dim> factory_from(const std::string &type,
                                const std::string &entries)
  {
    return softgrasp_tests::factory_from<dim>(type,
                                              type == "ball"   ? "Ball"
                                              : type == "tube" ? "Tube"
                                                               : "Block",
                                              entries);
  }

  /// Refine the mesh of @p factory 0, 1, 2 times; the volume and boundary
  /// areas must converge to @p volume and @p areas (ids not listed must not
  /// exist), within @p tolerance at the finest level.
  template <int dim>
  void check_convergence(const MeshFactory<dim>               &factory,
                         const double                          volume,
                         const std::map<unsigned int, double> &areas,
                         const double                          tolerance)
  {
    double previous = 1;
    for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      Triangulation<dim> tria;
      factory.create_coarse_mesh(tria);
      tria.refine_global(refinement);
      std::map<unsigned int, double> v, a;
      measure(tria, v, a);
      double measured_volume = 0;
      for (const auto &[id, value] : v)
        measured_volume += value;
      const double volume_error = std::abs(measured_volume / volume - 1);
      const double area_error   = largest_relative_error(a, areas);
      const double error        = std::max(volume_error, area_error);
      deallog << "  refinement " << refinement << ": " << tria.n_active_cells()
              << " cells, volume error " << volume_error
              << ", largest boundary area error " << area_error << std::endl;
      for (const auto &[id, value] : a)
        SG_CHECK(areas.count(id), "no unexpected boundary id");
      SG_CHECK(refinement == 0 || error < previous, "errors decrease");
      previous = error;
    }
    SG_CHECK(previous < tolerance, "converged to the exact geometry");
  }

  void ball_parts_3d()
  {
    const double R = 0.02, pi = numbers::PI;
    for (const double core : {0.0, 0.01})
      for (const std::string sector : {"octant", "quarter", "half"})
      {
        deallog << "3D ball, " << sector
                << (core > 0 ? " shell on a core" : " solid") << std::endl;
        const auto factory = factory_from<3>(
            "ball",
            "  set Center = 0.001, -0.002, 0.003\n  set Radius = 0.02\n"
            "  set Core radius = " +
                std::to_string(core) + "\n  set Sector = " + sector + "\n");
        const double frac = sector == "octant"    ? 0.125
                            : sector == "quarter" ? 0.25
                                                  : 0.5;
        const double disc = pi * (R * R - core * core);
        // each cut plane is a quarter, half or whole disc (annulus)
        const double                   plane = sector == "octant"    ? disc / 4
                                               : sector == "quarter" ? disc / 2
                                                                     : disc;
        std::map<unsigned int, double> areas = {{0, frac * 4 * pi * R * R},
                                                {2, plane}};
        if (core > 0)
          areas[1] = frac * 4 * pi * core * core;
        if (sector != "half")
          areas[3] = plane;
        if (sector == "octant")
          areas[4] = plane;
        check_convergence(factory,
                          frac * 4. / 3 * pi * (R * R * R - core * core * core),
                          areas,
                          2e-3);
      }
  }

  void ball_parts_2d()
  {
    const double R = 0.02, pi = numbers::PI;
    for (const std::string sector : {"quarter", "half"})
    {
      deallog << "2D disc, " << sector << std::endl;
      const auto                     factory = factory_from<2>("ball",
                                           "  set Center = 0.001, -0.002\n"
                                                               "  set Radius = 0.02\n"
                                                               "  set Sector = " +
                                               sector + "\n");
      const double                   frac    = sector == "quarter" ? 0.25 : 0.5;
      std::map<unsigned int, double> areas   = {
            {0, frac * 2 * pi * R}, {2, sector == "quarter" ? R : 2 * R}};
      if (sector == "quarter")
        areas[3] = R;
      check_convergence(factory, frac * pi * R * R, areas, 2e-3);
    }
  }

  void tube_parts()
  {
    const double L = 0.1, ri = 0.01, ro = 0.025, pi = numbers::PI;
    for (const std::string sector : {"full", "half", "quarter"})
    {
      deallog << "Tube, " << sector << ", rotated and moved" << std::endl;
      auto factory = factory_from<3>(
          "tube",
          "  set Center = 0.01, 0, 0\n  set Length = 0.1\n"
          "  set Inner radius = 0.01\n  set Outer radius = 0.025\n"
          "  set Sector = " +
              sector +
              "\n  set Circumferential cells = 8\n  set Radial cells = 2\n"
              "  set Radial grading = 1.5\n  set Fine zone center = 0.01\n"
              "  set Fine zone length = 0.04\n  set Fine zone cells = 2\n"
              "  set Axial growth = 1.5\n");
      // the axis x turned to z about y, then moved
      factory.placement  = turned_and_moved();
      const double frac  = sector == "full" ? 1 : sector == "half" ? 0.5 : 0.25;
      const double strip = (ro - ri) * L;
      std::map<unsigned int, double> areas = {
          {0, frac * 2 * pi * ro * L},
          {1, frac * 2 * pi * ri * L},
          {2, frac * pi * (ro * ro - ri * ri)},
          {3, frac * pi * (ro * ro - ri * ri)}};
      if (sector == "half")
        areas[4] = 2 * strip;
      if (sector == "quarter")
        areas[4] = areas[5] = strip;
      check_convergence(
          factory, frac * pi * (ro * ro - ri * ri) * L, areas, 2e-3);
    }
  }

  void block_fine_zone()
  {
    deallog << "Block with a fine zone" << std::endl;
    const auto factory =
        factory_from<3>("block",
                        "  set Lower corner = 0, 0, -0.05\n"
                        "  set Upper corner = 0.05, 0.05, 0\n"
                        "  set Subdivisions = 4, 4, 2\n"
                        "  set Grading = 1.5\n"
                        "  set Fine zone = 0, 0, -0.002; 0.004, 0.004, 0\n");
    const auto &block = dynamic_cast<const BlockMesh<3> &>(factory.generator());
    for (unsigned int d = 0; d < 3; ++d)
    {
      const auto x = block.divisions(d);
      deallog << "  direction " << d << ":";
      for (const double xi : x)
        deallog << ' ' << xi * 1e3;
      deallog << " mm" << std::endl;
      const unsigned int n = d < 2 ? 4 : 2;
      const double       h = d < 2 ? 0.001 : 0.001;
      SG_CHECK(close(x.front(), block.lower[d], 0, 1e-15) &&
                   close(x.back(), block.upper[d], 0, 1e-15),
               "the divisions span the block");
      // the zone: uniform cells of size h at the fine end
      const unsigned int first = d < 2 ? 0 : x.size() - 1 - n;
      for (unsigned int i = first; i < first + n; ++i)
        SG_CHECK(close(x[i + 1] - x[i], h, 1e-12), "uniform zone");
      for (unsigned int i = 0; i + 2 < x.size(); ++i)
      {
        const double a = x[i + 1] - x[i], b = x[i + 2] - x[i + 1];
        SG_CHECK(std::max(a, b) / std::min(a, b) < 1.5 * (1 + 1e-9) + 1e-12,
                 "neighbours differ by at most the growth ratio");
      }
    }
  }

  void bad_input()
  {
    deallog << "Bad input" << std::endl;
    const auto refused = [](const auto &make)
    {
      try
      {
        make();
      }
      catch (const InputError &e)
      {
        deallog << "  refused: " << e.what() << std::endl;
        return true;
      }
      return false;
    };
    SG_CHECK(refused(
                 []
                 {
                   factory_from<3>("tube",
                                   "  set Inner radius = 0.03\n"
                                   "  set Outer radius = 0.02\n");
                 }),
             "inner radius above the outer one");
    SG_CHECK(refused(
                 []
                 {
                   factory_from<3>(
                       "block",
                       "  set Upper corner = 0.01, 0.01, 0.01\n"
                       "  set Fine zone = 0, 0, 0; 0.02, 0.01, 0.01\n");
                 }),
             "fine zone outside the block");
    SG_CHECK(refused(
                 []
                 {
                   factory_from<3>("ball",
                                   "  set Radius = 0.01\n"
                                   "  set Core radius = 0.02\n"
                                   "  set Sector = octant\n");
                 }),
             "core larger than the ball");
  }
} // namespace

int
main()
{
  initlog(3);
  ball_parts_3d();
  ball_parts_2d();
  tube_parts();
  block_fine_zone();
  bad_input();
}
