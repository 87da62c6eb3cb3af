#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/grasp/limb_scene.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  void LimbScene::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Arm scene");
    prm.declare_entry("Density",
                      "1050",
                      Patterns::Double(0),
                      "Mean density of the rigid arm (its mass under "
                      "gravity). Unit: kg/m^3.");
    prm.declare_entry("Shoulder",
                      "ball joint",
                      Patterns::Selection("ball joint|fixed"),
                      "ball joint: the arm hangs from the shoulder on a "
                      "damped ball joint (it gives way to the grasp); "
                      "fixed: the arm is held where it is, as the finite "
                      "element humerus is (for a pull along the arm).");
    prm.declare_entry("Shoulder damping",
                      "20",
                      Patterns::Double(0),
                      "Damping of the shoulder's ball joint. Unit: N m s/rad.");
    prm.declare_entry("Shoulder stiffness",
                      "50",
                      Patterns::Double(0),
                      "Restoring stiffness of the shoulder's ball joint "
                      "(the passive shoulder holding the arm). Unit: "
                      "N m/rad.");
    prm.declare_entry("Facets",
                      "96",
                      Patterns::Integer(8, 4096),
                      "Facets around the rigid arm's skin surface, made "
                      "from the layered limb's shape; a limb mesh from a "
                      "file gives its own skin faces instead. Unit: 1.");
    prm.leave_subsection();
  }

  void LimbScene::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Arm scene");
    const CheckedSection section(prm, "Arm scene");
    density            = section.get_positive("Density", "kg/m^3");
    shoulder_damping   = section.get_positive("Shoulder damping", "N m s/rad");
    shoulder_stiffness = section.get_positive("Shoulder stiffness", "N m/rad");
    facets             = prm.get_integer("Facets");
    shoulder_joint     = prm.get("Shoulder") == "ball joint";
    prm.leave_subsection();
  }

  Pose LimbScene::limb_frame_in_body(const double length)
  {
    Eigen::Matrix3d R; // columns: the limb's x, y, z in the body frame
    R << 0, -1, 0,     //
        1, 0, 0,       //
        0, 0, 1;
    Pose pose;
    pose.position    = Eigen::Vector3d(0, length / 2, 0);
    pose.orientation = Eigen::Quaterniond(R);
    return pose;
  }

  namespace
  {
    /// A binary STL of @p surface moved into the arm body's frame by
    /// @p frame.
    std::string skin_stl(const LimbSurface &surface, const Pose &frame)
    {
      std::string       out(80, '\0');
      const std::string header = "softgrasp limb skin surface (m)";
      out.replace(0, header.size(), header);
      const auto put = [&out](const auto value)
      {
        char bytes[sizeof(value)];
        std::memcpy(bytes, &value, sizeof(value));
        out.append(bytes, sizeof(value));
      };
      put(static_cast<std::uint32_t>(surface.triangles.size()));
      for (const auto &triangle : surface.triangles)
      {
        const LimbSurface::Triangle t = {{frame.to_world(triangle[0]),
                                          frame.to_world(triangle[1]),
                                          frame.to_world(triangle[2])}};
        const Eigen::Vector3d       normal =
            (t[1] - t[0]).cross(t[2] - t[0]).normalized();
        for (const auto &v : {normal, t[0], t[1], t[2]})
          for (unsigned int d = 0; d < 3; ++d)
            put(static_cast<float>(v[d]));
        put(static_cast<std::uint16_t>(0));
      }
      return out;
    }
  } // namespace

  std::string LimbScene::write(const LimbSurface &limb,
                               const std::string &hand_file,
                               const std::string &directory) const
  {
    namespace fs = std::filesystem;
    if (!fs::exists(hand_file))
      throw InputError("The hand's MJCF file '" + hand_file +
                       "' ('Rigid environment/Scene file') does not exist. "
                       "Fix: name the hand model, e.g. "
                       "mjcf/three_finger_hand.xml next to the .prm.");
    const std::string folder = directory.empty() ? "." : directory;
    std::error_code   code;
    fs::create_directories(folder, code);
    // MuJoCo 2.2 resolves an include relative to the including file.
    const std::string include =
        fs::relative(fs::absolute(hand_file), fs::absolute(folder), code)
            .string();
    if (code || include.empty())
      throw InputError("Cannot reach the hand's MJCF file '" + hand_file +
                       "' from '" + folder +
                       "'. Fix: keep both on the same file system.");
    const Pose   frame  = limb_frame_in_body(limb.length);
    const double volume = limb.volume();
    AtomicFile::write(folder + "/mujoco_arm_skin.stl", skin_stl(limb, frame));
    std::ostringstream xml;
    xml << std::setprecision(17);
    // The geom's mass is given: MuJoCo 2.2 infers a mesh's mass from its
    // equivalent inertia box (3/pi of a cylinder's volume).
    xml << "<!-- Written by softgrasp from the finite element limb's skin "
           "surface; see doc/studies.md. -->\n"
        << "<mujoco model=\"arm_grasp\">\n"
        << "  <compiler angle=\"radian\" autolimits=\"true\"/>\n"
        << "  <option timestep=\"0.001\" gravity=\"0 0 -9.81\" "
           "cone=\"elliptic\" impratio=\"10\" iterations=\"100\" "
           "tolerance=\"1e-10\" noslip_iterations=\"20\"/>\n"
        << "  <include file=\"" << include << "\"/>\n"
        << "  <asset>\n    <mesh name=\"upper_arm_skin\" "
           "file=\"mujoco_arm_skin.stl\"/>\n  </asset>\n"
        << "  <worldbody>\n"
        << "    <body name=\"object\" pos=\"0 " << -limb.length / 2
        << " 0\">\n";
    if (shoulder_joint)
      xml << "      <joint name=\"shoulder\" type=\"ball\" damping=\""
          << shoulder_damping << "\" stiffness=\"" << shoulder_stiffness
          << "\"/>\n";
    xml << "      <geom name=\"upper_arm\" type=\"mesh\" "
           "mesh=\"upper_arm_skin\" mass=\""
        << density * volume
        << "\" condim=\"3\" friction=\"1 0.005 0.0001\" solref=\"0.004 1\" "
           "solimp=\"0.95 0.99 0.001\" rgba=\"0.85 0.65 0.55 1\"/>\n"
        << "    </body>\n  </worldbody>\n</mujoco>\n";
    const std::string scene = folder + "/mujoco_arm_scene.xml";
    AtomicFile::write(scene, xml.str());
    return scene;
  }
} // namespace softgrasp

namespace
{
  // A file with this subsection given to another program names its program.
  [[maybe_unused]] const bool softgrasp_program_section =
      softgrasp::ParameterReader::register_program_section(
          "Arm scene", "arm_grasp or grasp_pull_sweep");
} // namespace
