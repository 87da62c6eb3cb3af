#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <softgrasp/meshes/cook_membrane.h>

namespace softgrasp
{
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
} // namespace softgrasp
