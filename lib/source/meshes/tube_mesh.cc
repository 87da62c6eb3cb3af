#include <cmath>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/meshes/tube_mesh.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    constexpr types::manifold_id tube_manifold_id = 0;
  } // namespace

  void TubeMesh::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Tube");
    prm.declare_entry("Center",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "Mid-point of the tube's axis (the local x axis) in "
                      "the mesh's own frame. Unit: m.");
    prm.declare_entry(
        "Length", "0.2", Patterns::Double(0), "Length along x. Unit: m.");
    prm.declare_entry("Inner radius",
                      "0.01",
                      Patterns::Double(0),
                      "Radius of the inner surface (boundary id 1, e.g. "
                      "bonded to a rigid bone). Unit: m.");
    prm.declare_entry("Outer radius",
                      "0.03",
                      Patterns::Double(0),
                      "Radius of the outer surface (boundary id 0, the "
                      "contact surface). Unit: m.");
    prm.declare_entry("Sector",
                      "full",
                      Patterns::Selection("full|half|quarter"),
                      "The part of the tube to mesh, for symmetric models: "
                      "full; half (y >= 0; cut plane id 4); quarter (y, "
                      "z >= 0; cut planes y = 0 id 4, z = 0 id 5).");
    prm.declare_entry("Circumferential cells",
                      "16",
                      Patterns::Integer(4, 4096),
                      "Cells around the full circumference (a part gets its "
                      "share); a multiple of 4. Unit: 1.");
    prm.declare_entry("Radial cells",
                      "4",
                      Patterns::Integer(1, 1024),
                      "Cells across the wall. Unit: 1.");
    prm.declare_entry("Radial grading",
                      "1",
                      Patterns::Double(0),
                      "Size ratio of neighbouring radial cells from the "
                      "outer surface inwards (> 1: finest at the outer "
                      "surface, where the contact is). Unit: 1.");
    prm.declare_entry("Fine zone center",
                      "0",
                      Patterns::Double(),
                      "Axial position (x, from 'Center') of the zone of "
                      "uniform cells, e.g. where a finger presses and "
                      "drags. Unit: m.");
    prm.declare_entry("Fine zone length",
                      "0.2",
                      Patterns::Double(0),
                      "Axial length of that zone (the whole length: "
                      "uniform). Unit: m.");
    prm.declare_entry("Fine zone cells",
                      "8",
                      Patterns::Integer(1, 10000),
                      "Axial cells in the zone. Unit: 1.");
    prm.declare_entry("Axial growth",
                      "1.3",
                      Patterns::Double(1),
                      "Size ratio of neighbouring axial cells from the zone "
                      "towards the ends (1: as in the zone). Unit: 1.");
    prm.leave_subsection();
  }

  void TubeMesh::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Tube");
    center       = parse_point<3>(prm.get("Center"), "Mesh/Tube/Center");
    length       = prm.get_double("Length");
    inner_radius = prm.get_double("Inner radius");
    outer_radius = prm.get_double("Outer radius");
    sector       = prm.get("Sector");
    circumferential_cells = prm.get_integer("Circumferential cells");
    radial_cells          = prm.get_integer("Radial cells");
    radial_grading        = prm.get_double("Radial grading");
    zone_center           = prm.get_double("Fine zone center");
    zone_length           = prm.get_double("Fine zone length");
    zone_cells            = prm.get_integer("Fine zone cells");
    axial_growth          = prm.get_double("Axial growth");
    prm.leave_subsection();
    const auto fail = [](const std::string &what, const std::string &fix)
    { throw InputError("'Mesh/Tube': " + what + ". Fix: " + fix + "."); };
    if (!(length > 0) || !(inner_radius > 0) || !(radial_grading > 0))
      fail("'Length', 'Inner radius' and 'Radial grading' must be positive",
           "give positive values (m, m, 1)");
    if (!(outer_radius > inner_radius))
      fail("'Outer radius' (" + std::to_string(outer_radius) +
               " m) is not above 'Inner radius' (" +
               std::to_string(inner_radius) + " m)",
           "give an outer radius above the inner one");
    if (circumferential_cells % 4 != 0)
      fail(
          "'Circumferential cells' = " + std::to_string(circumferential_cells) +
              " is not a multiple of 4",
          "give 8, 12, 16, ...");
    if (!(zone_length > 0) ||
        zone_center - zone_length / 2 < -length / 2 * (1 + 1e-12) ||
        zone_center + zone_length / 2 > length / 2 * (1 + 1e-12))
      fail("the fine zone (centre " + std::to_string(zone_center) +
               " m, length " + std::to_string(zone_length) +
               " m) does not lie within the tube's length",
           "give a zone inside [-Length/2, Length/2]");
  }

  std::vector<double> TubeMesh::radial_nodes() const
  {
    // from the outer surface inwards, then reversed
    auto r = geometric_division(
        outer_radius, inner_radius, radial_cells, radial_grading);
    return std::vector<double>(r.rbegin(), r.rend());
  }

  std::vector<double> TubeMesh::angles() const
  {
    const double        pi    = numbers::PI;
    const double        begin = sector == "quarter" ? 0 : -pi / 2;
    const double        span  = sector == "full"   ? 2 * pi
                                : sector == "half" ? pi
                                                   : pi / 2;
    const unsigned int  n     = circumferential_cells * span / (2 * pi) + 0.5;
    std::vector<double> t;
    for (unsigned int j = 0; j <= n; ++j)
      t.push_back(begin + span * j / n);
    if (sector == "full")
      t.pop_back(); // periodic: the last node is the first
    return t;
  }

  double TubeMesh::n_coarse_cells() const
  {
    const double axial = zoned_division(-length / 2,
                                        length / 2,
                                        zone_center - zone_length / 2,
                                        zone_center + zone_length / 2,
                                        zone_cells,
                                        axial_growth)
                             .size() -
                         1;
    const double around = angles().size() - (sector == "full" ? 0 : 1);
    return axial * around * radial_cells;
  }

  void TubeMesh::create_coarse_mesh(Triangulation<3> &triangulation) const
  {
    const auto         x    = zoned_division(-length / 2,
                                  length / 2,
                                  zone_center - zone_length / 2,
                                  zone_center + zone_length / 2,
                                  zone_cells,
                                  axial_growth);
    const auto         r    = radial_nodes();
    const auto         t    = angles();
    const bool         full = sector == "full";
    const unsigned int n_x = x.size(), n_r = r.size(), n_t = t.size();
    const unsigned int n_t_cell = full ? n_t : n_t - 1;
    const auto index = [&](unsigned int i, unsigned int k, unsigned int j)
    { return (i * n_r + k) * n_t + j % n_t; };

    std::vector<Point<3>> vertices;
    for (unsigned int i = 0; i < n_x; ++i)
      for (unsigned int k = 0; k < n_r; ++k)
        for (unsigned int j = 0; j < n_t; ++j)
          vertices.emplace_back(center[0] + x[i],
                                center[1] + r[k] * std::cos(t[j]),
                                center[2] + r[k] * std::sin(t[j]));
    // (x, r, t) is right-handed: lexicographic vertex order in (i, k, j)
    std::vector<CellData<3>> cells;
    for (unsigned int i = 0; i + 1 < n_x; ++i)
      for (unsigned int k = 0; k + 1 < n_r; ++k)
        for (unsigned int j = 0; j < n_t_cell; ++j)
        {
          CellData<3> cell;
          cell.vertices = {index(i, k, j),
                           index(i + 1, k, j),
                           index(i, k + 1, j),
                           index(i + 1, k + 1, j),
                           index(i, k, j + 1),
                           index(i + 1, k, j + 1),
                           index(i, k + 1, j + 1),
                           index(i + 1, k + 1, j + 1)};
          cells.push_back(cell);
        }
    GridTools::invert_cells_with_negative_measure(vertices, cells);
    triangulation.create_triangulation(vertices, cells, SubCellData());

    // Boundary ids by position (before any placement).
    const double tol = 1e-8 * outer_radius;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
      {
        if (!face->at_boundary())
          continue;
        const Tensor<1, 3> c  = face->center() - center;
        const double       rc = std::hypot(c[1], c[2]);
        if (std::abs(c[0] + length / 2) < tol)
          face->set_boundary_id(2);
        else if (std::abs(c[0] - length / 2) < tol)
          face->set_boundary_id(3);
        else if (std::abs(c[1]) < tol && !full)
          face->set_boundary_id(4);
        else if (std::abs(c[2]) < tol && sector == "quarter")
          face->set_boundary_id(5);
        else
          face->set_boundary_id(rc < 0.5 * (inner_radius + outer_radius) ? 1
                                                                         : 0);
      }
    triangulation.set_all_manifold_ids(tube_manifold_id);
  }

  void TubeMesh::attach_manifolds(Triangulation<3>   &triangulation,
                                  const Placement<3> &placement) const
  {
    const Tensor<1, 3> axis = placement.rotate(Tensor<1, 3>({1., 0., 0.}));
    triangulation.set_manifold(tube_manifold_id,
                               CylindricalManifold<3>(axis, placement(center)));
  }
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH_3D(softgrasp::TubeMesh,
                           tube,
                           "tube",
                           "a hollow cylinder (whole, half or quarter) with a "
                           "bonded inner surface, graded radially and axially")
