// The layered limb mesh against the analytic geometry it models: the volume
// of every tissue layer (annuli of a straight circular limb; elliptic,
// tapered layers on a solid bone, placed by a rotation and a translation)
// converges to the exact value under refinement with a quadratic mapping,
// the boundary ids carry the analytic surface areas, refinement puts new
// skin vertices on the true ellipse, and bad input is refused with a
// message naming the entry.
#include "../tests.h"
#include "measure.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <map>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/layered_limb.h>
#include <softgrasp/meshes/mesh_factory.h>

using namespace dealii;
using namespace softgrasp;
using namespace softgrasp_tests;

namespace
{
  MeshFactory<3> factory_from(const std::string &entries)
  {
    ParameterHandler prm;
    MeshFactory<3>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Mesh\n set Type = layered limb\n"
                                " subsection Layered limb\n" +
                                entries + " end\nend\n");
    MeshFactory<3> factory;
    factory.parse_parameters(prm);
    return factory;
  }

  /// The coarse mesh of @p factory, refined @p refinement times.
  void build(const MeshFactory<3> &factory,
             const unsigned int    refinement,
             Triangulation<3>     &tria)
  {
    factory.create_coarse_mesh(tria);
    tria.refine_global(refinement);
  }

  void straight_circular_limb()
  {
    deallog << "Straight circular limb, rigid bone" << std::endl;
    const double L = 0.1, C = 0.3, skin = 0.002, fat = 0.005, fascia = 0.001,
                 rb    = 0.01;
    const auto factory = factory_from(
        "  set Length = 0.1\n  set Circumference = 0.3\n"
        "  set Skin thickness = 0.002\n  set Fat thickness = 0.005\n"
        "  set Fascia thickness = 0.001\n  set Bone radius = 0.01\n"
        "  set Radial cells = 1, 1, 1, 2\n  set Circumferential cells = 8\n"
        "  set Grasp zone length = 0.04\n  set Grasp zone cells = 2\n"
        "  set Axial growth = 1.5\n");
    const double R        = C / (2 * M_PI);
    const double radii[5] = {
        rb, R - skin - fat - fascia, R - skin - fat, R - skin, R};
    // material ids 1 skin ... 4 muscle: layer between radii[4-id], [5-id]
    std::map<unsigned int, double> exact;
    for (unsigned int id = 1; id <= 4; ++id)
      exact[id] =
          M_PI * L * (std::pow(radii[5 - id], 2) - std::pow(radii[4 - id], 2));
    const std::map<unsigned int, double> exact_area = {
        {0, 2 * M_PI * R * L},
        {1, 2 * M_PI * rb * L},
        {2, M_PI * (R * R - rb * rb)},
        {3, M_PI * (R * R - rb * rb)}};
    double previous = 1;
    for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      Triangulation<3> tria;
      build(factory, refinement, tria);
      std::map<unsigned int, double> volume, area;
      measure(tria, volume, area);
      const double worst = std::max(largest_relative_error(volume, exact),
                                    largest_relative_error(area, exact_area));
      SG_CHECK(volume.size() == 4 && area.size() == 4,
               "four tissues and four boundary ids");
      deallog << "  refinement " << refinement << ": " << tria.n_active_cells()
              << " cells, largest relative error of layer volumes and "
                 "surface areas "
              << worst << std::endl;
      SG_CHECK(worst < previous / 8, "converges at least at third order");
      previous = worst;
    }
    SG_CHECK(previous < 1e-4, "volumes and areas within 1e-4");
  }

  void tapered_elliptic_limb()
  {
    deallog << "Tapered elliptic limb, solid bone, placed" << std::endl;
    auto factory = factory_from(
        "  set Length = 0.12\n  set Circumference = 0.3\n"
        "  set Aspect ratio = 0.8\n  set Taper = 0.8\n"
        "  set Bone = solid\n  set Radial cells = 1, 1, 1, 2\n"
        "  set Circumferential cells = 8\n  set Grasp zone center = 0.02\n"
        "  set Grasp zone length = 0.04\n  set Grasp zone cells = 2\n");
    // An independent evaluation of the geometry: Ramanujan's perimeter.
    const double k = 0.8, L = 0.12, taper = 0.8;
    const double a_mid =
        0.3 / (M_PI * (3 * (1 + k) - std::sqrt((3 + k) * (1 + 3 * k))));
    const double depth[5] = {0, 0.0021, 0.0021 + 0.0055, 0.0083, 0};
    const auto   section  = [&](const unsigned int layer, const double x)
    {
      // area inside the outer interface of layer (0 skin .. 3 muscle)
      const double a =
          a_mid * 2 / (1 + taper) * (1 + (taper - 1) * (x / L + 0.5));
      return M_PI * (a - depth[layer]) * (k * a - depth[layer]);
    };
    std::map<unsigned int, double> exact;
    for (unsigned int layer = 0; layer < 4; ++layer)
    {
      const auto inner = [&](const double x)
      { return layer < 3 ? section(layer + 1, x) : M_PI * 0.0095 * 0.0095; };
      // A B is quadratic in x: Simpson's rule is exact.
      const auto f = [&](const double x)
      { return section(layer, x) - inner(x); };
      exact[layer + 1] = L / 6 * (f(-L / 2) + 4 * f(0) + f(L / 2));
    }
    exact[5] = M_PI * 0.0095 * 0.0095 * L;

    Tensor<2, 3>       R; // 30 degrees about (1, 1, 1)/sqrt(3)
    const Tensor<1, 3> n  = Tensor<1, 3>({1., 1., 1.}) / std::sqrt(3.);
    const double       th = M_PI / 6;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = std::cos(th) * (i == j) + (1 - std::cos(th)) * n[i] * n[j];
    R[0][1] -= std::sin(th) * n[2];
    R[1][0] += std::sin(th) * n[2];
    R[0][2] += std::sin(th) * n[1];
    R[2][0] -= std::sin(th) * n[1];
    R[1][2] -= std::sin(th) * n[0];
    R[2][1] += std::sin(th) * n[0];
    factory.placement.rotation    = R;
    factory.placement.translation = Tensor<1, 3>({0.3, -0.2, 0.5});

    double previous = 1;
    for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      Triangulation<3> tria;
      build(factory, refinement, tria);
      std::map<unsigned int, double> volume, area;
      measure(tria, volume, area);
      const double           worst = largest_relative_error(volume, exact);
      std::set<unsigned int> ids;
      for (const auto &[id, a] : area)
        ids.insert(id);
      SG_CHECK((ids == std::set<unsigned int>{0, 2, 3, 4, 5}),
               "skin, tissue end caps and bone ends; no bone surface");
      deallog << "  refinement " << refinement << ": " << tria.n_active_cells()
              << " cells, largest relative error of layer volumes " << worst
              << std::endl;
      SG_CHECK(worst < previous / 6, "converges");
      previous = worst;
      if (refinement == 2)
      {
        // Every skin vertex on the placed ellipse of its axial position.
        double off = 0;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == 0)
              for (const unsigned int v : face->vertex_indices())
              {
                const Point<3> p(transpose(R) *
                                 (face->vertex(v) -
                                  Point<3>(factory.placement.translation)));
                const double   a = a_mid * 2 / (1 + taper) *
                                 (1 + (taper - 1) * (p[0] / L + 0.5));
                off = std::max(off,
                               std::abs(std::pow(p[1] / a, 2) +
                                        std::pow(p[2] / (k * a), 2) - 1));
              }
        deallog << "  skin vertices off the ellipse by at most "
                << (off < 1e-12 ? "1e-12" : std::to_string(off)) << std::endl;
        SG_CHECK(off < 1e-12, "refinement follows the skin surface");
      }
    }
    SG_CHECK(previous < 1e-3, "volumes within 1e-3");
  }

  void bad_input()
  {
    deallog << "Bad input" << std::endl;
    for (const std::string entries :
         {"  set Skin thickness = 0.05\n",
          "  set Fat thickness = -0.001\n",
          "  set Grasp zone center = 0.14\n",
          "  set Circumferential cells = 10\n",
          "  set Bone = solid\n  set Circumferential cells = 12\n"})
      try
      {
        factory_from(entries);
        SG_CHECK(false, "refused: " + entries);
      }
      catch (const InputError &e)
      {
        deallog << "  " << e.what() << std::endl;
      }
    try
    {
      MeshRegistry<2>::create("layered limb", "mesh type ('Mesh/Type')");
      SG_CHECK(false, "a 2D layered limb is refused");
    }
    catch (const InputError &e)
    {
      deallog << "  2D: " << e.what() << std::endl;
    }
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog(3);
  straight_circular_limb();
  tapered_elliptic_limb();
  bad_input();
}
