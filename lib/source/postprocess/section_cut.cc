#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/postprocess/section_cut.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// Where the straight edge (a, b) crosses the plane (signed distances
    /// da, db of opposite sign): the fraction from a.
    double crossing(const double da, const double db)
    {
      return da / (da - db);
    }

    /// Corners of a convex polygon in the plane, ordered around their mean.
    std::vector<unsigned int> order_around(const std::vector<Point<3>> &p,
                                           const Tensor<1, 3>          &n)
    {
      Point<3> mean;
      for (const auto &x : p)
        mean += x / double(p.size());
      Tensor<1, 3> e1 = p[0] - mean;
      e1 /= std::max(e1.norm(), 1e-300);
      const Tensor<1, 3>        e2 = cross_product_3d(n, e1);
      std::vector<double>       angle(p.size());
      std::vector<unsigned int> order(p.size());
      for (unsigned int i = 0; i < p.size(); ++i)
      {
        angle[i] = std::atan2((p[i] - mean) * e2, (p[i] - mean) * e1);
        order[i] = i;
      }
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned int a, const unsigned int b)
                { return angle[a] < angle[b]; });
      return order;
    }

    void put(std::vector<double> &data, const Point<3> &p)
    {
      data.insert(data.end(), {p[0], p[1], p[2]});
    }

    Point<3> take(const std::vector<double> &data, std::size_t &i)
    {
      const Point<3> p(data[i], data[i + 1], data[i + 2]);
      i += 3;
      return p;
    }
  } // namespace

  namespace
  {
    using Cell = DoFHandler<3>::active_cell_iterator;

    /// The displacement (m) at vertex @p v of @p cell.
    Tensor<1, 3> vertex_displacement(const Cell                          &cell,
                                     const unsigned int                   v,
                                     const TrilinosWrappers::MPI::Vector &u)
    {
      Tensor<1, 3> d;
      for (unsigned int c = 0; c < 3; ++c)
        d[c] = u[cell->vertex_dof_index(v, c)];
      return d;
    }

    /// Where the plane crosses the edge between vertices @p a and @p b of
    /// @p cell (signed distances @p dist): appends the point before and
    /// after the deformation to @p X and @p x, if it crosses.
    void add_crossing(const Cell                          &cell,
                      const unsigned int                   a,
                      const unsigned int                   b,
                      const double                        *dist,
                      const TrilinosWrappers::MPI::Vector &u,
                      std::vector<Point<3>>               &X,
                      std::vector<Point<3>>               &x)
    {
      if ((dist[a] >= 0) == (dist[b] >= 0))
        return;
      const double   t = crossing(dist[a], dist[b]);
      const Point<3> Xc =
          cell->vertex(a) + t * (cell->vertex(b) - cell->vertex(a));
      X.push_back(Xc);
      x.push_back(Xc + (1 - t) * vertex_displacement(cell, a, u) +
                  t * vertex_displacement(cell, b, u));
    }

    /// The segments of the outline: faces of @p cell on boundary
    /// @p outline_id that the plane crosses, packed (X, x) twice each.
    void add_outline(const Cell                          &cell,
                     const double                        *dist,
                     const TrilinosWrappers::MPI::Vector &u,
                     const types::boundary_id             outline_id,
                     std::vector<double>                 &segments)
    {
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == outline_id)
        {
          std::vector<Point<3>> FX, Fx;
          for (unsigned int l = 0; l < 4; ++l)
            add_crossing(cell,
                         GeometryInfo<3>::face_to_cell_vertices(
                             f, GeometryInfo<2>::line_to_cell_vertices(l, 0)),
                         GeometryInfo<3>::face_to_cell_vertices(
                             f, GeometryInfo<2>::line_to_cell_vertices(l, 1)),
                         dist,
                         u,
                         FX,
                         Fx);
          if (FX.size() == 2)
            for (unsigned int k = 0; k < 2; ++k)
            {
              put(segments, FX[k]);
              put(segments, Fx[k]);
            }
        }
    }

    /// The section from the packed polygons and segments of every process.
    Section unpack(const Point<3>                         &origin,
                   const Tensor<1, 3>                     &n,
                   const std::vector<std::vector<double>> &all_polygons,
                   const std::vector<std::vector<double>> &all_segments)
    {
      Section section;
      section.origin = origin;
      section.normal = n;
      for (const auto &data : all_polygons)
        for (std::size_t i = 0; i < data.size();)
        {
          Section::Polygon p;
          const auto       corners = static_cast<unsigned int>(data[i]);
          p.material = static_cast<types::material_id>(data[i + 1]);
          p.e_max    = data[i + 2];
          i += 3;
          for (unsigned int k = 0; k < corners; ++k)
          {
            p.reference.push_back(take(data, i));
            p.deformed.push_back(take(data, i));
          }
          section.polygons.push_back(std::move(p));
        }
      for (const auto &data : all_segments)
        for (std::size_t i = 0; i < data.size();)
        {
          Section::Segment s;
          for (unsigned int k = 0; k < 2; ++k)
          {
            s.reference[k] = take(data, i);
            s.deformed[k]  = take(data, i);
          }
          section.outline.push_back(s);
        }
      return section;
    }
  } // namespace

  Section Section::cut(const SolidSystem<3>    &system,
                       const Point<3>          &origin,
                       const Tensor<1, 3>      &normal_in,
                       const types::boundary_id outline_id,
                       MPI_Comm                 comm)
  {
    const Tensor<1, 3> n    = normal_in / normal_in.norm();
    const auto        &dofs = system.dof_handler();
    const auto        &u    = system.ghosted_solution();
    FEValues<3>        centre(
        system.mapping(), dofs.get_fe(), QMidpoint<3>(), update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 3>>        grad_u(1);

    // Packed: polygons [n, material, e_max, n x (X, x)], then segments.
    std::vector<double> polygons, segments;
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      double dist[8];
      bool   above = false, below = false;
      for (const unsigned int v : cell->vertex_indices())
      {
        dist[v]                        = (cell->vertex(v) - origin) * n;
        (dist[v] >= 0 ? above : below) = true;
      }
      if (!(above && below))
        continue;
      std::vector<Point<3>> X, x;
      for (unsigned int l = 0; l < GeometryInfo<3>::lines_per_cell; ++l)
        add_crossing(cell,
                     GeometryInfo<3>::line_to_cell_vertices(l, 0),
                     GeometryInfo<3>::line_to_cell_vertices(l, 1),
                     dist,
                     u,
                     X,
                     x);
      if (X.size() < 3)
        continue;
      centre.reinit(cell);
      centre[displacement].get_function_gradients(u, grad_u);
      const Tensor<2, 3> F =
          Tensor<2, 3>(unit_symmetric_tensor<3>()) + grad_u[0];
      polygons.insert(polygons.end(),
                      {double(X.size()),
                       double(cell->material_id()),
                       PrincipalStrains::compute(F).e_max()});
      for (const unsigned int i : order_around(X, n))
      {
        put(polygons, X[i]);
        put(polygons, x[i]);
      }
      add_outline(cell, dist, u, outline_id, segments);
    }
    return unpack(origin,
                  n,
                  Utilities::MPI::gather(comm, polygons, 0),
                  Utilities::MPI::gather(comm, segments, 0));
  }
} // namespace softgrasp
