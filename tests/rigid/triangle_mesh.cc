// Triangle-mesh geoms (STL/OBJ) through the bounding-volume hierarchy:
//  - a box written as ASCII STL, binary STL and OBJ (quads), and inside out
//    (every triangle reversed), reads back with
//    the signed distance of the analytic BoxShape to 1e-12 at 2000 random
//    points inside and outside, and the same outward normals outside;
//  - an icosphere (1280 triangles) matches the analytic sphere within its
//    faceting error, with the right sign away from the surface;
//  - bad files give errors that name the file and the problem.
#include "../tests.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/box_shape.h>
#include <softgrasp/rigid/sphere_shape.h>
#include <softgrasp/rigid/triangle_mesh_shape.h>

using namespace softgrasp;
using Eigen::Vector3d;
using Triangles = std::vector<std::array<unsigned, 3>>;

namespace
{
  void write_ascii_stl(const std::string           &file,
                       const std::vector<Vector3d> &v,
                       const Triangles             &t)
  {
    std::ofstream out(file);
    out << std::setprecision(17) << "solid test\n";
    for (const auto &tri : t)
    {
      out << " facet normal 0 0 0\n  outer loop\n";
      for (const unsigned i : tri)
        out << "   vertex " << v[i][0] << " " << v[i][1] << " " << v[i][2]
            << "\n";
      out << "  endloop\n endfacet\n";
    }
    out << "endsolid test\n";
  }

  void write_binary_stl(const std::string           &file,
                        const std::vector<Vector3d> &v,
                        const Triangles             &t,
                        const bool                   truncate = false)
  {
    std::ofstream out(file, std::ios::binary);
    char          header[80] = {};
    out.write(header, 80);
    const std::uint32_t n = t.size();
    out.write(reinterpret_cast<const char *>(&n), 4);
    for (std::size_t k = 0; k < t.size() - (truncate ? 1 : 0); ++k)
    {
      float data[12] = {};
      for (unsigned int c = 0; c < 3; ++c)
        for (unsigned int d = 0; d < 3; ++d)
          data[3 + 3 * c + d] = static_cast<float>(v[t[k][c]][d]);
      out.write(reinterpret_cast<const char *>(data), 48);
      out.write("\0\0", 2);
    }
  }

  std::string error_of(const std::string &file)
  {
    try
    {
      TriangleMeshShape::read(file);
    }
    catch (const InputError &e)
    {
      return e.what();
    }
    return "no error";
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  // A box of half sizes (0.02, 0.01, 0.005) m; exactly representable in
  // float for the binary STL.
  const Vector3d        h(0.015625, 0.0078125, 0.00390625);
  std::vector<Vector3d> box_vertices;
  for (unsigned int i = 0; i < 8; ++i)
    box_vertices.emplace_back((i & 1 ? 1 : -1) * h[0],
                              (i & 2 ? 1 : -1) * h[1],
                              (i & 4 ? 1 : -1) * h[2]);
  // outward quads (corner bits x=1, y=2, z=4)
  const unsigned quads[6][4] = {{0, 2, 3, 1},
                                {4, 5, 7, 6},
                                {0, 1, 5, 4},
                                {2, 6, 7, 3},
                                {0, 4, 6, 2},
                                {1, 3, 7, 5}};
  Triangles      box_triangles;
  for (const auto &q : quads)
  {
    box_triangles.push_back({{q[0], q[1], q[2]}});
    box_triangles.push_back({{q[0], q[2], q[3]}});
  }
  write_ascii_stl("box_ascii.stl", box_vertices, box_triangles);
  write_binary_stl("box_binary.stl", box_vertices, box_triangles);
  // The same box inside out (every triangle reversed): turned outward.
  Triangles inside_out = box_triangles;
  for (auto &tri : inside_out)
    std::swap(tri[1], tri[2]);
  write_ascii_stl("box_inside_out.stl", box_vertices, inside_out);
  {
    std::ofstream obj("box.obj");
    obj << std::setprecision(17) << "# box\n";
    for (const auto &v : box_vertices)
      obj << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (const auto &q : quads)
      obj << "f " << q[0] + 1 << "/1/1 " << q[1] + 1 << " " << q[2] + 1 << " "
          << q[3] + 1 << "\n";
  }

  const BoxShape                         box(h);
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-2, 2);
  std::vector<Vector3d>                  points;
  for (unsigned int i = 0; i < 2000; ++i)
    points.emplace_back(
        uniform(random) * h[0], uniform(random) * h[1], uniform(random) * h[2]);
  for (const std::string file :
       {"box_ascii.stl", "box_binary.stl", "box.obj", "box_inside_out.stl"})
  {
    const auto mesh  = TriangleMeshShape::read(file);
    double     worst = 0, worst_normal = 0;
    for (const auto &x : points)
    {
      const auto a = mesh->query(x), b = box.query(x);
      worst = std::max(worst, std::abs(a.distance - b.distance));
      if (b.distance > 1e-6)
        worst_normal = std::max(worst_normal, (a.normal - b.normal).norm());
    }
    dealii::deallog << file << ": " << mesh->n_triangles()
                    << " triangles, distance error " << (worst < 1e-12)
                    << ", normal error " << (worst_normal < 1e-9) << std::endl;
    SG_CHECK(worst < 1e-12, file + ": signed distance of the box");
    SG_CHECK(worst_normal < 1e-9, file + ": outward normal of the box");
  }

  // Icosphere of radius R: subdivide an icosahedron three times.
  const double          R = 0.01, g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vector3d> v = {{-1, g, 0},
                             {1, g, 0},
                             {-1, -g, 0},
                             {1, -g, 0},
                             {0, -1, g},
                             {0, 1, g},
                             {0, -1, -g},
                             {0, 1, -g},
                             {g, 0, -1},
                             {g, 0, 1},
                             {-g, 0, -1},
                             {-g, 0, 1}};
  Triangles t = {{{0, 11, 5}},  {{0, 5, 1}},  {{0, 1, 7}},  {{0, 7, 10}},
                 {{0, 10, 11}}, {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}},
                 {{10, 7, 6}},  {{7, 1, 8}},  {{3, 9, 4}},  {{3, 4, 2}},
                 {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},  {{4, 9, 5}},
                 {{2, 4, 11}},  {{6, 2, 10}}, {{8, 6, 7}},  {{9, 8, 1}}};
  for (auto &p : v)
    p = R * p.normalized();
  for (unsigned int level = 0; level < 3; ++level)
  {
    std::map<std::pair<unsigned, unsigned>, unsigned> middle;
    const auto mid = [&](unsigned a, unsigned b)
    {
      const auto key = std::minmax(a, b);
      const auto it  = middle.find(key);
      if (it != middle.end())
        return it->second;
      v.push_back(R * (v[a] + v[b]).normalized());
      return middle[key] = v.size() - 1;
    };
    Triangles finer;
    for (const auto &tri : t)
    {
      const unsigned a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]),
                     c = mid(tri[2], tri[0]);
      finer.push_back({{tri[0], a, c}});
      finer.push_back({{tri[1], b, a}});
      finer.push_back({{tri[2], c, b}});
      finer.push_back({{a, b, c}});
    }
    t = finer;
  }
  write_ascii_stl("sphere.stl", v, t);
  const auto        sphere_mesh = TriangleMeshShape::read("sphere.stl");
  const SphereShape sphere(R);
  double facet = R; // distance of the nearest facet plane to the centre
  for (const auto &tri : t)
    facet = std::min(facet,
                     std::abs((v[tri[1]] - v[tri[0]])
                                  .cross(v[tri[2]] - v[tri[0]])
                                  .normalized()
                                  .dot(v[tri[0]])));
  const double sagitta = R - facet;
  double       worst   = 0;
  bool         signs   = true;
  for (unsigned int i = 0; i < 2000; ++i)
  {
    const Vector3d x(
        uniform(random) * R, uniform(random) * R, uniform(random) * R);
    const double a = sphere_mesh->query(x).distance;
    const double b = sphere.query(x).distance;
    worst          = std::max(worst, std::abs(a - b));
    if (std::abs(b) > sagitta)
      signs = signs && (a > 0) == (b > 0);
  }
  dealii::deallog << "icosphere: " << sphere_mesh->n_triangles()
                  << " triangles, distance error within the facet sagitta "
                  << (worst <= sagitta * (1 + 1e-9)) << ", signs " << signs
                  << std::endl;
  SG_CHECK(worst <= sagitta * (1 + 1e-9), "icosphere within faceting error");
  SG_CHECK(signs, "inside/outside of the icosphere");

  // Bad files.
  Triangles open = box_triangles;
  open.pop_back();
  write_ascii_stl("open.stl", box_vertices, open);
  write_binary_stl("truncated.stl", box_vertices, box_triangles, true);
  {
    std::ofstream("bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
    std::ofstream("box.ply") << "ply\n";
  }
  for (const std::string file :
       {"open.stl", "truncated.stl", "bad.obj", "box.ply", "missing.stl"})
  {
    const std::string message = error_of(file);
    dealii::deallog << file << ": " << message << std::endl;
    SG_CHECK(message.find(file) != std::string::npos &&
                 message.find("Fix:") != std::string::npos,
             "the error names the file and the fix");
  }
}
