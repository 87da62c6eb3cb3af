#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/triangle_mesh_shape.h>
#include <sstream>
#include <tuple>

namespace softgrasp
{
  namespace
  {
    using Eigen::Vector3d;

    /// Closest point of @p p on triangle (a, b, c) (Ericson, Real-Time
    /// Collision Detection, 5.1.5). @p feature: 0-2 a corner, 3-5 the edge
    /// ab, bc, ca, 6 the interior.
    Vector3d closest_on_triangle(const Vector3d &p,
                                 const Vector3d &a,
                                 const Vector3d &b,
                                 const Vector3d &c,
                                 int            &feature)
    {
      const Vector3d ab = b - a, ac = c - a, ap = p - a;
      const double   d1 = ab.dot(ap), d2 = ac.dot(ap);
      if (d1 <= 0 && d2 <= 0)
        return feature = 0, a;
      const Vector3d bp = p - b;
      const double   d3 = ab.dot(bp), d4 = ac.dot(bp);
      if (d3 >= 0 && d4 <= d3)
        return feature = 1, b;
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return feature = 3, Vector3d(a + d1 / (d1 - d3) * ab);
      const Vector3d cp = p - c;
      const double   d5 = ab.dot(cp), d6 = ac.dot(cp);
      if (d6 >= 0 && d5 <= d6)
        return feature = 2, c;
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return feature = 5, Vector3d(a + d2 / (d2 - d6) * ac);
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return feature = 4,
               Vector3d(b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
      const double denominator = 1 / (va + vb + vc);
      feature                  = 6;
      return a + ab * (vb * denominator) + ac * (vc * denominator);
    }

    double box_distance_squared(const Vector3d &x,
                                const Vector3d &lower,
                                const Vector3d &upper)
    {
      double sum = 0;
      for (unsigned int d = 0; d < 3; ++d)
      {
        const double excess = std::max({lower[d] - x[d], 0.0, x[d] - upper[d]});
        sum += excess * excess;
      }
      return sum;
    }

    /// Merges vertices with identical coordinates (STL stores each
    /// triangle's corners separately).
    class VertexWelder
    {
    public:
      unsigned int add(const Vector3d &v)
      {
        const auto key            = std::make_tuple(v[0], v[1], v[2]);
        const auto [it, inserted] = index.emplace(key, vertices.size());
        if (inserted)
          vertices.push_back(v);
        return it->second;
      }
      std::map<std::tuple<double, double, double>, unsigned int> index;
      std::vector<Vector3d>                                      vertices;
    };

    std::unique_ptr<TriangleMeshShape> read_stl(const std::string &filename,
                                                const double       scale)
    {
      std::ifstream in(filename, std::ios::binary);
      std::string   content((std::istreambuf_iterator<char>(in)),
                          std::istreambuf_iterator<char>());
      VertexWelder  welder;
      std::vector<std::array<unsigned, 3>> triangles;
      const bool ascii = content.compare(0, 5, "solid") == 0 &&
                         content.find("facet") != std::string::npos;
      if (ascii)
      {
        std::istringstream    text(content);
        std::string           word;
        std::vector<unsigned> corners;
        while (text >> word)
          if (word == "vertex")
          {
            Vector3d v;
            if (!(text >> v[0] >> v[1] >> v[2]) || !v.allFinite())
              throw InputError("The STL file '" + filename +
                               "' has a malformed vertex. Fix: export the "
                               "mesh again (ASCII or binary STL).");
            corners.push_back(welder.add(scale * v));
            if (corners.size() == 3)
            {
              triangles.push_back({{corners[0], corners[1], corners[2]}});
              corners.clear();
            }
          }
      }
      else
      {
        if (content.size() < 84)
          throw InputError("The STL file '" + filename +
                           "' is too short to be a binary STL. Fix: check "
                           "the file (it may be empty or truncated).");
        std::uint32_t count = 0;
        std::memcpy(&count, content.data() + 80, 4);
        if (content.size() != 84 + 50 * std::size_t(count))
          throw InputError("The binary STL file '" + filename + "' declares " +
                           std::to_string(count) + " triangles but has " +
                           std::to_string(content.size()) +
                           " bytes. Fix: the file is truncated or not an "
                           "STL file; export it again.");
        for (std::uint32_t t = 0; t < count; ++t)
        {
          std::array<unsigned, 3> corners;
          for (unsigned int k = 0; k < 3; ++k)
          {
            float xyz[3];
            std::memcpy(xyz, content.data() + 84 + 50 * t + 12 * (k + 1), 12);
            const Vector3d v(xyz[0], xyz[1], xyz[2]);
            if (!v.allFinite())
              throw InputError("The STL file '" + filename +
                               "' has a non-finite vertex in triangle " +
                               std::to_string(t) + ". Fix: repair the mesh.");
            corners[k] = welder.add(scale * v);
          }
          triangles.push_back(corners);
        }
      }
      return std::make_unique<TriangleMeshShape>(
          welder.vertices, triangles, "STL file '" + filename + "'");
    }

    std::unique_ptr<TriangleMeshShape> read_obj(const std::string &filename,
                                                const double       scale)
    {
      std::ifstream                        in(filename);
      std::vector<Vector3d>                vertices;
      std::vector<std::array<unsigned, 3>> triangles;
      std::string                          line;
      unsigned int                         number = 0;
      while (std::getline(in, line))
      {
        ++number;
        std::istringstream words(line);
        std::string        tag;
        if (!(words >> tag))
          continue;
        const std::string where =
            "OBJ file '" + filename + "', line " + std::to_string(number);
        if (tag == "v")
        {
          Vector3d v;
          if (!(words >> v[0] >> v[1] >> v[2]) || !v.allFinite())
            throw InputError(where + " has a malformed vertex. Fix: write "
                                     "'v x y z'.");
          vertices.push_back(scale * v);
        }
        else if (tag == "f")
        {
          std::vector<unsigned> corners;
          std::string           token;
          while (words >> token)
          {
            int index = 0;
            try
            {
              index = std::stoi(token.substr(0, token.find('/')));
            }
            catch (...)
            {
              throw InputError(where + " has a malformed face index '" + token +
                               "'. Fix: write 'f i j k'.");
            }
            const long resolved =
                index > 0 ? index - 1 : long(vertices.size()) + index;
            if (resolved < 0 || resolved >= long(vertices.size()))
              throw InputError(where + " refers to vertex " + token +
                               ", which is not defined before it. Fix: "
                               "check the face indices.");
            corners.push_back(resolved);
          }
          if (corners.size() < 3)
            throw InputError(where + " has a face with fewer than three "
                                     "vertices. Fix: remove or repair it.");
          for (unsigned int k = 1; k + 1 < corners.size(); ++k)
            triangles.push_back({{corners[0], corners[k], corners[k + 1]}});
        }
      }
      return std::make_unique<TriangleMeshShape>(
          vertices, triangles, "OBJ file '" + filename + "'");
    }
  } // namespace

  std::unique_ptr<TriangleMeshShape>
  TriangleMeshShape::read(const std::string &filename, const double scale)
  {
    std::ifstream probe(filename);
    if (!probe)
      throw InputError("Cannot open the mesh file '" + filename +
                       "'. Fix: check the path (relative to the working "
                       "directory).");
    if (!(scale > 0) || !std::isfinite(scale))
      throw InputError("The scale of the mesh file '" + filename +
                       "' must be positive. Fix: give e.g. 0.001 for a "
                       "file in millimetres.");
    std::string extension = filename.substr(filename.find_last_of('.') + 1);
    std::transform(
        extension.begin(), extension.end(), extension.begin(), ::tolower);
    if (extension == "stl")
      return read_stl(filename, scale);
    if (extension == "obj")
      return read_obj(filename, scale);
    throw InputError("The mesh file '" + filename +
                     "' is neither .stl nor .obj. Fix: convert it to STL or "
                     "OBJ.");
  }

  TriangleMeshShape::TriangleMeshShape(
      std::vector<Eigen::Vector3d>         vertices_in,
      std::vector<std::array<unsigned, 3>> triangles_in,
      const std::string                   &source)
      : vertices(std::move(vertices_in))
      , triangles(std::move(triangles_in))
  {
    if (triangles.size() < 4)
      throw InputError("The " + source + " has " +
                       std::to_string(triangles.size()) +
                       " triangles; a closed surface needs at least 4. Fix: "
                       "give a closed triangle mesh.");
    check_closed(source);
    // Outward orientation: a positive enclosed volume.
    double volume = 0;
    for (const auto &t : triangles)
      volume += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]])) / 6;
    if (volume < 0)
      for (auto &t : triangles)
        std::swap(t[1], t[2]);

    // The edges again, in the outward orientation: an edge's other
    // triangle is the one with the reversed edge.
    compute_normals(check_closed(source), source);
    Eigen::Vector3d lower = vertices[0], upper = vertices[0];
    for (const auto &v : vertices)
    {
      radius = std::max(radius, v.norm());
      lower  = lower.cwiseMin(v);
      upper  = upper.cwiseMax(v);
    }
    size = (upper - lower).norm();
    order.resize(triangles.size());
    for (unsigned int t = 0; t < order.size(); ++t)
      order[t] = t;
    tree.reserve(2 * triangles.size());
    build(0, triangles.size());
  }

  TriangleMeshShape::EdgeMap
  TriangleMeshShape::check_closed(const std::string &source) const
  {
    // Closed and consistently oriented: every directed edge appears once,
    // and its reverse once.
    EdgeMap edges;
    for (unsigned int t = 0; t < triangles.size(); ++t)
      for (unsigned int k = 0; k < 3; ++k)
      {
        const auto &tri = triangles[t];
        if (tri[k] >= vertices.size())
          throw InputError("The " + source +
                           " has a triangle with an "
                           "invalid vertex index. Fix: "
                           "repair the mesh.");
        if (!edges
                 .emplace(std::make_pair(tri[k], tri[(k + 1) % 3]),
                          std::make_pair(t, k))
                 .second)
          throw InputError("The " + source +
                           " is not a consistently oriented 2-manifold (an "
                           "edge is used twice in the same direction). Fix: "
                           "repair the mesh (e.g. with MeshLab) so that "
                           "every edge joins exactly two triangles.");
      }
    for (const auto &[edge, where] : edges)
      if (edges.count({edge.second, edge.first}) == 0)
        throw InputError(
            "The " + source + " is not closed: the edge between vertices " +
            std::to_string(edge.first) + " and " + std::to_string(edge.second) +
            " has only one triangle. Fix: close the holes of "
            "the mesh; the sign of the distance needs a closed "
            "surface.");

    return edges;
  }

  void TriangleMeshShape::compute_normals(const EdgeMap     &edges,
                                          const std::string &source)
  {
    face_normals.resize(triangles.size());
    vertex_normals.assign(vertices.size(), Eigen::Vector3d::Zero());
    for (unsigned int t = 0; t < triangles.size(); ++t)
    {
      const auto     &tri = triangles[t];
      Eigen::Vector3d n   = (vertices[tri[1]] - vertices[tri[0]])
                              .cross(vertices[tri[2]] - vertices[tri[0]]);
      if (n.norm() == 0)
        throw InputError("The " + source + " has a degenerate triangle (" +
                         std::to_string(t) +
                         "). Fix: remove zero-area "
                         "triangles.");
      face_normals[t] = n.normalized();
      for (unsigned int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d e1 =
            vertices[tri[(k + 1) % 3]] - vertices[tri[k]];
        const Eigen::Vector3d e2 =
            vertices[tri[(k + 2) % 3]] - vertices[tri[k]];
        const double angle = std::acos(
            std::clamp(e1.normalized().dot(e2.normalized()), -1.0, 1.0));
        vertex_normals[tri[k]] += angle * face_normals[t];
      }
    }
    for (auto &n : vertex_normals)
      n.normalize();
    edge_normals.resize(triangles.size());
    for (unsigned int t = 0; t < triangles.size(); ++t)
      for (unsigned int k = 0; k < 3; ++k)
      {
        const auto &tri   = triangles[t];
        const auto  other = edges.count({tri[(k + 1) % 3], tri[k]})
                                ? edges.at({tri[(k + 1) % 3], tri[k]}).first
                                : edges.at({tri[k], tri[(k + 1) % 3]}).first;
        edge_normals[t][k] =
            (face_normals[t] + face_normals[other]).normalized();
      }
  }

  int TriangleMeshShape::build(const unsigned int begin, const unsigned int end)
  {
    BoxNode node;
    node.lower = node.upper = vertices[triangles[order[begin]][0]];
    for (unsigned int i = begin; i < end; ++i)
      for (const unsigned v : triangles[order[i]])
      {
        node.lower = node.lower.cwiseMin(vertices[v]);
        node.upper = node.upper.cwiseMax(vertices[v]);
      }
    const int index = tree.size();
    tree.push_back(node);
    if (end - begin <= 4)
    {
      tree[index].begin = begin;
      tree[index].end   = end;
      return index;
    }
    unsigned int axis = 0;
    (node.upper - node.lower).maxCoeff(&axis);
    const auto centroid = [&](const unsigned t)
    {
      const auto &tri = triangles[t];
      return vertices[tri[0]][axis] + vertices[tri[1]][axis] +
             vertices[tri[2]][axis];
    };
    const unsigned int middle = (begin + end) / 2;
    std::nth_element(order.begin() + begin,
                     order.begin() + middle,
                     order.begin() + end,
                     [&](const unsigned a, const unsigned b)
                     { return centroid(a) < centroid(b); });
    const int left    = build(begin, middle);
    const int right   = build(middle, end);
    tree[index].left  = left;
    tree[index].right = right;
    return index;
  }

  void TriangleMeshShape::closest(const int              node_index,
                                  const Eigen::Vector3d &x,
                                  double                &best_squared,
                                  unsigned int          &best_triangle,
                                  Eigen::Vector3d       &best_point,
                                  int                   &best_feature) const
  {
    const BoxNode &node = tree[node_index];
    if (node.left < 0)
    {
      for (unsigned int i = node.begin; i < node.end; ++i)
      {
        const auto           &tri = triangles[order[i]];
        int                   feature;
        const Eigen::Vector3d p = closest_on_triangle(
            x, vertices[tri[0]], vertices[tri[1]], vertices[tri[2]], feature);
        const double squared = (x - p).squaredNorm();
        if (squared < best_squared)
        {
          best_squared  = squared;
          best_triangle = order[i];
          best_point    = p;
          best_feature  = feature;
        }
      }
      return;
    }
    const BoxNode &l = tree[node.left], &r = tree[node.right];
    const double   dl     = box_distance_squared(x, l.lower, l.upper);
    const double   dr     = box_distance_squared(x, r.lower, r.upper);
    const int      first  = dl <= dr ? node.left : node.right;
    const int      second = dl <= dr ? node.right : node.left;
    if (std::min(dl, dr) < best_squared)
      closest(first, x, best_squared, best_triangle, best_point, best_feature);
    if (std::max(dl, dr) < best_squared)
      closest(second, x, best_squared, best_triangle, best_point, best_feature);
  }

  ShapeQuery TriangleMeshShape::query(const Eigen::Vector3d &x) const
  {
    double          best_squared = std::numeric_limits<double>::infinity();
    unsigned int    triangle     = 0;
    int             feature      = 6;
    Eigen::Vector3d point;
    closest(0, x, best_squared, triangle, point, feature);

    const auto     &tri           = triangles[triangle];
    Eigen::Vector3d pseudo_normal = feature < 3 ? vertex_normals[tri[feature]]
                                    : feature < 6
                                        ? edge_normals[triangle][feature - 3]
                                        : face_normals[triangle];
    const Eigen::Vector3d d       = x - point;
    const double          length  = d.norm();
    const double          sign    = d.dot(pseudo_normal) >= 0 ? 1.0 : -1.0;
    ShapeQuery            q;
    q.distance = sign * length;
    q.closest  = point;
    q.normal   = length > 1e-9 * size ? Eigen::Vector3d(sign * d / length)
                                      : pseudo_normal;
    return q;
  }

  double TriangleMeshShape::bounding_radius() const
  {
    return radius;
  }

  std::string TriangleMeshShape::type() const
  {
    return type_name;
  }

  unsigned int TriangleMeshShape::n_triangles() const
  {
    return triangles.size();
  }

  std::unique_ptr<TriangleMeshShape>
  TriangleMeshShape::create(const ShapeSpec &spec)
  {
    if (!spec.triangles.empty())
      return std::make_unique<TriangleMeshShape>(
          spec.vertices, spec.triangles, "mesh geom '" + spec.geom_name + "'");
    if (spec.mesh_file.empty())
      throw InputError("Geom '" + spec.geom_name +
                       "' has type mesh but names no mesh file. Fix: set "
                       "its 'Mesh file' (an STL or OBJ file of a closed "
                       "surface).");
    return read(spec.mesh_file, spec.mesh_scale);
  }

  std::vector<std::vector<Eigen::Vector3d>> TriangleMeshShape::wireframe() const
  {
    // every edge once
    std::vector<std::vector<Eigen::Vector3d>>       lines;
    std::set<std::pair<unsigned int, unsigned int>> edges;
    for (const auto &t : triangles)
      for (unsigned int k = 0; k < 3; ++k)
      {
        const unsigned int a = t[k], b = t[(k + 1) % 3];
        if (edges.insert({std::min(a, b), std::max(a, b)}).second)
          lines.push_back({vertices[a], vertices[b]});
      }
    return lines;
  }

  SOFTGRASP_REGISTER_SHAPE(
      TriangleMeshShape,
      "a closed triangle surface read from the geom's mesh file (STL or OBJ)")
} // namespace softgrasp
