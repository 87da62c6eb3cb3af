#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <softgrasp/meshes/cook_membrane.h>

namespace softgrasp
{
  using namespace dealii;

  namespace Meshes
  {
    using namespace dealii;

    template <int dim>
    void cook_membrane(Triangulation<dim> &triangulation,
                       const unsigned int  n_per_edge,
                       const double        thickness,
                       const unsigned int  n_layers)
    {
      // Unit box with colourised boundary ids (0/1: x, 2/3: y, 4/5: z),
      // then the bilinear map onto the tapered membrane.
      std::vector<unsigned int> repetitions(dim, n_per_edge);
      Point<dim>                upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = 1.0;
      if (dim == 3)
      {
        repetitions[2] = n_layers;
        upper[dim - 1] = thickness;
      }
      GridGenerator::subdivided_hyper_rectangle(
          triangulation, repetitions, Point<dim>(), upper, true);
      GridTools::transform(
          [](const Point<dim> &p)
          {
            Point<dim>   q      = p;
            const double x      = 0.048 * p[0];
            const double bottom = 0.044 * p[0];
            const double top    = 0.044 + 0.016 * p[0];
            q[0]                = x;
            q[1]                = bottom + p[1] * (top - bottom);
            return q;
          },
          triangulation);
    }

    template void cook_membrane(Triangulation<2> &,
                                const unsigned int,
                                const double,
                                const unsigned int);
    template void cook_membrane(Triangulation<3> &,
                                const unsigned int,
                                const double,
                                const unsigned int);
  } // namespace Meshes

  template <int dim>
  void CookMembraneMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cook's membrane");
    prm.declare_entry("Elements per edge",
                      "8",
                      Patterns::Integer(1),
                      "Elements along each edge of the membrane. Unit: 1.");
    prm.declare_entry("Thickness",
                      "0.001",
                      Patterns::Double(0),
                      "Out-of-plane thickness (3D only). Unit: m.");
    prm.declare_entry("Layers",
                      "1",
                      Patterns::Integer(1),
                      "Elements through the thickness (3D only). Unit: 1.");
    prm.leave_subsection();
  }

  template <int dim>
  void CookMembraneMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cook's membrane");
    elements_per_edge = prm.get_integer("Elements per edge");
    thickness         = prm.get_double("Thickness");
    layers            = prm.get_integer("Layers");
    prm.leave_subsection();
  }

  template <int dim>
  void CookMembraneMesh<dim>::create_coarse_mesh(
      Triangulation<dim> &triangulation) const
  {
    Meshes::cook_membrane(triangulation, elements_per_edge, thickness, layers);
  }

  template class CookMembraneMesh<2>;
  template class CookMembraneMesh<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH(softgrasp::CookMembraneMesh,
                        cook_membrane,
                        "Cook's membrane",
                        "Cook's tapered membrane (a bending benchmark)")
