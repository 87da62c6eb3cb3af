#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <softgrasp/rigid/sphere_shape.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    std::vector<std::string> names_in(const std::string &list)
    {
      std::vector<std::string> names;
      for (const auto &name : Utilities::split_string_list(list, ','))
        if (!name.empty())
          names.push_back(name);
      return names;
    }

    std::vector<double> numbers_in(const std::string &text,
                                   const std::string &what)
    {
      std::vector<double> values;
      for (const auto &item : Utilities::split_string_list(text, ','))
      {
        std::istringstream in(item);
        double             value;
        std::string        rest;
        if (!(in >> value) || (in >> rest) || !std::isfinite(value))
          throw InputError(what + ": '" + item +
                           "' is not a finite number. Fix: write "
                           "comma-separated numbers.");
        values.push_back(value);
      }
      return values;
    }

    Eigen::Vector3d vector_in(const std::string &text,
                              const std::string &what,
                              const std::string &unit)
    {
      const auto v = numbers_in(text, what);
      if (v.size() != 3)
        throw InputError(what + " has " + std::to_string(v.size()) +
                         " numbers. Fix: give three (" + unit + ").");
      return {v[0], v[1], v[2]};
    }

    Eigen::Quaterniond quaternion_in(const std::string &text,
                                     const std::string &what)
    {
      const auto q = numbers_in(text, what);
      if (q.size() != 4)
        throw InputError(what + " has " + std::to_string(q.size()) +
                         " numbers. Fix: give a quaternion w, x, y, z.");
      const Eigen::Quaterniond result(q[0], q[1], q[2], q[3]);
      if (result.norm() < 1e-12)
        throw InputError(what + " is the zero quaternion. Fix: give a "
                                "non-zero quaternion w, x, y, z (1, 0, 0, 0 "
                                "is no rotation).");
      return result.normalized();
    }

    /// The pose x, y, z, qw, qx, qy, qz in seven numbers from @p v (the
    /// trajectory validates and normalises the quaternion).
    Pose pose_from(const double *v)
    {
      Pose pose;
      pose.position    = {v[0], v[1], v[2]};
      pose.orientation = Eigen::Quaterniond(v[3], v[4], v[5], v[6]);
      return pose;
    }

    void declare_geom(ParameterHandler &prm)
    {
      std::string types;
      for (const auto &[name, entry] : ShapeRegistry::all())
        types += "\n  " + name + ": " + entry.description + ".";
      prm.declare_entry(
          "Type",
          SphereShape::type_name,
          Patterns::Selection(ShapeRegistry::names_separated_by("|")),
          "MuJoCo geom type (sizes in 'Size', m):" + types);
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "STL (ASCII or binary) or OBJ file of a closed "
                        "triangle surface, for Type = mesh; coordinates in "
                        "the geom frame.");
      prm.declare_entry("Mesh scale",
                        "1",
                        Patterns::Double(0),
                        "Factor from the mesh file's length unit to m (e.g. "
                        "0.001 for mm). Unit: m per file unit.");
      prm.declare_entry("Size",
                        "0.01",
                        Patterns::List(Patterns::Double(0), 1, 3),
                        "MuJoCo's size vector (m): sphere r; capsule and "
                        "cylinder r, half-length; box three half-sizes; "
                        "ellipsoid three radii; plane ignored (infinite).");
      prm.declare_entry("Position",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "Position of the geom frame in the body frame (m).");
      prm.declare_entry("Orientation",
                        "1, 0, 0, 0",
                        Patterns::Anything(),
                        "Orientation of the geom frame in the body frame, a "
                        "quaternion w, x, y, z (normalised on input).");
      prm.declare_entry(
          "Reference normal",
          "patch mean",
          Patterns::Anything(),
          "The direction n (unitless, normalised) that splits the geom's "
          "contact force F into the normal part (n n^T) F and the lateral "
          "part (I - n n^T) F; the normal force is -n.F. 'patch mean' (or "
          "empty): the area-weighted mean normal of the geom's contact "
          "patch, with the components across the symmetry planes the patch "
          "touches removed, so that a part model gives the whole model's "
          "split (a symmetry plane is a boundary where exactly one "
          "displacement component is fixed); 'x, y, z': a fixed world "
          "direction; 'geom: x, y, z': a direction in the geom's frame "
          "that turns with the geom (e.g. the palm side of a finger link). "
          "Studies that read a kinematics file use MuJoCo's equilibrium "
          "contact normal (world).");
    }

    void declare_body(ParameterHandler &prm)
    {
      prm.declare_entry("Geom names",
                        "",
                        Patterns::Anything(),
                        "Comma-separated geom names; each has a subsection "
                        "'Geom <name>'.");
      prm.declare_entry("Trajectory",
                        "0: 0, 0, 0, 1, 0, 0, 0",
                        Patterns::Anything(),
                        "Pose samples 't: x, y, z, qw, qx, qy, qz' separated "
                        "by ';' (time in s, position in m, unit quaternion), "
                        "times increasing; positions are interpolated "
                        "linearly and orientations by slerp.");
      prm.declare_entry("Trajectory file",
                        "",
                        Patterns::Anything(),
                        "A CSV file with the header t,x,y,z,qw,qx,qy,qz "
                        "(s, m, unitless); overrides 'Trajectory' if set.");
    }
  } // namespace

  void RigidBodySet::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid bodies");
    prm.declare_entry("Names",
                      "",
                      Patterns::Anything(),
                      "Comma-separated names of the rigid bodies; each has "
                      "a subsection 'Body <name>'. Empty: no rigid body.");
    prm.leave_subsection();
  }

  void RigidBodySet::add_passes(ParameterReader &reader)
  {
    reader.add_pass(
        [](ParameterHandler &prm)
        {
          prm.enter_subsection("Rigid bodies");
          for (const auto &name : names_in(prm.get("Names")))
          {
            prm.enter_subsection("Body " + name);
            declare_body(prm);
            prm.leave_subsection();
          }
          prm.leave_subsection();
        });
    reader.add_pass(
        [](ParameterHandler &prm)
        {
          prm.enter_subsection("Rigid bodies");
          for (const auto &name : names_in(prm.get("Names")))
          {
            prm.enter_subsection("Body " + name);
            for (const auto &geom : names_in(prm.get("Geom names")))
            {
              prm.enter_subsection("Geom " + geom);
              declare_geom(prm);
              prm.leave_subsection();
            }
            prm.leave_subsection();
          }
          prm.leave_subsection();
        });
  }

  void RigidBodySet::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid bodies");
    const auto body_names = names_in(prm.get("Names"));
    for (const auto &name : body_names)
    {
      const std::string path = "Rigid bodies/Body " + name;
      prm.enter_subsection("Body " + name);
      const std::string file = prm.get("Trajectory file");
      PoseTrajectory    trajectory =
          file.empty() ? parse_trajectory(prm.get("Trajectory"),
                                          "Parameter '" + path + "/Trajectory'")
                          : read_trajectory_file(file);
      RigidBody  body(name, trajectory);
      const auto geoms = names_in(prm.get("Geom names"));
      if (geoms.empty())
        throw InputError("Rigid body '" + name + "' has no geoms. Fix: set '" +
                         path +
                         "/Geom names' and a subsection 'Geom <name>' each.");
      std::vector<ReferenceNormal> body_normals;
      for (const auto &geom : geoms)
      {
        const std::string geom_path = path + "/Geom " + geom;
        prm.enter_subsection("Geom " + geom);
        const auto size =
            numbers_in(prm.get("Size"), "Parameter '" + geom_path + "/Size'");
        Eigen::Vector3d size3 = Eigen::Vector3d::Zero();
        for (unsigned int i = 0; i < size.size(); ++i)
          size3[i] = size[i];
        Pose local;
        local.position = vector_in(
            prm.get("Position"), "Parameter '" + geom_path + "/Position'", "m");
        local.orientation =
            quaternion_in(prm.get("Orientation"),
                          "Parameter '" + geom_path + "/Orientation'");
        ShapeSpec spec;
        spec.type       = prm.get("Type");
        spec.size       = size3;
        spec.geom_name  = geom_path;
        spec.mesh_file  = prm.get("Mesh file");
        spec.mesh_scale = prm.get_double("Mesh scale");
        body.add_geom(geom, create_shape(spec), local);
        body_normals.push_back(ReferenceNormal::parse(
            prm.get("Reference normal"), geom_path + "/Reference normal"));
        prm.leave_subsection();
      }
      prm.leave_subsection();
      body_list.push_back(body);
      normals.push_back(body_normals);
    }
    prm.leave_subsection();
  }

  unsigned int RigidBodySet::add_body(const RigidBody &body)
  {
    body_list.push_back(body);
    normals.emplace_back(body.geoms().size());
    return body_list.size() - 1;
  }

  void RigidBodySet::set_reference_normal(const unsigned int     b,
                                          const unsigned int     g,
                                          const Eigen::Vector3d &normal)
  {
    if (normal.norm() < 1e-12 || !normal.allFinite())
      throw InputError("The reference normal of geom " + geom_label(b, g) +
                       " is zero or not finite. Fix: give a direction.");
    normals.at(b).at(g) = {ReferenceNormal::Kind::world, normal.normalized()};
  }

  const ReferenceNormal &
  RigidBodySet::reference_normal(const unsigned int b,
                                 const unsigned int g) const
  {
    return normals.at(b).at(g);
  }

  ReferenceNormal ReferenceNormal::parse(const std::string &text,
                                         const std::string &path)
  {
    const std::string trimmed = Utilities::trim(text);
    if (trimmed.empty() || trimmed == "patch mean")
      return {};
    const bool        in_geom = trimmed.rfind("geom:", 0) == 0;
    const std::string numbers = in_geom ? trimmed.substr(5) : trimmed;
    Eigen::Vector3d   n;
    try
    {
      n = vector_in(numbers, "Parameter '" + path + "'", "a direction");
    }
    catch (const InputError &e)
    {
      throw InputError(std::string(e.what()) +
                       " The entry takes 'patch mean', a world direction "
                       "'x, y, z' or a direction in the geom's frame "
                       "'geom: x, y, z'.");
    }
    if (n.norm() < 1e-12)
      throw InputError("Parameter '" + path +
                       "' is the zero vector. Fix: give a direction, "
                       "'geom: x, y, z', or 'patch mean'.");
    return {in_geom ? Kind::geom_frame : Kind::world, n.normalized()};
  }

  const std::vector<RigidBody> &RigidBodySet::bodies() const
  {
    return body_list;
  }

  bool RigidBodySet::empty() const
  {
    return body_list.empty();
  }

  std::string RigidBodySet::geom_label(const unsigned int b,
                                       const unsigned int g) const
  {
    return body_list.at(b).name() + "/" + body_list.at(b).geoms().at(g).name;
  }

  PoseTrajectory parse_trajectory(const std::string &text,
                                  const std::string &source)
  {
    std::vector<double> times;
    std::vector<Pose>   poses;
    unsigned int        index = 0;
    for (const auto &sample : Utilities::split_string_list(text, ';'))
    {
      const std::string what  = source + ", sample " + std::to_string(index++);
      const auto        colon = sample.find(':');
      if (colon == std::string::npos)
        throw InputError(what + " ('" + sample +
                         "') has no ':'. Fix: write 't: x, y, z, qw, qx, qy, "
                         "qz'.");
      const auto t = numbers_in(sample.substr(0, colon), what);
      const auto v = numbers_in(sample.substr(colon + 1), what);
      if (t.size() != 1 || v.size() != 7)
        throw InputError(what + " ('" + sample +
                         "') needs one time and seven pose numbers. Fix: "
                         "write 't: x, y, z, qw, qx, qy, qz'.");
      times.push_back(t[0]);
      poses.push_back(pose_from(v.data()));
    }
    if (times.empty())
      throw InputError(source + " has no samples. Fix: give at least one "
                                "'t: x, y, z, qw, qx, qy, qz'.");
    return PoseTrajectory(times, poses, source);
  }

  PoseTrajectory read_trajectory_file(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError("Cannot open the trajectory file '" + filename +
                       "'. Fix: check the path in 'Trajectory file' (it is "
                       "relative to the working directory).");
    std::string line;
    std::getline(in, line);
    std::string header;
    for (const char c : line)
      if (!std::isspace(static_cast<unsigned char>(c)))
        header += c;
    if (header != "t,x,y,z,qw,qx,qy,qz")
      throw InputError("The trajectory file '" + filename +
                       "' has the header '" + line +
                       "'. Fix: the first line must be t,x,y,z,qw,qx,qy,qz.");
    std::vector<double> times;
    std::vector<Pose>   poses;
    unsigned int        line_number = 1;
    while (std::getline(in, line))
    {
      ++line_number;
      if (line.find_first_not_of(" \t\r") == std::string::npos)
        continue;
      const auto v = numbers_in(line,
                                "Trajectory file '" + filename + "', line " +
                                    std::to_string(line_number));
      if (v.size() != 8)
        throw InputError("Trajectory file '" + filename + "', line " +
                         std::to_string(line_number) + " has " +
                         std::to_string(v.size()) +
                         " numbers. Fix: give t,x,y,z,qw,qx,qy,qz.");
      times.push_back(v[0]);
      poses.push_back(pose_from(v.data() + 1));
    }
    if (times.empty())
      throw InputError("The trajectory file '" + filename +
                       "' has no samples. Fix: add rows t,x,y,z,qw,qx,qy,qz.");
    return PoseTrajectory(times, poses, "trajectory file '" + filename + "'");
  }
} // namespace softgrasp
