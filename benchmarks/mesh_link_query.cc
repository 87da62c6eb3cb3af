// Benchmark (not a test): the cost of one contact query (signed distance,
// normal, closest point) on a triangle-mesh link against an analytic
// capsule link of a similar size, as the contact update asks it for every
// slave node near a link. Issue 54's bound: a 5,000-triangle pad at most
// twice a capsule.
//
//   mesh_link_query [queries per round = 200000] [cells per box edge = 20]
//                   [rounds = 7]
//
// The mesh is a box of 18 x 18 x 58 mm whose faces are split into
// k x k cells of two triangles each (12 k^2 triangles: 4800 for k = 20),
// the capsule has radius 9 mm and a 40 mm segment (the hand's distal
// link). The query points lie from 2 mm inside to 5 mm outside each
// link's surface (where a contact search asks). Capsule and mesh rounds
// alternate (A B A B ...) and the medians of the time per query are
// compared, so the ratio holds on a noisy machine.
#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <map>
#include <random>
#include <softgrasp/rigid/capsule_shape.h>
#include <softgrasp/rigid/triangle_mesh_shape.h>

using namespace softgrasp;
using Eigen::Vector3d;

namespace
{
  /// A box of half sizes @p h whose faces are k x k grids of two triangles
  /// per cell, counter-clockwise from outside, vertices shared.
  TriangleMeshShape subdivided_box(const Vector3d &h, const unsigned int k)
  {
    std::map<std::array<unsigned, 3>, unsigned> index;
    std::vector<Vector3d>                       vertices;
    std::vector<std::array<unsigned, 3>>        triangles;
    const auto vertex = [&](const std::array<unsigned, 3> &p)
    {
      const auto [it, added] = index.emplace(p, vertices.size());
      if (added)
        vertices.emplace_back((2.0 * p[0] / k - 1) * h[0],
                              (2.0 * p[1] / k - 1) * h[1],
                              (2.0 * p[2] / k - 1) * h[2]);
      return it->second;
    };
    for (unsigned int axis = 0; axis < 3; ++axis)
      for (const unsigned side : {0u, k})
      {
        const unsigned a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (unsigned i = 0; i < k; ++i)
          for (unsigned j = 0; j < k; ++j)
          {
            std::array<std::array<unsigned, 3>, 4> q;
            for (unsigned c = 0; c < 4; ++c)
            {
              q[c][axis] = side;
              q[c][a]    = i + (c == 1 || c == 2);
              q[c][b]    = j + (c >= 2);
            }
            std::array<unsigned, 4> v;
            for (unsigned c = 0; c < 4; ++c)
              v[c] = vertex(q[c]);
            // (a, b, axis) is right-handed: a b-then-a order faces -axis
            if (side == k)
              triangles.insert(triangles.end(),
                               {{{v[0], v[1], v[2]}}, {{v[0], v[2], v[3]}}});
            else
              triangles.insert(triangles.end(),
                               {{{v[0], v[2], v[1]}}, {{v[0], v[3], v[2]}}});
          }
      }
    return TriangleMeshShape(vertices, triangles, "benchmark box");
  }

  /// Seconds per query of @p shape over @p points; @p sink keeps the
  /// results alive.
  double time_per_query(const Shape                 &shape,
                        const std::vector<Vector3d> &points,
                        double                      &sink)
  {
    const auto start = std::chrono::steady_clock::now();
    for (const auto &x : points)
      sink += shape.query(x).distance;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
               .count() /
           points.size();
  }

  double median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned          queries = argc > 1 ? std::stoul(argv[1]) : 200000;
  const unsigned          k       = argc > 2 ? std::stoul(argv[2]) : 20;
  const unsigned          rounds  = argc > 3 ? std::stoul(argv[3]) : 7;
  const TriangleMeshShape mesh    = subdivided_box({0.009, 0.009, 0.029}, k);
  const CapsuleShape      capsule(0.009, 0.02);

  // where a contact search asks: tissue nodes from 2 mm inside to 5 mm
  // outside each link's surface (a point of the surface moved along its
  // normal); the same offsets for both links
  std::mt19937                           random(1);
  std::uniform_real_distribution<double> u(-1, 1), offset(-0.002, 0.005);
  std::vector<Vector3d> capsule_points(queries), mesh_points(queries);
  for (unsigned i = 0; i < queries; ++i)
  {
    const double   d = offset(random);
    const Vector3d c(0.009 * u(random), 0.009 * u(random), 0.029 * u(random));
    const auto     on_mesh = mesh.query(c);
    mesh_points[i]         = on_mesh.closest + d * on_mesh.normal;
    const auto on_capsule  = capsule.query(c);
    capsule_points[i]      = on_capsule.closest + d * on_capsule.normal;
  }

  double              sink = 0;
  std::vector<double> t_capsule, t_mesh;
  for (unsigned r = 0; r < rounds; ++r)
  {
    t_capsule.push_back(time_per_query(capsule, capsule_points, sink));
    t_mesh.push_back(time_per_query(mesh, mesh_points, sink));
  }
  std::cout << "mesh: " << mesh.n_triangles() << " triangles; " << queries
            << " queries per round, " << rounds << " rounds (checksum " << sink
            << ")\n"
            << "capsule: " << median(t_capsule) * 1e9 << " ns per query\n"
            << "mesh:    " << median(t_mesh) * 1e9 << " ns per query\n"
            << "mesh / capsule: " << median(t_mesh) / median(t_capsule)
            << std::endl;
}
