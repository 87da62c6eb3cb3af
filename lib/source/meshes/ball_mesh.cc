#include <deal.II/grid/grid_generator.h>
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
    prm.leave_subsection();
  }

  template <int dim> void BallMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Ball");
    center      = parse_point<dim>(prm.get("Center"), "Mesh/Ball/Center");
    radius      = prm.get_double("Radius");
    core_radius = prm.get_double("Core radius");
    shell_cells = prm.get_integer("Shell cells");
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
    if (core_radius > 0)
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

  template <int dim>
  void BallMesh<dim>::attach_manifolds(Triangulation<dim>   &triangulation,
                                       const Placement<dim> &placement) const
  {
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
