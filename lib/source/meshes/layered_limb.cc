#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>
#include <functional>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/meshes/layered_limb.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    constexpr types::manifold_id limb_manifold_id = 0;
    constexpr types::manifold_id core_manifold_id = 1;
  } // namespace

  void LayeredLimb::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Layered limb");
    const LimbGeometry g;
    const auto         number = [&prm](const std::string &name,
                               const double       value,
                               const std::string &doc)
    {
      prm.declare_entry(
          name, Patterns::Tools::to_string(value), Patterns::Double(), doc);
    };
    number("Length",
           g.length,
           "Length of the segment along its axis (local "
           "x, shoulder end at -L/2). Unit: m.");
    number("Circumference",
           g.circumference,
           "Circumference of the skin at mid-segment. Unit: m.");
    number("Aspect ratio",
           g.aspect_ratio,
           "Ratio of the cross-section's semi-axes b (local z) / a (local "
           "y); 1 is circular; 0.2 to 5. Unit: 1.");
    number("Taper",
           g.taper,
           "Circumference at the elbow end / at the shoulder end; 1 is "
           "straight; 0.2 to 5. Unit: 1.");
    number("Skin thickness", g.skin, "Epidermis and dermis. Unit: m.");
    number("Fat thickness",
           g.fat,
           "Subcutaneous fat; 0 leaves the layer out. Unit: m.");
    number("Fascia thickness",
           g.fascia,
           "Deep (brachial) fascia; 0 leaves the layer out. Unit: m.");
    number("Bone radius",
           g.bone_radius,
           "Radius of the humerus shaft; the muscle fills the space "
           "between it and the fascia. Unit: m.");
    prm.declare_entry("Bone",
                      "rigid",
                      Patterns::Selection("rigid|solid"),
                      "rigid: the bone is not meshed, its surface (boundary "
                      "id 1) is to be fixed; solid: the bone is meshed to "
                      "the axis with its own material id.");
    prm.declare_entry("Radial cells",
                      "1, 1, 1, 3",
                      Patterns::List(Patterns::Integer(1, 256), 4, 4),
                      "Cells across skin, fat, fascia and muscle. Unit: 1.");
    number("Muscle grading",
           1.5,
           "Size ratio of neighbouring muscle cells from the fascia towards "
           "the bone (> 1: finest under the fascia); 0.2 to 5. Unit: 1.");
    prm.declare_entry("Circumferential cells",
                      "24",
                      Patterns::Integer(8, 4096),
                      "Cells around the limb; a multiple of 4 (of 8 with a "
                      "solid bone). Unit: 1.");
    number("Grasp zone center",
           0,
           "Axial position of the finely meshed zone where the hand "
           "grasps. Unit: m.");
    number("Grasp zone length",
           0.1,
           "Length of that zone (uniform cells). Unit: m.");
    prm.declare_entry("Grasp zone cells",
                      "8",
                      Patterns::Integer(1, 10000),
                      "Axial cells in the grasp zone. Unit: 1.");
    number("Axial growth",
           1.3,
           "Size ratio of neighbouring axial cells from the zone towards "
           "the ends (1: as in the zone); 1 to 3. Unit: 1.");
    prm.declare_entry("Check human size",
                      "true",
                      Patterns::Bool(),
                      "Refuse sizes outside those of human limbs (length "
                      "0.03-1.2 m, circumference 0.08-1 m, skin 0.5-5 mm, "
                      "fat up to 80 mm, fascia up to 3 mm, bone radius "
                      "2-30 mm), which are usually a unit typed wrong; false "
                      "for another animal's limb or a test piece.");
    prm.declare_entry("Material ids",
                      "1, 2, 3, 4, 5",
                      Patterns::List(Patterns::Integer(0, 254), 5, 5),
                      "Material ids of skin, fat, fascia, muscle and bone; "
                      "map them to materials (e.g. the tissue presets) in "
                      "'Materials'. Unit: 1.");
    prm.leave_subsection();
  }

  void LayeredLimb::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Layered limb");
    const CheckedSection s(prm, "Mesh/Layered limb");
    geometry.length        = s.get_positive("Length", "m");
    geometry.circumference = s.get_positive("Circumference", "m");
    // Ratios beyond these give cells too thin to compute with.
    geometry.aspect_ratio = s.get_in_range("Aspect ratio", 0.2, 5, true, "1");
    geometry.taper        = s.get_in_range("Taper", 0.2, 5, true, "1");
    geometry.skin         = s.get_positive("Skin thickness", "m");
    geometry.fat          = s.get_positive("Fat thickness", "m", true);
    geometry.fascia       = s.get_positive("Fascia thickness", "m", true);
    geometry.bone_radius  = s.get_positive("Bone radius", "m");
    bone             = prm.get("Bone") == "solid" ? Bone::solid : Bone::rigid;
    const auto cells = Utilities::split_string_list(prm.get("Radial cells"));
    for (unsigned int i = 0; i < 4; ++i)
      radial_cells[i] = Utilities::string_to_int(cells[i]);
    muscle_grading        = s.get_in_range("Muscle grading", 0.2, 5, true, "1");
    circumferential_cells = prm.get_integer("Circumferential cells");
    zone_center           = s.get_number("Grasp zone center");
    zone_length           = s.get_positive("Grasp zone length", "m");
    zone_cells            = prm.get_integer("Grasp zone cells");
    axial_growth          = s.get_in_range("Axial growth", 1, 3, true, "1");
    const bool check_human_size = prm.get_bool("Check human size");
    const auto ids = Utilities::split_string_list(prm.get("Material ids"));
    for (unsigned int i = 0; i < 5; ++i)
      material_ids[i] = Utilities::string_to_int(ids[i]);
    prm.leave_subsection();

    geometry.check();
    if (check_human_size)
      geometry.check_human_size();
    const unsigned int multiple = bone == Bone::solid ? 8 : 4;
    if (circumferential_cells % multiple != 0)
      throw InputError(
          "'Mesh/Layered limb/Circumferential cells' = " +
          std::to_string(circumferential_cells) + " is not a multiple of " +
          std::to_string(multiple) +
          (bone == Bone::solid ? " (needed for a solid bone)" : "") +
          ". Fix: give " + std::to_string(multiple) + ", " +
          std::to_string(2 * multiple) + ", " + std::to_string(3 * multiple) +
          ", ...");
    if (zone_center - zone_length / 2 < -geometry.length / 2 - 1e-12 ||
        zone_center + zone_length / 2 > geometry.length / 2 + 1e-12)
      throw InputError(
          "The grasp zone of 'Mesh/Layered limb' (centre " +
          std::to_string(zone_center) + " m, length " +
          std::to_string(zone_length) +
          " m) reaches outside the segment, which runs from " +
          std::to_string(-geometry.length / 2) + " to " +
          std::to_string(geometry.length / 2) +
          " m along its axis. Fix: move 'Grasp zone center' or shorten "
          "'Grasp zone length'.");
  }

  std::vector<double> LayeredLimb::radial_nodes() const
  {
    // Chart levels: 0 bone, then one per present interface (see
    // LimbManifold); muscle graded finest under the fascia.
    std::vector<double> xi =
        geometric_division(0, 1, radial_cells[3], 1 / muscle_grading);
    double level = 1;
    for (const auto &[thickness, cells] :
         {std::pair{geometry.fascia, radial_cells[2]},
          std::pair{geometry.fat, radial_cells[1]},
          std::pair{geometry.skin, radial_cells[0]}})
      if (thickness > 0)
      {
        const auto layer = geometric_division(level, level + 1, cells, 1);
        xi.insert(xi.end(), layer.begin() + 1, layer.end());
        level += 1;
      }
    return xi;
  }

  double LayeredLimb::n_coarse_cells() const
  {
    const double m = circumferential_cells / 4.0;
    const double section =
        (radial_nodes().size() - 1) * circumferential_cells +
        (bone == Bone::solid
             ? m * m + std::max(1.0, std::floor(m / 2)) * circumferential_cells
             : 0.0);
    return section * (axial_nodes().size() - 1);
  }

  std::vector<double> LayeredLimb::axial_nodes() const
  {
    const double L = geometry.length;
    return zoned_division(-L / 2,
                          L / 2,
                          zone_center - zone_length / 2,
                          zone_center + zone_length / 2,
                          zone_cells,
                          axial_growth);
  }

  namespace
  {
    /// A vertex of the cross-section: on the limb chart (xi, theta), whose
    /// position varies with x by the taper, or fixed (y, z) in the bone.
    struct SectionVertex
    {
      bool   on_chart;
      double u, v; ///< (xi, theta) or (y, z)
    };

    /// A quadrilateral of the cross-section, vertices in deal.II order,
    /// and which tissue (index into LayeredLimb::material_ids) it holds.
    struct SectionCell
    {
      std::array<unsigned int, 4> v;
      unsigned int                tissue;
    };

    /// The bone's core (solid bone): an m x m square of half-width s and
    /// m/2 rings from its boundary to the bone circle, whose 4m vertices
    /// are ring(j) of the limb's first radial level.
    void add_core(std::vector<SectionVertex>             &vertices,
                  std::vector<SectionCell>               &cells,
                  const unsigned int                      n_theta,
                  const double                            r,
                  const std::function<unsigned int(int)> &ring)
    {
      const unsigned int        m = n_theta / 4, rings = std::max(1u, m / 2);
      const double              s = 0.6 * r / std::sqrt(2.0);
      std::vector<unsigned int> square((m + 1) * (m + 1));
      for (unsigned int q = 0; q <= m; ++q)
        for (unsigned int p = 0; p <= m; ++p)
        {
          square[q * (m + 1) + p] = vertices.size();
          vertices.push_back({false, -s + 2 * s * p / m, -s + 2 * s * q / m});
        }
      for (unsigned int q = 0; q < m; ++q)
        for (unsigned int p = 0; p < m; ++p)
        {
          const unsigned int a = q * (m + 1) + p;
          cells.push_back({{{square[a],
                             square[a + 1],
                             square[a + m + 1],
                             square[a + m + 2]}},
                           4});
        }
      // The square's boundary vertex at angle index j (theta_j = 2 pi j /
      // 4m), counter-clockwise from (s, 0).
      const auto boundary = [&](const unsigned int j)
      {
        const unsigned int u = (j + m / 2) % n_theta, t = u % m;
        const unsigned int pq[4][2] = {{m, t}, {m - t, m}, {0, m - t}, {t, 0}};
        return square[pq[u / m][1] * (m + 1) + pq[u / m][0]];
      };
      std::vector<std::vector<unsigned int>> level(
          rings + 1, std::vector<unsigned int>(n_theta));
      for (unsigned int j = 0; j < n_theta; ++j)
      {
        level[0][j]     = boundary(j);
        level[rings][j] = ring(j);
        const auto  &a  = vertices[level[0][j]];
        const double t  = 2 * M_PI * j / n_theta;
        for (unsigned int l = 1; l < rings; ++l)
        {
          const double w = double(l) / rings;
          level[l][j]    = vertices.size();
          vertices.push_back({false,
                              (1 - w) * a.u + w * r * std::cos(t),
                              (1 - w) * a.v + w * r * std::sin(t)});
        }
      }
      for (unsigned int l = 0; l < rings; ++l)
        for (unsigned int j = 0; j < n_theta; ++j)
        {
          const unsigned int k = (j + 1) % n_theta;
          cells.push_back(
              {{{level[l][j], level[l + 1][j], level[l][k], level[l + 1][k]}},
               4});
        }
    }
  } // namespace

  void LayeredLimb::create_coarse_mesh(Triangulation<3> &triangulation) const
  {
    const auto         xi      = radial_nodes();
    const auto         x       = axial_nodes();
    const unsigned int n_theta = circumferential_cells;
    const unsigned int n_r     = xi.size();

    // The cross-section: the soft-tissue rings, then the bone's core.
    std::vector<SectionVertex> section;
    for (unsigned int i = 0; i < n_r; ++i)
      for (unsigned int j = 0; j < n_theta; ++j)
        section.push_back({true, xi[i], 2 * M_PI * j / n_theta});
    const auto ring = [n_theta](const unsigned int i, const unsigned int j)
    { return i * n_theta + j % n_theta; };
    // Tissue of radial cell i: the chart level it lies in, counted down
    // from the skin (0 skin, 1 fat, 2 fascia, 3 muscle) over present layers.
    std::vector<unsigned int> outside_in = {0};
    if (geometry.fat > 0)
      outside_in.push_back(1);
    if (geometry.fascia > 0)
      outside_in.push_back(2);
    outside_in.push_back(3);
    const double             top = xi.back();
    std::vector<SectionCell> cells;
    for (unsigned int i = 0; i + 1 < n_r; ++i)
    {
      const unsigned int layer = outside_in[static_cast<unsigned int>(
          top - 0.5 * (xi[i] + xi[i + 1]))];
      for (unsigned int j = 0; j < n_theta; ++j)
        cells.push_back(
            {{{ring(i, j), ring(i + 1, j), ring(i, j + 1), ring(i + 1, j + 1)}},
             layer});
    }
    if (bone == Bone::solid)
      add_core(section,
               cells,
               n_theta,
               geometry.bone_radius,
               [&ring](const int j) { return ring(0, j); });

    // Extrude along x: slice k holds a copy of every section vertex.
    const LimbManifold       chart(geometry, Placement<3>());
    std::vector<Point<3>>    vertices;
    std::vector<CellData<3>> hexes;
    for (const double xk : x)
      for (const auto &v : section)
        vertices.push_back(v.on_chart
                               ? chart.local_point(Point<3>(v.u, v.v, xk))
                               : Point<3>(xk, v.u, v.v));
    const unsigned int n_section = section.size();
    for (unsigned int k = 0; k + 1 < x.size(); ++k)
      for (const auto &c : cells)
      {
        CellData<3> hex;
        for (unsigned int i = 0; i < 4; ++i)
        {
          hex.vertices[i]     = c.v[i] + k * n_section;
          hex.vertices[i + 4] = c.v[i] + (k + 1) * n_section;
        }
        hex.material_id = material_ids[c.tissue];
        hex.manifold_id =
            c.tissue == 4 && bone == Bone::solid && c.v[0] >= n_r * n_theta
                ? core_manifold_id
                : limb_manifold_id;
        hexes.push_back(hex);
      }
    triangulation.create_triangulation(vertices, hexes, SubCellData());

    set_ids(triangulation);
  }

  void LayeredLimb::set_ids(Triangulation<3> &triangulation) const
  {
    // Manifold ids: the core first, so that the limb chart wins on the
    // faces and edges the core shares with the muscle (the bone circle).
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->manifold_id() == core_manifold_id)
        cell->set_all_manifold_ids(core_manifold_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->manifold_id() == limb_manifold_id)
        cell->set_all_manifold_ids(limb_manifold_id);

    // Boundary ids from where each face lies.
    const double L = geometry.length;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          const Point<3> c     = face->center();
          const bool     solid = cell->material_id() == material_ids[4] &&
                             cell->manifold_id() == core_manifold_id;
          if (std::abs(c[0] + L / 2) < 1e-9 * L)
            face->set_boundary_id(solid ? 4 : 2);
          else if (std::abs(c[0] - L / 2) < 1e-9 * L)
            face->set_boundary_id(solid ? 5 : 3);
          else
            face->set_boundary_id(
                std::hypot(c[1], c[2]) < 1.01 * geometry.bone_radius ? 1 : 0);
        }
  }

  void LayeredLimb::attach_manifolds(Triangulation<3>   &triangulation,
                                     const Placement<3> &placement) const
  {
    triangulation.set_manifold(limb_manifold_id,
                               LimbManifold(geometry, placement));
    if (bone == Bone::solid)
    {
      TransfiniteInterpolationManifold<3> core;
      core.initialize(triangulation);
      triangulation.set_manifold(core_manifold_id, core);
    }
  }
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH_3D(softgrasp::LayeredLimb,
                           layered_limb,
                           "layered limb",
                           "an upper-arm segment of skin, fat, fascia and "
                           "muscle on the humerus (doc/layered_limb.md)")
