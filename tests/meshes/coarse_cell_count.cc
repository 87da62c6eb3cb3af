// The number of coarse cells that a generated mesh announces before it is
// built (so that a run too large for the machine is refused before its
// mesh exists) is the number it builds: a graded block with a fine zone in
// 2D and 3D, a whole and a half tube, a layered limb on a rigid and on a
// solid bone.
#include "../tests.h"
#include "measure.h"

#include <deal.II/grid/tria.h>

using namespace softgrasp_tests;

namespace
{
  template <int dim>
  void compare(const std::string &label,
               const std::string &type,
               const std::string &section,
               const std::string &entries)
  {
    const auto factory = factory_from<dim>(type, section, entries);
    dealii::Triangulation<dim> tria;
    factory.create_coarse_mesh(tria);
    const double announced = factory.generator().n_coarse_cells();
    dealii::deallog << label << ": " << tria.n_active_cells()
                    << " cells, announced " << announced << std::endl;
    SG_CHECK(announced == tria.n_active_cells(),
             label + ": the announced count is the built count");
  }
} // namespace

int
main()
{
  initlog();
  compare<2>("block 2D, fine zone",
             "block",
             "Block",
             "  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.02\n"
             "  set Fine zone = 0.03, 0.01; 0.06, 0.02\n"
             "  set Subdivisions = 6, 4\n  set Grading = 1.3, 1.5\n");
  compare<3>("block 3D",
             "block",
             "Block",
             "  set Upper corner = 0.03, 0.02, 0.01\n"
             "  set Subdivisions = 5, 3, 2\n  set Grading = 1, 0.7, 1\n");
  compare<3>("full tube",
             "tube",
             "Tube",
             "  set Circumferential cells = 12\n  set Radial cells = 3\n"
             "  set Fine zone length = 0.05\n  set Fine zone cells = 5\n");
  compare<3>("half tube",
             "tube",
             "Tube",
             "  set Sector = half\n  set Circumferential cells = 16\n"
             "  set Radial cells = 2\n");
  compare<3>("layered limb, rigid bone",
             "layered limb",
             "Layered limb",
             "  set Circumferential cells = 16\n");
  compare<3>("layered limb, solid bone, no fat",
             "layered limb",
             "Layered limb",
             "  set Bone = solid\n  set Fat thickness = 0\n"
             "  set Circumferential cells = 24\n");
}
