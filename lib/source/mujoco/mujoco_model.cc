#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/mujoco_model.h>
#include <softgrasp/rigid/box_shape.h>
#include <softgrasp/rigid/capsule_shape.h>
#include <softgrasp/rigid/cylinder_shape.h>
#include <softgrasp/rigid/ellipsoid_shape.h>
#include <softgrasp/rigid/plane_shape.h>
#include <softgrasp/rigid/sphere_shape.h>
#include <softgrasp/rigid/triangle_mesh_shape.h>

namespace softgrasp
{
  MujocoModel::MujocoModel(const std::string &mjcf_file)
      : file(mjcf_file)
  {
    if (!std::ifstream(mjcf_file))
      throw InputError("Cannot open the MJCF scene '" + mjcf_file +
                       "'. Fix: check 'Scene file' (relative paths are "
                       "relative to the parameter file's directory).");
    char error[1000] = "";
    m                = mj_loadXML(mjcf_file.c_str(), nullptr, error, 1000);
    if (!m)
      throw InputError("MuJoCo could not load the MJCF scene '" + mjcf_file +
                       "': " + error +
                       ". Fix: correct the scene file (see doc/mujoco.md).");
    load_warnings = error; // warnings are reported even on success
    d             = mj_makeData(m);
  }

  MujocoModel::~MujocoModel()
  {
    if (d)
      mj_deleteData(d);
    if (m)
      mj_deleteModel(m);
  }

  mjModel *MujocoModel::model() const
  {
    return m;
  }

  mjData *MujocoModel::data() const
  {
    return d;
  }

  mjData *MujocoModel::make_data() const
  {
    return mj_makeData(m);
  }

  std::vector<std::string> MujocoModel::names(const mjtObj type) const
  {
    int n = 0;
    switch (type)
    {
    case mjOBJ_BODY:
      n = m->nbody;
      break;
    case mjOBJ_JOINT:
      n = m->njnt;
      break;
    case mjOBJ_GEOM:
      n = m->ngeom;
      break;
    case mjOBJ_ACTUATOR:
      n = m->nu;
      break;
    case mjOBJ_KEY:
      n = m->nkey;
      break;
    default:
      break;
    }
    std::vector<std::string> result;
    for (int i = 0; i < n; ++i)
      if (const char *name = mj_id2name(m, type, i))
        result.emplace_back(name);
    return result;
  }

  int MujocoModel::id(const mjtObj       type,
                      const std::string &name,
                      const std::string &what) const
  {
    const int i = mj_name2id(m, type, name.c_str());
    if (i < 0)
    {
      std::string valid;
      for (const auto &n : names(type))
        valid += (valid.empty() ? "" : ", ") + n;
      throw InputError("The scene '" + file + "' has no " + what + " '" + name +
                       "'. Fix: use one of: " + valid + ".");
    }
    return i;
  }

  int MujocoModel::actuator_of_joint(const int joint) const
  {
    for (int a = 0; a < m->nu; ++a)
      if (m->actuator_trntype[a] == mjTRN_JOINT &&
          m->actuator_trnid[2 * a] == joint)
        return a;
    return -1;
  }

  void MujocoModel::check_contact_time_constants() const
  {
    const double dt = m->opt.timestep;
    for (int g = 0; g < m->ngeom; ++g)
    {
      const double timeconst = m->geom_solref[mjNREF * g];
      if (timeconst > 0 && timeconst < 2 * dt)
        throw InputError(
            "Geom '" + std::string(mj_id2name(m, mjOBJ_GEOM, g)) +
            "' of the scene '" + file + "' has a solref time constant of " +
            std::to_string(timeconst) + " s, under two time steps (2 x " +
            std::to_string(dt) +
            " s); MuJoCo 2.2 would silently use 2 time steps. Fix: raise the "
            "time constant or lower <option timestep>.");
    }
  }

  const std::string &MujocoModel::warnings() const
  {
    return load_warnings;
  }

  std::string mujoco_geom_type_name(const int type)
  {
    switch (type)
    {
    case mjGEOM_PLANE:
      return PlaneShape::type_name;
    case mjGEOM_SPHERE:
      return SphereShape::type_name;
    case mjGEOM_CAPSULE:
      return CapsuleShape::type_name;
    case mjGEOM_ELLIPSOID:
      return EllipsoidShape::type_name;
    case mjGEOM_CYLINDER:
      return CylinderShape::type_name;
    case mjGEOM_BOX:
      return BoxShape::type_name;
    case mjGEOM_MESH:
      return TriangleMeshShape::type_name;
    default:
      return "hfield";
    }
  }
} // namespace softgrasp
