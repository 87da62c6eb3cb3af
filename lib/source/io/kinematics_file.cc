#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/io/kinematics_file.h>
#include <tuple>

namespace softgrasp
{
  namespace
  {
    const char *schema_name = "softgrasp kinematics";

    /// Closes an HDF5 handle when it goes out of scope.
    struct Handle
    {
      hid_t id;
      herr_t (*close)(hid_t);
      Handle(hid_t id, herr_t (*close)(hid_t))
          : id(id)
          , close(close)
      {
      }
      ~Handle()
      {
        if (id >= 0)
          close(id);
      }
      operator hid_t() const
      {
        return id;
      }
    };

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

    /// "a,b,c" of link names (already checked).
    std::string join_links(const std::vector<std::string> &links)
    {
      std::string list;
      for (const auto &l : links)
        list += (list.empty() ? "" : ",") + l;
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

    // ---- writing
    void write_string_attribute(hid_t              object,
                                const std::string &name,
                                const std::string &value)
    {
      Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(type, value.size() + 1);
      Handle space(H5Screate(H5S_SCALAR), H5Sclose);
      Handle attribute(
          H5Acreate2(
              object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
      H5Awrite(attribute, type, value.c_str());
    }

    template <typename T>
    void write_number_attribute(hid_t              object,
                                const std::string &name,
                                const T            value,
                                hid_t              type)
    {
      Handle space(H5Screate(H5S_SCALAR), H5Sclose);
      Handle attribute(
          H5Acreate2(
              object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
      H5Awrite(attribute, type, &value);
    }

    void write_dataset(hid_t                      location,
                       const std::string         &name,
                       const std::vector<double> &values,
                       const hsize_t              rows,
                       const hsize_t              columns)
    {
      const hsize_t dims[2] = {rows, columns};
      Handle        space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr),
                   H5Sclose);
      // One chunk with a Fletcher-32 checksum: a damaged value is refused
      // on reading instead of being used.
      Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
      if (rows * columns > 0)
      {
        H5Pset_chunk(properties, columns == 1 ? 1 : 2, dims);
        H5Pset_fletcher32(properties);
      }
      Handle set(H5Dcreate2(location,
                            name.c_str(),
                            H5T_NATIVE_DOUBLE,
                            space,
                            H5P_DEFAULT,
                            properties,
                            H5P_DEFAULT),
                 H5Dclose);
      if (rows * columns > 0)
        H5Dwrite(set,
                 H5T_NATIVE_DOUBLE,
                 H5S_ALL,
                 H5S_ALL,
                 H5P_DEFAULT,
                 values.data());
    }

    void write_poses(hid_t location, const std::vector<Pose> &poses)
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
      write_dataset(location, "position", p, poses.size(), 3);
      write_dataset(location, "quaternion", q, poses.size(), 4);
    }

    void write_vectors(hid_t                               location,
                       const std::string                  &name,
                       const std::vector<Eigen::Vector3d> &vectors)
    {
      std::vector<double> values;
      for (const auto &v : vectors)
        values.insert(values.end(), {v[0], v[1], v[2]});
      write_dataset(location, name, values, vectors.size(), 3);
    }

    Handle create_group(hid_t location, const std::string &name)
    {
      return Handle(
          H5Gcreate2(
              location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
          H5Gclose);
    }

    // ---- reading
    class Reader
    {
    public:
      explicit Reader(const std::string &filename)
          : filename(filename)
      {
      }

      [[noreturn]] void fail(const std::string &what,
                             const std::string &fix) const
      {
        throw InputError("The kinematics file '" + filename + "' " + what +
                         ". Fix: " + fix + ".");
      }

      Handle open_group(hid_t location, const std::string &path) const
      {
        if (H5Lexists(location, path.c_str(), H5P_DEFAULT) <= 0)
          fail("has no group '" + path + "'",
               "write it as described in doc/kinematics_file.md");
        return Handle(H5Gopen2(location, path.c_str(), H5P_DEFAULT), H5Gclose);
      }

      std::string string_attribute(hid_t              object,
                                   const std::string &name,
                                   const std::string &where) const
      {
        if (H5Aexists(object, name.c_str()) <= 0)
          fail("has no attribute '" + name + "' on '" + where + "'",
               "write it as described in doc/kinematics_file.md");
        Handle attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
        Handle type(H5Aget_type(attribute), H5Tclose);
        const size_t size = H5Tget_size(type);
        if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
          fail("has a non-string attribute '" + name + "' on '" + where + "'",
               "store it as a fixed-length string");
        std::string value(size, '\0');
        if (H5Aread(attribute, type, value.data()) < 0)
          fail("has an unreadable attribute '" + name + "' on '" + where +
                   "' (the file is damaged)",
               "write it again with the rigid-body program");
        return value.substr(0, value.find('\0'));
      }

      double number_attribute(hid_t              object,
                              const std::string &name,
                              const std::string &where) const
      {
        if (H5Aexists(object, name.c_str()) <= 0)
          fail("has no attribute '" + name + "' on '" + where + "'",
               "write it as described in doc/kinematics_file.md");
        Handle attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
        double value = 0;
        if (H5Aread(attribute, H5T_NATIVE_DOUBLE, &value) < 0)
          fail("has an unreadable attribute '" + name + "' on '" + where +
                   "' (the file is damaged)",
               "write it again with the rigid-body program");
        return value;
      }

      /// A dataset of @p rows x @p columns (rows = 0: any), all finite.
      std::vector<double> dataset(hid_t              location,
                                  const std::string &name,
                                  const std::string &path,
                                  const hsize_t      rows,
                                  const hsize_t      columns) const
      {
        if (H5Lexists(location, name.c_str(), H5P_DEFAULT) <= 0)
          fail("has no dataset '" + path + "'",
               "write it as described in doc/kinematics_file.md");
        Handle    set(H5Dopen2(location, name.c_str(), H5P_DEFAULT), H5Dclose);
        Handle    space(H5Dget_space(set), H5Sclose);
        hsize_t   dims[2] = {0, 1};
        const int rank    = H5Sget_simple_extent_ndims(space);
        H5Sget_simple_extent_dims(space, dims, nullptr);
        if (rank < 1 || rank > 2 || (rank == 1 && columns != 1) ||
            (rank == 2 && dims[1] != columns) || (rows > 0 && dims[0] != rows))
          fail("has the dataset '" + path + "' with shape " +
                   std::to_string(dims[0]) +
                   (rank == 2 ? " x " + std::to_string(dims[1]) : "") +
                   ", expected " + (rows > 0 ? std::to_string(rows) : "n") +
                   (columns > 1 ? " x " + std::to_string(columns) : ""),
               "write one row per time sample (doc/kinematics_file.md)");
        std::vector<double> values(dims[0] * columns);
        if (!values.empty() && H5Dread(set,
                                       H5T_NATIVE_DOUBLE,
                                       H5S_ALL,
                                       H5S_ALL,
                                       H5P_DEFAULT,
                                       values.data()) < 0)
          fail("has an unreadable dataset '" + path +
                   "' (the file is damaged or truncated)",
               "write it again with the rigid-body program");
        for (std::size_t i = 0; i < values.size(); ++i)
          if (!std::isfinite(values[i]))
            fail("has a non-finite value (NaN or inf) in '" + path +
                     "' at row " + std::to_string(i / columns),
                 "check the simulation that wrote it");
        return values;
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

      std::vector<Pose>
      poses(hid_t location, const std::string &path, const hsize_t n) const
      {
        const auto p = dataset(location, "position", path + "/position", n, 3);
        const auto q =
            dataset(location, "quaternion", path + "/quaternion", n, 4);
        std::vector<Pose> result(n);
        for (hsize_t i = 0; i < n; ++i)
        {
          result[i].position = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
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

      std::string filename;
    };

    std::vector<std::string> names_of(const std::string &list)
    {
      return dealii::Utilities::split_string_list(list, ',');
    }

    /// The group @p name in @p location, created if missing.
    Handle group_in(hid_t location, const std::string &name)
    {
      if (H5Lexists(location, name.c_str(), H5P_DEFAULT) <= 0)
        create_group(location, name);
      return Handle(H5Gopen2(location, name.c_str(), H5P_DEFAULT), H5Gclose);
    }

    /// "body/geom" of a link, rejecting names with ',' or '/'.
    std::string link_name(const std::string &body, const std::string &geom)
    {
      join({body, geom});
      return body + "/" + geom;
    }

    std::vector<Eigen::Vector3d> vectors_of(const std::vector<double> &values)
    {
      std::vector<Eigen::Vector3d> result;
      for (std::size_t i = 0; i + 2 < values.size(); i += 3)
        result.emplace_back(values[i], values[i + 1], values[i + 2]);
      return result;
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
    RunManifest::note(filename);
    const std::string temporary = AtomicFile::temporary_name(filename);
    {
      // The HDF5 1.10 file format: its metadata (object headers with the
      // attributes) carries checksums, so damage is detected on reading.
      Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_V110);
      Handle file(
          H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access),
          H5Fclose);
      if (file < 0)
        throw InputError("Cannot create the kinematics file '" + filename +
                         "'. Fix: check that its directory exists and is "
                         "writable.");
      write_string_attribute(file, "schema", schema_name);
      write_number_attribute<int>(file,
                                  "schema_version",
                                  KinematicsData::schema_version,
                                  H5T_NATIVE_INT);
      write_string_attribute(file, "source", data.source);
      write_dataset(file, "time", data.time, data.time.size(), 1);

      Handle bodies = create_group(file, "bodies");
      write_string_attribute(bodies, "names", names_list(data.bodies));
      for (const auto &b : data.bodies)
      {
        Handle group = create_group(bodies, b.name);
        write_poses(group, b.poses);
        Handle geoms = create_group(group, "geoms");
        write_string_attribute(geoms, "names", names_list(b.geoms));
        for (const auto &g : b.geoms)
        {
          Handle geom = create_group(geoms, g.name);
          write_string_attribute(geom, "type", g.type);
          write_dataset(geom, "size", {g.size[0], g.size[1], g.size[2]}, 3, 1);
          write_poses(geom, {g.local_pose});
        }
      }

      Handle joints = create_group(file, "joints");
      write_string_attribute(joints, "names", names_list(data.joints));
      for (const auto &j : data.joints)
      {
        Handle group = create_group(joints, j.name);
        write_dataset(group, "angle", j.angle, j.angle.size(), 1);
        write_dataset(group, "target", j.target, j.target.size(), 1);
      }

      Handle equilibrium = create_group(file, "equilibrium");
      write_number_attribute<double>(
          equilibrium, "time", data.equilibrium_time, H5T_NATIVE_DOUBLE);
      std::vector<std::string> links;
      for (const auto &f : data.equilibrium_forces)
        links.push_back(link_name(f.body, f.geom));
      write_string_attribute(equilibrium, "links", join_links(links));
      for (const auto &f : data.equilibrium_forces)
      {
        Handle body = group_in(equilibrium, f.body);
        Handle link = create_group(body, f.geom);
        write_dataset(
            link, "force", {f.force[0], f.force[1], f.force[2]}, 3, 1);
        write_dataset(
            link, "normal", {f.normal[0], f.normal[1], f.normal[2]}, 3, 1);
      }

      Handle histories = create_group(file, "link_forces");
      links.clear();
      for (const auto &h : data.link_forces)
      {
        links.push_back(link_name(h.body, h.geom));
        if (h.force.size() != data.time.size() ||
            h.normal_force.size() != data.time.size())
          throw InputError("The force history of link " + links.back() +
                           " has " + std::to_string(h.force.size()) +
                           " samples for " + std::to_string(data.time.size()) +
                           " times. Fix: record one force per time sample.");
      }
      write_string_attribute(histories, "links", join_links(links));
      for (const auto &h : data.link_forces)
      {
        Handle body = group_in(histories, h.body);
        Handle link = create_group(body, h.geom);
        write_vectors(link, "force", h.force);
        write_vectors(link, "normal_force", h.normal_force);
      }

      Handle phases = create_group(file, "phases");
      write_string_attribute(phases, "names", names_list(data.phases));
      for (const auto &p : data.phases)
      {
        Handle group = create_group(phases, p.name);
        for (const auto &[key, value] : {std::pair{"start_time", p.start_time},
                                         {"end_time", p.end_time},
                                         {"amount", p.amount}})
          write_number_attribute<double>(group, key, value, H5T_NATIVE_DOUBLE);
      }
    }
    AtomicFile::commit(temporary, filename);
  }

  KinematicsData read_kinematics_file(const std::string &filename)
  {
    if (!std::ifstream(filename) || std::filesystem::is_directory(filename))
      throw InputError("Cannot open the kinematics file '" + filename +
                       "'. Fix: check the path (relative to the working "
                       "directory), or run the rigid-body program that "
                       "writes it.");
    // HDF5 would print its own error stack; the messages below say more.
    H5E_auto2_t old_function;
    void       *old_data;
    H5Eget_auto2(H5E_DEFAULT, &old_function, &old_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    struct Restore
    {
      H5E_auto2_t f;
      void       *d;
      ~Restore()
      {
        H5Eset_auto2(H5E_DEFAULT, f, d);
      }
    } restore{old_function, old_data};

    const Reader reader(filename);
    if (H5Fis_hdf5(filename.c_str()) <= 0)
      reader.fail("is not an HDF5 file",
                  "give the .h5 file written by the rigid-body program");
    Handle  file(H5Fopen(filename.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                H5Fclose);
    haddr_t end_of_data = 0;
    if (file < 0 || H5Fget_eoa(file, &end_of_data) < 0)
      reader.fail("is damaged: HDF5 cannot open it",
                  "write it again with the rigid-body program");
    if (std::filesystem::file_size(filename) < end_of_data)
      reader.fail("is truncated (" +
                      std::to_string(std::filesystem::file_size(filename)) +
                      " of " + std::to_string(end_of_data) + " bytes)",
                  "write it again with the rigid-body program (was the disk "
                  "full, or the copy interrupted?)");
    if (reader.string_attribute(file, "schema", "/") != schema_name)
      reader.fail("is not a softgrasp kinematics file (attribute 'schema')",
                  "give the file written by the rigid-body program");
    const int version =
        static_cast<int>(reader.number_attribute(file, "schema_version", "/"));
    if (version != KinematicsData::schema_version)
      reader.fail("has schema version " + std::to_string(version) +
                      ", this softgrasp reads version " +
                      std::to_string(KinematicsData::schema_version),
                  "write the file again with the matching softgrasp");

    KinematicsData data;
    data.source     = reader.string_attribute(file, "source", "/");
    data.time       = reader.dataset(file, "time", "/time", 0, 1);
    const hsize_t n = data.time.size();
    if (n == 0)
      reader.fail("has an empty '/time'", "record at least one sample");
    for (hsize_t i = 1; i < n; ++i)
      if (!(data.time[i] > data.time[i - 1]))
        reader.fail("has non-increasing times in '/time' at row " +
                        std::to_string(i),
                    "record samples at strictly increasing times");

    Handle bodies = reader.open_group(file, "bodies");
    for (const auto &name :
         names_of(reader.string_attribute(bodies, "names", "/bodies")))
    {
      const std::string    path  = "/bodies/" + name;
      Handle               group = reader.open_group(bodies, name);
      KinematicsData::Body body;
      body.name    = name;
      body.poses   = reader.poses(group, path, n);
      Handle geoms = reader.open_group(group, "geoms");
      for (const auto &geom_name :
           names_of(reader.string_attribute(geoms, "names", path + "/geoms")))
      {
        const std::string    geom_path = path + "/geoms/" + geom_name;
        Handle               geom      = reader.open_group(geoms, geom_name);
        KinematicsData::Geom g;
        g.name = geom_name;
        g.type = reader.string_attribute(geom, "type", geom_path);
        const auto size =
            reader.dataset(geom, "size", geom_path + "/size", 3, 1);
        g.size       = {size[0], size[1], size[2]};
        g.local_pose = reader.poses(geom, geom_path, 1)[0];
        body.geoms.push_back(g);
      }
      data.bodies.push_back(body);
    }

    Handle joints = reader.open_group(file, "joints");
    for (const auto &name :
         names_of(reader.string_attribute(joints, "names", "/joints")))
    {
      const std::string     path  = "/joints/" + name;
      Handle                group = reader.open_group(joints, name);
      KinematicsData::Joint joint;
      joint.name   = name;
      joint.angle  = reader.dataset(group, "angle", path + "/angle", n, 1);
      joint.target = reader.dataset(group, "target", path + "/target", n, 1);
      data.joints.push_back(joint);
    }

    Handle equilibrium = reader.open_group(file, "equilibrium");
    data.equilibrium_time =
        reader.number_attribute(equilibrium, "time", "/equilibrium");
    for (const auto &link : names_of(
             reader.string_attribute(equilibrium, "links", "/equilibrium")))
    {
      const std::string         path  = "/equilibrium/" + link;
      Handle                    group = reader.open_group(equilibrium, link);
      KinematicsData::LinkForce f;
      std::tie(f.body, f.geom) = reader.link_parts(link, "/equilibrium");
      const auto force = reader.dataset(group, "force", path + "/force", 3, 1);
      const auto normal =
          reader.dataset(group, "normal", path + "/normal", 3, 1);
      f.force  = {force[0], force[1], force[2]};
      f.normal = {normal[0], normal[1], normal[2]};
      data.equilibrium_forces.push_back(f);
    }

    Handle histories = reader.open_group(file, "link_forces");
    for (const auto &link :
         names_of(reader.string_attribute(histories, "links", "/link_forces")))
    {
      const std::string           path  = "/link_forces/" + link;
      Handle                      group = reader.open_group(histories, link);
      KinematicsData::LinkHistory h;
      std::tie(h.body, h.geom) = reader.link_parts(link, "/link_forces");
      h.force =
          vectors_of(reader.dataset(group, "force", path + "/force", n, 3));
      h.normal_force = vectors_of(
          reader.dataset(group, "normal_force", path + "/normal_force", n, 3));
      data.link_forces.push_back(h);
    }

    Handle phases = reader.open_group(file, "phases");
    for (const auto &name :
         names_of(reader.string_attribute(phases, "names", "/phases")))
    {
      const std::string     path  = "/phases/" + name;
      Handle                group = reader.open_group(phases, name);
      KinematicsData::Phase p;
      p.name       = name;
      p.start_time = reader.number_attribute(group, "start_time", path);
      p.end_time   = reader.number_attribute(group, "end_time", path);
      p.amount     = reader.number_attribute(group, "amount", path);
      if (!(p.end_time > p.start_time) || !std::isfinite(p.amount))
        reader.fail("has the phase '" + path + "' with start_time " +
                        std::to_string(p.start_time) + " s, end_time " +
                        std::to_string(p.end_time) + " s, amount " +
                        std::to_string(p.amount),
                    "write finite values with end_time > start_time");
      const double slack = 1e-9 * (data.time.back() - data.time.front());
      if (p.start_time < data.time.front() - slack ||
          p.end_time > data.time.back() + slack)
        reader.fail("has the phase '" + path + "' from " +
                        std::to_string(p.start_time) + " s to " +
                        std::to_string(p.end_time) +
                        " s, outside the recorded samples (" +
                        std::to_string(data.time.front()) + " s to " +
                        std::to_string(data.time.back()) + " s)",
                    "record the whole phase, or give its times within the "
                    "recorded samples");
      data.phases.push_back(p);
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
        body.add_geom(g.name,
                      create_shape(g.type, g.size, b.name + "/" + g.name),
                      g.local_pose);
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
