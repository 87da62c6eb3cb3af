#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/ball_mesh.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void BallMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Ball");
    prm.declare_entry("Center",
                      per_direction<dim>("0"),
                      Patterns::Anything(),
                      "Centre of the ball in the mesh's own frame (a study "
                      "places the mesh at the grasped object's pose). Unit: "
                      "m.");
    prm.declare_entry(
        "Radius", "0.04", Patterns::Double(0), "Radius of the ball. Unit: m.");
    prm.declare_entry("Core radius",
                      "0",
                      Patterns::Double(0),
                      "Radius of a rigid core that holds the ball (a shell "
                      "mesh whose inner surface has boundary id 1, to be "
                      "fixed by a Dirichlet condition); 0: a solid ball. "
                      "Unit: m.");
    prm.declare_entry("Shell cells",
                      "6",
                      Patterns::Selection("6|12|24|48|96"),
                      "Coarse cells of the shell around a core (3D: 6, 12, "
                      "24, 48 or 96; 2D: any). Unit: 1.");
    prm.declare_entry(
        "Sector",
        "full",
        dim == 3 ? Patterns::Selection("full|half|quarter|octant")
                 : Patterns::Selection("full|half|quarter"),
        "The part of the ball to mesh, for symmetric models: full; half "
        "(x >= c, with c the centre); quarter (x, y >= c); octant (x, y, "
        "z >= c; 3D). The cut planes x = c, y = c, z = c get boundary ids "
        "2, 3, 4: fix the normal component there for a symmetry plane. A "
        "part's shell has the cells of deal.II's quarter_hyper_shell, "
        "mirrored ('Shell cells' applies to the full shell).");
    prm.leave_subsection();
  }

  template <int dim> void BallMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Ball");
    center      = parse_point<dim>(prm.get("Center"), "Mesh/Ball/Center");
    radius      = prm.get_double("Radius");
    core_radius = prm.get_double("Core radius");
    shell_cells = prm.get_integer("Shell cells");
    sector      = prm.get("Sector");
    prm.leave_subsection();
    if (!(radius > 0))
      throw InputError("'Mesh/Ball/Radius' must be positive. Fix: give the "
                       "ball's radius (m).");
    if (core_radius >= radius)
      throw InputError("'Mesh/Ball/Core radius' (" +
                       std::to_string(core_radius) +
                       " m) is not smaller than 'Mesh/Ball/Radius' (" +
                       std::to_string(radius) +
                       " m). Fix: give a core radius below the radius, or 0 "
                       "for a solid ball.");
  }

  template <int dim>
  void
  BallMesh<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    if (sector != "full")
      create_sector(triangulation);
    else if (core_radius > 0)
    {
      // hyper_shell: 0 inner, 1 outer; softgrasp: 0 outer, 1 core.
      GridGenerator::hyper_shell(
          triangulation, center, core_radius, radius, shell_cells, true);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(face->boundary_id() == 0 ? 1 : 0);
    }
    else
      GridGenerator::hyper_ball_balanced(triangulation, center, radius);
  }

  namespace
  {
    constexpr types::manifold_id sphere_manifold_id = 0;
    constexpr types::manifold_id inner_manifold_id  = 1;

    /// Append the mirror image of the mesh (@p vertices, @p cells) at the
    /// plane x_axis = c; the caller merges the shared vertices.
    template <int dim>
    void mirror(std::vector<Point<dim>>    &vertices,
                std::vector<CellData<dim>> &cells,
                const unsigned int          axis,
                const double                c)
    {
      const unsigned int n_vertices = vertices.size();
      const unsigned int n_cells    = cells.size();
      for (unsigned int v = 0; v < n_vertices; ++v)
      {
        Point<dim> p = vertices[v];
        p[axis]      = 2 * c - p[axis];
        vertices.push_back(p);
      }
      for (unsigned int k = 0; k < n_cells; ++k)
      {
        CellData<dim> cell = cells[k];
        for (auto &v : cell.vertices)
          v += n_vertices;
        cells.push_back(cell);
      }
    }
  } // namespace

  template <int dim>
  void BallMesh<dim>::create_sector(Triangulation<dim> &triangulation) const
  {
    Triangulation<dim> orthant;
    if (core_radius > 0)
      GridGenerator::quarter_hyper_shell(orthant, center, core_radius, radius);
    else
      GridGenerator::quarter_hyper_ball(orthant, center, radius);
    auto [vertices, cells, subcells] =
        GridTools::get_coarse_mesh_description(orthant);
    // planes to mirror at: 3D octant -> quarter (z) -> half (y)
    std::vector<unsigned int> axes;
    if (dim == 3 && sector != "octant")
      axes.push_back(2);
    if (sector == "half")
      axes.push_back(1);
    for (const unsigned int axis : axes)
      mirror(vertices, cells, axis, center[axis]);
    for (auto &cell : cells)
      cell.manifold_id = numbers::flat_manifold_id;
    SubCellData               no_subcells;
    std::vector<unsigned int> all_vertices;
    GridTools::delete_duplicated_vertices(
        vertices, cells, no_subcells, all_vertices, 1e-10 * radius);
    GridTools::invert_cells_with_negative_measure(vertices, cells);
    GridTools::consistently_order_cells(cells);
    triangulation.create_triangulation(vertices, cells, no_subcells);

    // Ids by position: cut planes 2 + axis, the core 1, the sphere 0.
    const double tol = 1e-8 * radius;
    triangulation.set_all_manifold_ids(core_radius > 0 ? sphere_manifold_id
                                                       : inner_manifold_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
      {
        if (!face->at_boundary())
          continue;
        const Point<dim> x        = face->center();
        bool             on_plane = false;
        for (unsigned int d = 0; d < dim && !on_plane; ++d)
        {
          bool all_on = true;
          for (const unsigned int v : face->vertex_indices())
            all_on = all_on && std::abs(face->vertex(v)[d] - center[d]) < tol;
          if (all_on)
          {
            face->set_boundary_id(2 + d);
            if (core_radius == 0)
              face->set_manifold_id(numbers::flat_manifold_id);
            on_plane = true;
          }
        }
        if (on_plane)
          continue;
        const bool on_core = core_radius > 0 &&
                             x.distance(center) < 0.5 * (core_radius + radius);
        face->set_boundary_id(on_core ? 1 : 0);
      }
    if (core_radius == 0)
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 0)
            face->set_all_manifold_ids(sphere_manifold_id);
  }

  template <int dim>
  void BallMesh<dim>::attach_manifolds(Triangulation<dim>   &triangulation,
                                       const Placement<dim> &placement) const
  {
    if (sector != "full")
    {
      triangulation.set_manifold(sphere_manifold_id,
                                 SphericalManifold<dim>(placement(center)));
      if (core_radius == 0)
      {
        TransfiniteInterpolationManifold<dim> inner;
        inner.initialize(triangulation);
        triangulation.set_manifold(inner_manifold_id, inner);
      }
      return;
    }
    if (placement.is_identity())
      return; // the generator's own manifolds are in place
    // Both generators put a spherical manifold about the centre on id 0;
    // the balanced ball's transfinite interior (id 1) follows the moved
    // vertices when it is rebuilt.
    triangulation.set_manifold(0, SphericalManifold<dim>(placement(center)));
    if (core_radius == 0)
    {
      TransfiniteInterpolationManifold<dim> inner;
      inner.initialize(triangulation);
      triangulation.set_manifold(1, inner);
    }
  }

  template class BallMesh<2>;
  template class BallMesh<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH(softgrasp::BallMesh,
                        ball,
                        "ball",
                        "a solid ball or a spherical shell on a rigid core")
