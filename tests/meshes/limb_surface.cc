// A user's own limb mesh gives the rigid arm its skin: the layered limb's
// coarse mesh, written as a Gmsh file and read back through 'Mesh/Type =
// file', keeps its material and boundary ids, and the skin surface made
// from its faces (boundary id 0, the open ends capped) is closed, as long
// as the limb and encloses exactly the volume of the polygonal prism its
// skin vertices span; the analytic skin of the layered limb with as many
// facets agrees. A mesh off the limb's frame or without a skin is refused
// with a message naming the fix.
#include "../tests.h"

#include <cmath>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <fstream>
#include <map>
#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/limb_surface.h>
#include <softgrasp/meshes/layered_limb.h>
#include <softgrasp/meshes/mesh_factory.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  MeshFactory<3> factory_from(const std::string &mesh_entries)
  {
    ParameterHandler prm;
    MeshFactory<3>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Mesh\n" + mesh_entries + "end\n");
    MeshFactory<3> factory;
    factory.parse_parameters(prm);
    return factory;
  }

  /// Cells per material id and faces per boundary id.
  std::map<unsigned int, unsigned int> census(const Triangulation<3> &tria)
  {
    std::map<unsigned int, unsigned int> count;
    for (const auto &cell : tria.active_cell_iterators())
    {
      ++count[cell->material_id()];
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          ++count[1000 + cell->face(f)->boundary_id()];
    }
    return count;
  }

  /// The enclosed volume after moving every vertex by @p shift: the same
  /// as without for a closed surface.
  double shifted_volume(LimbSurface surface, const Eigen::Vector3d &shift)
  {
    for (auto &t : surface.triangles)
      for (auto &x : t)
        x += shift;
    return surface.volume();
  }

  template <typename Function>
  void expect_refusal(const std::string &name,
                      const Function    &f,
                      const std::string &phrase)
  {
    try
    {
      f();
      SG_CHECK(false, name + " is refused");
    }
    catch (const InputError &e)
    {
      const std::string what = e.what();
      SG_CHECK(what.find(phrase) != std::string::npos,
               name + ": message names '" + phrase + "': " + what);
      deallog << name << ": refused, the message names '" << phrase << "'"
              << std::endl;
    }
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  const unsigned int n = 24; // cells around the limb
  const auto         limb_factory =
      factory_from("set Type = layered limb\nsubsection Layered limb\n"
                   "set Circumferential cells = " +
                   std::to_string(n) + "\nend\n");
  Triangulation<3> limb;
  limb_factory.create_coarse_mesh(limb);
  const LimbGeometry geometry =
      dynamic_cast<const LayeredLimb &>(limb_factory.generator()).geometry;

  // The user's mesh: the same limb as a Gmsh file (faces without a written
  // id are read back with id 0, the skin).
  {
    std::ofstream     out("limb.msh");
    GridOutFlags::Msh flags(true);
    GridOut           grid_out;
    grid_out.set_flags(flags);
    grid_out.write_msh(limb, out);
  }
  Triangulation<3> user;
  factory_from("set Type = file\nsubsection File\nset File name = "
               "limb.msh\nend\n")
      .create_coarse_mesh(user);
  SG_CHECK(census(user) == census(limb),
           "material and boundary ids survive the Gmsh file");
  deallog << "Gmsh round trip: " << user.n_active_cells()
          << " cells, material and boundary ids as in the layered limb"
          << std::endl;

  // The file stores about 7 digits; the mesh in memory is exact.
  const LimbSurface skin  = LimbSurface::of_mesh(user, 0);
  const LimbSurface exact = LimbSurface::of_mesh(limb, 0);
  const double      R     = geometry.mid_semi_axis();
  const double      L     = geometry.length;
  const double      prism =
      n / 2.0 * R * R * std::sin(2 * M_PI / n) * geometry.length;
  const double volume_error = std::abs(exact.volume() - prism) / prism;
  const double file_error   = std::abs(skin.volume() - prism) / prism;
  const double closure_error =
      std::abs(shifted_volume(exact, {0.1, 0.2, -0.3}) - exact.volume()) /
      prism;
  deallog << "skin from the file: " << skin.triangles.size()
          << " triangles, length " << skin.length << " m, volume within 1e-6 "
          << (file_error < 1e-6)
          << "; from the mesh in memory: volume within 1e-12 "
          << (volume_error < 1e-12) << ", closed " << (closure_error < 1e-12)
          << std::endl;
  SG_CHECK(file_error < 1e-6, "volume of the skin read from the file");
  SG_CHECK(std::abs(skin.length - L) < 1e-12 * L, "length of the limb");
  SG_CHECK(volume_error < 1e-12, "volume of the polygonal prism");
  SG_CHECK(closure_error < 1e-12, "closed surface");

  const LimbSurface analytic = LimbSurface::of_layered_limb(geometry, n);
  const double agreement = std::abs(analytic.volume() - exact.volume()) / prism;
  deallog << "analytic skin with " << n << " facets: same volume "
          << (agreement < 1e-12) << std::endl;
  SG_CHECK(agreement < 1e-12, "analytic and meshed skin agree");

  // Bad input: a mesh off the limb's frame, a mesh without a skin id.
  Triangulation<3> moved;
  moved.copy_triangulation(user);
  GridTools::shift(Tensor<1, 3>({0.05, 0, 0}), moved);
  expect_refusal(
      "mesh off the limb's frame",
      [&]() { LimbSurface::of_mesh(moved, 0); },
      "centred at x = 0");
  Triangulation<3> bare;
  bare.copy_triangulation(user);
  for (const auto &cell : bare.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        cell->face(f)->set_boundary_id(7);
  expect_refusal(
      "mesh without a skin",
      [&]() { LimbSurface::of_mesh(bare, 0); },
      "boundary id 0");
}
