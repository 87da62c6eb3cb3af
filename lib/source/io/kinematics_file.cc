#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/io/hdf5_record.h>
#include <softgrasp/io/kinematics_file.h>
#include <sstream>
#include <tuple>

namespace softgrasp
{
  namespace
  {
    using Hdf5Record::Group;
    using Hdf5Record::ReadError;

    const char *schema_name = "softgrasp kinematics";

    /// "a,b,c" of @p names, refusing names that cannot be stored.
    std::string join(const std::vector<std::string> &names)
    {
      std::string list;
      for (const auto &n : names)
      {
        if (n.empty() || n.find_first_of(",/") != std::string::npos)
          throw InputError("The name '" + n +
                           "' cannot be stored in a kinematics file. Fix: "
                           "use non-empty names without ',' or '/'.");
        list += (list.empty() ? "" : ",") + n;
      }
      return list;
    }

    /// The comma-separated names of @p items (bodies, geoms, joints).
    template <typename T> std::string names_list(const std::vector<T> &items)
    {
      std::vector<std::string> names;
      for (const auto &item : items)
        names.push_back(item.name);
      return join(names);
    }

    /// "body/geom,..." of @p links (forces or histories).
    template <typename T> std::string links_list(const std::vector<T> &links)
    {
      std::string list;
      for (const auto &l : links)
      {
        join({l.body, l.geom});
        list += (list.empty() ? "" : ",") + l.body + "/" + l.geom;
      }
      return list;
    }

    // ---- writing
    void write_poses(Group &group, const std::vector<Pose> &poses)
    {
      std::vector<double> p, q;
      for (const auto &pose : poses)
      {
        p.insert(p.end(),
                 {pose.position[0], pose.position[1], pose.position[2]});
        q.insert(q.end(),
                 {pose.orientation.w(),
                  pose.orientation.x(),
                  pose.orientation.y(),
                  pose.orientation.z()});
      }
      group.dataset("position", p, poses.size(), 3);
      group.dataset("quaternion", q, poses.size(), 4);
    }

    void write_vectors(Group                              &group,
                       const std::string                  &name,
                       const std::vector<Eigen::Vector3d> &vectors)
    {
      std::vector<double> values;
      for (const auto &v : vectors)
        values.insert(values.end(), {v[0], v[1], v[2]});
      group.dataset(name, values, vectors.size(), 3);
    }

    std::vector<double> values_of(const Eigen::Vector3d &v)
    {
      return {v[0], v[1], v[2]};
    }

    /// A mesh geom's vertices (n x 3, m) and triangles (m x 3 indices).
    void write_surface(Group &geom, const KinematicsData::Geom &g)
    {
      std::vector<double> vertices, triangles;
      for (const auto &v : g.vertices)
        vertices.insert(vertices.end(), {v[0], v[1], v[2]});
      for (const auto &t : g.triangles)
        triangles.insert(triangles.end(),
                         {double(t[0]), double(t[1]), double(t[2])});
      geom.dataset("vertices", vertices, g.vertices.size(), 3);
      geom.dataset("triangles", triangles, g.triangles.size(), 3);
    }

    void write_bodies(Group &root, const std::vector<KinematicsData::Body> &all)
    {
      Group bodies = root.group("bodies");
      bodies.attribute("names", names_list(all));
      for (const auto &b : all)
      {
        Group group = bodies.group(b.name);
        write_poses(group, b.poses);
        Group geoms = group.group("geoms");
        geoms.attribute("names", names_list(b.geoms));
        for (const auto &g : b.geoms)
        {
          Group geom = geoms.group(g.name);
          geom.attribute("type", g.type);
          geom.vector("size", values_of(g.size));
          write_poses(geom, {g.local_pose});
          if (!g.triangles.empty())
            write_surface(geom, g);
        }
      }
    }

    void write_joints(Group                                    &root,
                      const std::vector<KinematicsData::Joint> &all)
    {
      Group joints = root.group("joints");
      joints.attribute("names", names_list(all));
      for (const auto &j : all)
      {
        Group group = joints.group(j.name);
        group.vector("angle", j.angle);
        group.vector("target", j.target);
      }
    }

    void write_forces(Group &root, const KinematicsData &data)
    {
      Group equilibrium = root.group("equilibrium");
      equilibrium.attribute("time", data.equilibrium_time);
      equilibrium.attribute("links", links_list(data.equilibrium_forces));
      for (const auto &f : data.equilibrium_forces)
      {
        Group link = equilibrium.group(f.body).group(f.geom);
        link.vector("force", values_of(f.force));
        link.vector("normal", values_of(f.normal));
      }

      Group histories = root.group("link_forces");
      histories.attribute("links", links_list(data.link_forces));
      for (const auto &h : data.link_forces)
      {
        Group link = histories.group(h.body).group(h.geom);
        write_vectors(link, "force", h.force);
        write_vectors(link, "normal_force", h.normal_force);
      }
    }

    void write_phases(Group                                    &root,
                      const std::vector<KinematicsData::Phase> &all)
    {
      Group phases = root.group("phases");
      phases.attribute("names", names_list(all));
      for (const auto &p : all)
      {
        Group group = phases.group(p.name);
        for (const auto &[key, value] : {std::pair{"start_time", p.start_time},
                                         {"end_time", p.end_time},
                                         {"amount", p.amount}})
          group.attribute(key, value);
        group.attribute("unit", p.unit);
      }
    }

    /// Refuses what cannot be written: names with ',' or '/', force
    /// histories of another length than the time samples.
    void check_writable(const KinematicsData &data)
    {
      names_list(data.bodies);
      names_list(data.joints);
      names_list(data.phases);
      for (const auto &b : data.bodies)
        names_list(b.geoms);
      links_list(data.equilibrium_forces);
      for (const auto &h : data.link_forces)
        if (h.force.size() != data.time.size() ||
            h.normal_force.size() != data.time.size())
          throw InputError("The force history of link " + h.body + "/" +
                           h.geom + " has " + std::to_string(h.force.size()) +
                           " samples for " + std::to_string(data.time.size()) +
                           " times. Fix: record one force per time sample.");
    }

    // ---- reading
    /// The largest coordinate of a body position that a kinematics file may
    /// hold (m): a scene of a hand and a limb lies within it, while a
    /// diverged simulation or a wrong unit does not.
    constexpr double max_coordinate = 1000;

    /// Reads the groups of a kinematics file; HDF5 errors are ReadErrors.
    class KinematicsReader
    {
    public:
      KinematicsReader(const Hdf5Record::Reader &file,
                       const std::string        &filename)
          : file(file)
          , filename(filename)
      {
      }

      [[noreturn]] void fail(const std::string &what,
                             const std::string &fix) const
      {
        throw InputError("The kinematics file '" + filename + "' " + what +
                         ". Fix: " + fix + ".");
      }

      /// The names listed in the attribute @p name of the group @p path.
      std::vector<std::string> names(const std::string &path,
                                     const std::string &name) const
      {
        file.require_group(path);
        return dealii::Utilities::split_string_list(
            file.string_attribute(path, name), ',');
      }

      /// A vector of 3 values at @p path.
      Eigen::Vector3d vector(const std::string &path) const
      {
        const auto v = file.table(path, 3, 1);
        return {v[0], v[1], v[2]};
      }

      std::vector<Eigen::Vector3d> vectors(const std::string &path,
                                           const hsize_t      n) const
      {
        const auto                   values = file.table(path, n, 3);
        std::vector<Eigen::Vector3d> result;
        for (std::size_t i = 0; i + 2 < values.size(); i += 3)
          result.emplace_back(values[i], values[i + 1], values[i + 2]);
        return result;
      }

      std::vector<Pose> poses(const std::string &path, const hsize_t n) const
      {
        const auto        p = file.table(path + "/position", n, 3);
        const auto        q = file.table(path + "/quaternion", n, 4);
        std::vector<Pose> result(n);
        for (hsize_t i = 0; i < n; ++i)
        {
          result[i].position = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
          if (!(result[i].position.cwiseAbs().maxCoeff() <= max_coordinate))
          {
            std::ostringstream where;
            where << result[i].position.transpose().format(
                Eigen::IOFormat(6, Eigen::DontAlignCols, ", "));
            fail("has the position (" + where.str() + ") m in '" + path +
                     "/position' at row " + std::to_string(i) +
                     ", farther than " + std::to_string(int(max_coordinate)) +
                     " m from the origin in a coordinate",
                 "write positions in metres, of a scene within " +
                     std::to_string(int(max_coordinate)) +
                     " m of the origin (a robot hand and a limb span less "
                     "than 2 m); the simulation that wrote them diverged "
                     "or used another unit");
          }
          const Eigen::Quaterniond quaternion(
              q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
          if (quaternion.norm() < 1e-12)
            fail("has a zero quaternion in '" + path + "/quaternion' at row " +
                     std::to_string(i),
                 "write unit quaternions w, x, y, z");
          result[i].orientation = quaternion.normalized();
        }
        return result;
      }

      /// "body/geom" split into body and geom.
      std::pair<std::string, std::string>
      link_parts(const std::string &link, const std::string &where) const
      {
        const auto slash = link.find('/');
        if (slash == std::string::npos)
          fail("lists the link '" + link + "' in '" + where + "'",
               "name links as body/geom");
        return {link.substr(0, slash), link.substr(slash + 1)};
      }

      /// A mesh geom's vertices and triangles; indices checked.
      void read_surface(const std::string &path, KinematicsData::Geom &g) const
      {
        const auto v = file.table(path + "/vertices", 0, 3);
        const auto t = file.table(path + "/triangles", 0, 3);
        for (std::size_t i = 0; i + 2 < v.size(); i += 3)
          g.vertices.emplace_back(v[i], v[i + 1], v[i + 2]);
        for (std::size_t i = 0; i + 2 < t.size(); i += 3)
        {
          std::array<unsigned, 3> triangle;
          for (unsigned int k = 0; k < 3; ++k)
          {
            if (!(t[i + k] >= 0 && t[i + k] < g.vertices.size() &&
                  t[i + k] == std::floor(t[i + k])))
            {
              std::ostringstream index;
              index << t[i + k];
              fail("has a triangle with the vertex index " + index.str() +
                       " in '" + path + "/triangles', not one of its " +
                       std::to_string(g.vertices.size()) + " vertices",
                   "write the mesh again with the rigid-body program");
            }
            triangle[k] = static_cast<unsigned>(t[i + k]);
          }
          g.triangles.push_back(triangle);
        }
      }

      void read_header(KinematicsData &data) const;
      void read_bodies(KinematicsData &data) const;
      void read_joints(KinematicsData &data) const;
      void read_forces(KinematicsData &data) const;
      void read_phases(KinematicsData &data) const;

      const Hdf5Record::Reader &file;
      const std::string         filename;
    };

    void KinematicsReader::read_header(KinematicsData &data) const
    {
      if (file.string_attribute("/", "schema") != schema_name)
        fail("is not a softgrasp kinematics file (attribute 'schema')",
             "give the file written by the rigid-body program");
      const int version =
          static_cast<int>(file.number_attribute("/", "schema_version"));
      if (version < KinematicsData::oldest_schema_version ||
          version > KinematicsData::schema_version)
        fail("has schema version " + std::to_string(version) +
                 ", this softgrasp reads versions " +
                 std::to_string(KinematicsData::oldest_schema_version) +
                 " to " + std::to_string(KinematicsData::schema_version),
             "write the file again with the matching softgrasp");
      data.source = file.string_attribute("/", "source");
      data.time   = file.table("/time", 0, 1);
      if (data.time.empty())
        fail("has an empty '/time'", "record at least one sample");
      for (std::size_t i = 1; i < data.time.size(); ++i)
        if (!(data.time[i] > data.time[i - 1]))
          fail("has non-increasing times in '/time' at row " +
                   std::to_string(i),
               "record samples at strictly increasing times");
    }

    void KinematicsReader::read_bodies(KinematicsData &data) const
    {
      for (const auto &name : names("/bodies", "names"))
      {
        const std::string    path = "/bodies/" + name;
        KinematicsData::Body body;
        body.name  = name;
        body.poses = poses(path, data.time.size());
        for (const auto &geom_name : names(path + "/geoms", "names"))
        {
          const std::string    geom_path = path + "/geoms/" + geom_name;
          KinematicsData::Geom g;
          file.require_group(geom_path);
          g.name       = geom_name;
          g.type       = file.string_attribute(geom_path, "type");
          g.size       = vector(geom_path + "/size");
          g.local_pose = poses(geom_path, 1)[0];
          if (g.type == "mesh")
            read_surface(geom_path, g);
          body.geoms.push_back(g);
        }
        data.bodies.push_back(body);
      }
    }

    void KinematicsReader::read_joints(KinematicsData &data) const
    {
      const hsize_t n = data.time.size();
      for (const auto &name : names("/joints", "names"))
      {
        const std::string     path = "/joints/" + name;
        KinematicsData::Joint joint;
        joint.name   = name;
        joint.angle  = file.table(path + "/angle", n, 1);
        joint.target = file.table(path + "/target", n, 1);
        data.joints.push_back(joint);
      }
    }

    void KinematicsReader::read_forces(KinematicsData &data) const
    {
      file.require_group("/equilibrium");
      data.equilibrium_time = file.number_attribute("/equilibrium", "time");
      for (const auto &link : names("/equilibrium", "links"))
      {
        const std::string         path = "/equilibrium/" + link;
        KinematicsData::LinkForce f;
        std::tie(f.body, f.geom) = link_parts(link, "/equilibrium");
        file.require_group(path);
        f.force  = vector(path + "/force");
        f.normal = vector(path + "/normal");
        data.equilibrium_forces.push_back(f);
      }

      for (const auto &link : names("/link_forces", "links"))
      {
        const std::string           path = "/link_forces/" + link;
        KinematicsData::LinkHistory h;
        std::tie(h.body, h.geom) = link_parts(link, "/link_forces");
        file.require_group(path);
        h.force        = vectors(path + "/force", data.time.size());
        h.normal_force = vectors(path + "/normal_force", data.time.size());
        data.link_forces.push_back(h);
      }
    }

    void KinematicsReader::read_phases(KinematicsData &data) const
    {
      for (const auto &name : names("/phases", "names"))
      {
        const std::string     path = "/phases/" + name;
        KinematicsData::Phase p;
        file.require_group(path);
        p.name       = name;
        p.start_time = file.number_attribute(path, "start_time");
        p.end_time   = file.number_attribute(path, "end_time");
        p.amount     = file.number_attribute(path, "amount");
        if (file.has_attribute(path, "unit"))
          p.unit = file.string_attribute(path, "unit");
        if (!(p.end_time > p.start_time) || !std::isfinite(p.amount))
          fail("has the phase '" + path + "' with start_time " +
                   std::to_string(p.start_time) + " s, end_time " +
                   std::to_string(p.end_time) + " s, amount " +
                   std::to_string(p.amount),
               "write finite values with end_time > start_time");
        const double slack = 1e-9 * (data.time.back() - data.time.front());
        if (p.start_time < data.time.front() - slack ||
            p.end_time > data.time.back() + slack)
          fail("has the phase '" + path + "' from " +
                   std::to_string(p.start_time) + " s to " +
                   std::to_string(p.end_time) +
                   " s, outside the recorded samples (" +
                   std::to_string(data.time.front()) + " s to " +
                   std::to_string(data.time.back()) + " s)",
               "record the whole phase, or give its times within the "
               "recorded samples");
        data.phases.push_back(p);
      }
    }

    /// What a user does about a file that fails to read with @p kind.
    std::string fix_for(const ReadError::Kind kind)
    {
      switch (kind)
      {
      case ReadError::Kind::wrong_shape:
        return "write one row per time sample (doc/kinematics_file.md)";
      case ReadError::Kind::damaged:
        return "write it again with the rigid-body program";
      case ReadError::Kind::not_finite:
        return "check the simulation that wrote it";
      default:
        return "write it as described in doc/kinematics_file.md";
      }
    }
  } // namespace

  const KinematicsData::Phase &
  KinematicsData::phase(const std::string &name) const
  {
    std::string names;
    for (const auto &p : phases)
    {
      if (p.name == name)
        return p;
      names += (names.empty() ? "" : ", ") + p.name;
    }
    throw InputError("The kinematics (" + source + ") have no phase '" + name +
                     "'; they have: " + (names.empty() ? "none" : names) +
                     ". Fix: run the rigid-body program with that phase "
                     "enabled, or choose one of these.");
  }

  KinematicsData KinematicsData::slice(const double start,
                                       const double end) const
  {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < time.size(); ++i)
      if (time[i] >= start - 1e-12 && time[i] <= end + 1e-12)
        kept.push_back(i);
    if (kept.size() < 2)
      throw InputError("The kinematics (" + source +
                       ") have fewer than two "
                       "samples between " +
                       std::to_string(start) + " s and " + std::to_string(end) +
                       " s. Fix: record the phase with "
                       "more samples.");
    auto pick = [&kept](const auto &values)
    {
      std::decay_t<decltype(values)> result;
      for (const auto i : kept)
        result.push_back(values[i]);
      return result;
    };
    KinematicsData cut = *this;
    cut.time           = pick(time);
    for (auto &t : cut.time)
      t -= start;
    for (auto &b : cut.bodies)
      b.poses = pick(b.poses);
    for (auto &j : cut.joints)
    {
      j.angle  = pick(j.angle);
      j.target = pick(j.target);
    }
    for (auto &h : cut.link_forces)
    {
      h.force        = pick(h.force);
      h.normal_force = pick(h.normal_force);
    }
    cut.equilibrium_time -= start;
    cut.phases.clear();
    for (auto p : phases)
      if (p.start_time >= start - 1e-12 && p.end_time <= end + 1e-12)
      {
        p.start_time -= start;
        p.end_time -= start;
        cut.phases.push_back(p);
      }
    return cut;
  }

  void write_kinematics_file(const KinematicsData &data,
                             const std::string    &filename)
  {
    check_writable(data);
    Hdf5Record::write(
        filename,
        [&](Group &root)
        {
          root.attribute("schema", std::string(schema_name));
          root.attribute("schema_version", KinematicsData::schema_version);
          root.attribute("source", data.source);
          root.vector("time", data.time);
          write_bodies(root, data.bodies);
          write_joints(root, data.joints);
          write_forces(root, data);
          write_phases(root, data.phases);
        },
        Hdf5Record::Strings::fixed_length);
  }

  KinematicsData read_kinematics_file(const std::string &filename)
  {
    if (!std::ifstream(filename) || std::filesystem::is_directory(filename))
      throw InputError("Cannot open the kinematics file '" + filename +
                       "'. Fix: check the path (relative to the working "
                       "directory), or run the rigid-body program that "
                       "writes it.");
    const Hdf5Record::QuietErrors quiet;
    if (H5Fis_hdf5(filename.c_str()) <= 0)
      throw InputError("The kinematics file '" + filename +
                       "' is not an HDF5 file. Fix: give the .h5 file "
                       "written by the rigid-body program.");
    KinematicsData data;
    try
    {
      const Hdf5Record::Reader file(filename);
      const KinematicsReader   reader(file, filename);
      const auto               size = std::filesystem::file_size(filename);
      if (size < file.end_of_data())
        reader.fail("is truncated (" + std::to_string(size) + " of " +
                        std::to_string(file.end_of_data()) + " bytes)",
                    "write it again with the rigid-body program (was the "
                    "disk full, or the copy interrupted?)");
      reader.read_header(data);
      reader.read_bodies(data);
      reader.read_joints(data);
      reader.read_forces(data);
      reader.read_phases(data);
    }
    catch (const ReadError &e)
    {
      throw InputError("The kinematics file '" + filename + "' " + e.what() +
                       ". Fix: " + fix_for(e.kind) + ".");
    }
    return data;
  }

  RigidBodySet rigid_bodies_from(const KinematicsData &data)
  {
    RigidBodySet set;
    for (const auto &b : data.bodies)
    {
      if (b.geoms.empty())
        continue;
      RigidBody body(b.name,
                     PoseTrajectory(data.time,
                                    b.poses,
                                    "kinematics body '" + b.name + "'"));
      for (const auto &g : b.geoms)
      {
        ShapeSpec spec;
        spec.type      = g.type;
        spec.size      = g.size;
        spec.geom_name = b.name + "/" + g.name;
        spec.vertices  = g.vertices;
        spec.triangles = g.triangles;
        body.add_geom(g.name, create_shape(spec), g.local_pose);
      }
      const unsigned int index = set.add_body(body);
      for (const auto &f : data.equilibrium_forces)
        if (f.body == b.name)
          for (unsigned int g = 0; g < b.geoms.size(); ++g)
            if (b.geoms[g].name == f.geom && f.normal.norm() > 0)
              set.set_reference_normal(index, g, f.normal);
    }
    return set;
  }
} // namespace softgrasp
