// Curved geometry for meshes read from files ('Mesh/File/Manifolds'): a
// ball octant and a half tube are written as Gmsh files (straight-sided
// cells, vertices on the true surfaces, as a mesher writes them) and read
// back with and without manifolds on their ids. Without, refinement keeps
// the file's polyhedron: the volume and area errors stall. With, they
// converge to the exact values, as close as the generated curved mesh
// refined as often (the tube, whose cylindrical manifold is the
// generator's own, to round-off). Bad rules are refused, naming the fix:
// among them rules whose surface does not fit the faces they name (a
// wrong centre or axis) and two rules on one id.
#include "../tests.h"
#include "measure.h"

#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/mesh_factory.h>

using namespace dealii;
using namespace softgrasp;
using namespace softgrasp_tests;

namespace
{
  /// The generated mesh refined once, written as Gmsh with its ids.
  template <int dim>
  void write_file(MeshFactory<dim> generated, const std::string &name)
  {
    generated.placement = Placement<dim>(); // in the mesh's own frame
    Triangulation<dim> tria;
    generated.create_coarse_mesh(tria);
    tria.refine_global(1);
    GridOut out;
    out.set_flags(GridOutFlags::Msh(true));
    std::ofstream file(name);
    file.precision(17); // vertices on the surface to round-off
    out.write_msh(tria, file);
  }

  struct Measures
  {
    double                         volume = 0;
    std::map<unsigned int, double> area;
  };

  template <int dim>
  Measures measured(const MeshFactory<dim> &factory,
                    const unsigned int      refinements)
  {
    Triangulation<dim> tria;
    factory.create_coarse_mesh(tria);
    tria.refine_global(refinements);
    std::map<unsigned int, double> volume;
    Measures                       m;
    measure(tria, volume, m.area);
    for (const auto &[id, v] : volume)
      m.volume += v;
    return m;
  }

  /// The largest relative error of volume and boundary areas.
  double error_of(const Measures                       &m,
                  const double                          volume,
                  const std::map<unsigned int, double> &areas)
  {
    return std::max(std::abs(m.volume / volume - 1),
                    largest_relative_error(m.area, areas));
  }

  /// The file read flat and with @p rules, refined 0-2 times, against the
  /// exact @p volume and @p areas and against @p generated refined once
  /// more (it was written after one refinement). With @p identical, the
  /// rules are the generator's own manifolds on the same coarse cells, so
  /// the two meshes must agree to round-off; otherwise (a transfinite
  /// interior blends over the file's smaller coarse cells) the file mesh
  /// must be at most twice as far from the exact geometry.
  template <int dim>
  void compare(const std::string                    &file,
               const std::string                    &rules,
               const MeshFactory<dim>               &generated,
               const double                          volume,
               const std::map<unsigned int, double> &areas,
               const bool                            identical)
  {
    double flat_error = 0, previous = 1, curved_error = 1;
    bool   rate = true, close_to_generated = true;
    for (unsigned int r = 0; r < 3; ++r)
    {
      for (const bool curved : {false, true})
      {
        auto factory = factory_from<dim>(
            "file",
            "File",
            "  set File name = " + file +
                "\n  set Manifolds = " + (curved ? rules : "") + "\n");
        factory.placement = generated.placement;
        SG_CHECK(factory.has_curved_boundary() == curved,
                 "rules make the mesh curved");
        const double error = error_of(measured(factory, r), volume, areas);
        deallog << "  refinement " << r << (curved ? ", manifolds" : ", flat")
                << ": largest error of volume and areas " << error;
        if (!curved)
          flat_error = error;
        else
        {
          const Measures g       = measured(generated, r + 1);
          const Measures m       = measured(factory, r);
          const double   g_error = error_of(g, volume, areas);
          deallog << " (generated mesh " << g_error << ")";
          if (identical)
          {
            close_to_generated =
                close_to_generated && std::abs(g.volume / m.volume - 1) < 1e-12;
            for (const auto &[id, a] : g.area)
              close_to_generated =
                  close_to_generated && std::abs(m.area.at(id) / a - 1) < 1e-12;
          }
          else
            close_to_generated = close_to_generated && error < 2 * g_error;
          rate         = rate && (r == 0 || error < previous / 4);
          previous     = error;
          curved_error = error;
        }
        deallog << std::endl;
      }
    }
    deallog << "  flat: error stalls above 1e-4: " << (flat_error > 1e-4)
            << "; manifolds: error falls at least 4-fold per refinement: "
            << rate << ", below 1e-5: " << (curved_error < 1e-5) << "; "
            << (identical ? "equals" : "within twice the error of")
            << " the generated curved mesh: " << close_to_generated
            << std::endl;
    SG_CHECK(flat_error > 1e-4, "the flat file mesh keeps its polyhedron");
    SG_CHECK(rate && curved_error < 1e-5, "the manifolds converge");
    SG_CHECK(close_to_generated, "as good as the generated curved mesh");
  }

  void refused(const std::string &rules,
               const std::string &expected,
               const std::string &file = "ball_octant.msh")
  {
    try
    {
      const auto factory = factory_from<3>(
          "file",
          "File",
          "  set File name = " + file + "\n  set Manifolds = " + rules + "\n");
      Triangulation<3> tria;
      factory.create_coarse_mesh(tria);
      SG_CHECK(false, "bad rules are refused");
    }
    catch (const InputError &e)
    {
      const std::string what = e.what();
      deallog << "'" << rules << "': " << what << std::endl;
      SG_CHECK(what.find(expected) != std::string::npos &&
                   what.find("Fix:") != std::string::npos,
               "the message names the cause and the fix");
    }
  }
} // namespace

int
main()
{
  initlog();
  const double pi = numbers::PI, R = 0.02;

  deallog << "Ball octant (R = 20 mm), 'boundary 0: sphere; material 0: "
             "transfinite'"
          << std::endl;
  const auto ball = factory_from<3>(
      "ball", "Ball", "  set Radius = 0.02\n  set Sector = octant\n");
  write_file(ball, "ball_octant.msh");
  compare<3>("ball_octant.msh",
             "boundary 0: sphere 0, 0, 0; material 0: transfinite",
             ball,
             pi * R * R * R / 6,
             {{0, pi * R * R / 2},
              {2, pi * R * R / 4},
              {3, pi * R * R / 4},
              {4, pi * R * R / 4}},
             false);

  deallog << "Half tube (radii 10 and 25 mm, 100 mm), 'material 0: "
             "cylinder', rotated and moved"
          << std::endl;
  const double ri = 0.01, ro = 0.025, L = 0.1;
  auto         tube = factory_from<3>(
      "tube",
      "Tube",
      "  set Center = 0.01, 0, 0\n  set Length = 0.1\n"
              "  set Inner radius = 0.01\n  set Outer radius = 0.025\n"
              "  set Sector = half\n  set Circumferential cells = 4\n"
              "  set Radial cells = 1\n  set Fine zone center = 0\n"
              "  set Fine zone length = 0.04\n  set Fine zone cells = 1\n"
              "  set Axial growth = 1.5\n");
  // the axis x turned to z about y, then moved; the file is written in the
  // mesh's own frame and placed the same way
  tube.placement = turned_and_moved();
  write_file(tube, "half_tube.msh");
  compare<3>("half_tube.msh",
             "material 0: cylinder 1, 0, 0 through 0.01, 0, 0",
             tube,
             pi / 2 * (ro * ro - ri * ri) * L,
             {{0, pi * ro * L},
              {1, pi * ri * L},
              {2, pi / 2 * (ro * ro - ri * ri)},
              {3, pi / 2 * (ro * ro - ri * ri)},
              {4, 2 * (ro - ri) * L}},
             true);

  refused("boundary 7: sphere 0, 0, 0", "no such id");
  refused("boundary 0: transfinite", "volume manifold");
  refused("boundary 0: torus 0, 0, 0", "unknown kind");
  refused("face 0: sphere 0, 0, 0", "does not start with");
  refused("boundary 0: cylinder 1, 0, 0", "through");
  refused("boundary 0: sphere 0, 0", "Mesh/File/Manifolds");
  refused("boundary 0: sphere nan, 0, 0", "not a finite number");
  // a centre off by a quarter of the radius: the faces are not on a sphere
  refused("boundary 0: sphere 0.005, 0, 0", "does not fit the mesh");
  refused("boundary 0: cylinder 0, 0, 1 through 0, 0, 0",
          "does not fit the mesh");
  refused("boundary 0: sphere 0, 0, 0; boundary 0: sphere 0, 0, 0",
          "both give boundary id 0");
  // rules on cells: a sphere on the tube's cells, an axis 5 mm off, a
  // sphere on the ball's core (whose edges run neither along nor across it)
  refused("material 0: sphere 0.01, 0, 0", "nor points to it", "half_tube.msh");
  refused("material 0: cylinder 1, 0, 0 through 0.01, 0.005, 0",
          "nor points to it",
          "half_tube.msh");
  refused("material 0: sphere 0, 0, 0", "transfinite");
}
