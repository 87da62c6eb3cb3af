#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/limb_surface.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  double LimbSurface::volume() const
  {
    double v = 0;
    for (const auto &t : triangles)
      v += t[0].dot(t[1].cross(t[2])) / 6;
    return v;
  }

  LimbSurface LimbSurface::of_layered_limb(const LimbGeometry &limb,
                                           const unsigned int  n)
  {
    LimbSurface  surface;
    const double L   = limb.length;
    surface.length   = L;
    const auto point = [&](const unsigned int i, const double x)
    {
      const auto   s = limb.semi_axes(4, x);
      const double t = 2 * M_PI * (i % n) / n;
      return Eigen::Vector3d(x, s[0] * std::cos(t), s[1] * std::sin(t));
    };
    const Eigen::Vector3d shoulder(-L / 2, 0, 0), elbow(L / 2, 0, 0);
    for (unsigned int i = 0; i < n; ++i)
    {
      const auto a0 = point(i, -L / 2), a1 = point(i + 1, -L / 2);
      const auto b0 = point(i, L / 2), b1 = point(i + 1, L / 2);
      surface.triangles.push_back({{a0, a1, b0}});
      surface.triangles.push_back({{a1, b1, b0}});
      surface.triangles.push_back({{shoulder, a1, a0}});
      surface.triangles.push_back({{elbow, b0, b1}});
    }
    return surface;
  }

  namespace
  {
    Eigen::Vector3d eigen(const Point<3> &p)
    {
      return Eigen::Vector3d(p[0], p[1], p[2]);
    }

    /// Close every rim of the open surface (its directed edges without a
    /// reverse) by a fan about the rim's centroid.
    void close_rims(const std::map<std::pair<unsigned, unsigned>, int> &edges,
                    const std::map<unsigned, Eigen::Vector3d>          &points,
                    std::vector<LimbSurface::Triangle>                 &out)
    {
      std::map<unsigned, unsigned> next; // rim edge a -> b, walked backwards
      for (const auto &[edge, count] : edges)
        if (edges.count({edge.second, edge.first}) == 0)
        {
          if (count != 1 || !next.emplace(edge.first, edge.second).second)
            throw InputError(
                "The skin (boundary id 0) of the limb mesh is not a manifold "
                "surface: an edge or a rim vertex is shared by more than two "
                "skin faces. Fix: give boundary id 0 only to the outer skin "
                "surface, as one connected layer of faces.");
        }
      while (!next.empty())
      {
        std::vector<unsigned> rim;
        for (unsigned v = next.begin()->first; next.count(v) != 0;)
        {
          rim.push_back(v);
          const unsigned w = next.at(v);
          next.erase(v);
          v = w;
        }
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (const unsigned v : rim)
          centre += points.at(v) / rim.size();
        // The skin runs a -> b along the rim, so the cap runs b -> a.
        for (unsigned k = 0; k < rim.size(); ++k)
          out.push_back({{centre,
                          points.at(rim[(k + 1) % rim.size()]),
                          points.at(rim[k])}});
      }
    }
  } // namespace

  LimbSurface LimbSurface::of_mesh(const Triangulation<3>  &mesh,
                                   const types::boundary_id skin)
  {
    LimbSurface                                  surface;
    std::map<unsigned, Eigen::Vector3d>          points;
    std::map<std::pair<unsigned, unsigned>, int> edges; // directed, counted
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto f : cell->face_indices())
      {
        const auto face = cell->face(f);
        if (!face->at_boundary() || face->boundary_id() != skin)
          continue;
        // deal.II numbers a quadrilateral's vertices lexicographically.
        std::array<unsigned, 4>        v = {{face->vertex_index(0),
                                             face->vertex_index(1),
                                             face->vertex_index(3),
                                             face->vertex_index(2)}};
        std::array<Eigen::Vector3d, 4> x;
        for (unsigned k = 0; k < 4; ++k)
          x[k] = points[v[k]] = eigen(mesh.get_vertices()[v[k]]);
        const Eigen::Vector3d normal = (x[2] - x[0]).cross(x[3] - x[1]);
        if (normal.dot(eigen(face->center()) - eigen(cell->center())) < 0)
        {
          std::swap(v[1], v[3]);
          std::swap(x[1], x[3]);
        }
        surface.triangles.push_back({{x[0], x[1], x[2]}});
        surface.triangles.push_back({{x[0], x[2], x[3]}});
        for (unsigned k = 0; k < 4; ++k)
          ++edges[{v[k], v[(k + 1) % 4]}];
      }
    if (surface.triangles.empty())
      throw InputError(
          "The limb mesh has no boundary faces with id 0, the skin the "
          "fingers touch and the rigid arm is made of. Fix: give the skin "
          "surface boundary id 0 (a Gmsh physical surface with tag 0), as "
          "in doc/layered_limb.md.");
    close_rims(edges, points, surface.triangles);

    double x_min = std::numeric_limits<double>::max(), x_max = -x_min;
    for (const auto &[index, x] : points)
    {
      (void)index;
      x_min = std::min(x_min, x[0]);
      x_max = std::max(x_max, x[0]);
    }
    surface.length = x_max - x_min;
    if (std::abs(x_max + x_min) > 0.01 * surface.length)
    {
      std::ostringstream message;
      message << "The limb mesh's skin spans x = " << x_min << " to " << x_max
              << " m; a limb mesh must be in the limb's own frame: axis "
                 "along x, centred at x = 0 (doc/layered_limb.md). Fix: "
                 "translate the mesh by "
              << -(x_max + x_min) / 2 << " m along x (and rotate its axis "
              << "onto x) before exporting it.";
      throw InputError(message.str());
    }
    if (surface.volume() <= 0)
      throw InputError(
          "The skin (boundary id 0) of the limb mesh, closed at its open "
          "ends, encloses no volume. Fix: give boundary id 0 to the outer "
          "skin surface around the limb.");
    return surface;
  }
} // namespace softgrasp
