#ifndef softgrasp_mujoco_mujoco_model_h
#define softgrasp_mujoco_mujoco_model_h

#include <mujoco/mujoco.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A MuJoCo 2.2 model and its data, loaded from an MJCF file, with the
   * checks MuJoCo 2.2 leaves to the user:
   *  - mj_loadXML() fills its error buffer with warnings even on success;
   *    only a null model is a failure (an InputError with MuJoCo's message),
   *    the warnings are kept in warnings();
   *  - a contact solref time constant under two time steps is clamped
   *    silently: check_contact_time_constants() makes it an InputError;
   *  - names are looked up with an InputError listing the valid ones.
   *
   * Part of the softgrasp_mujoco library (target softgrasp::mujoco); the
   * core library never needs MuJoCo.
   */
  class MujocoModel
  {
  public:
    explicit MujocoModel(const std::string &mjcf_file);
    ~MujocoModel();
    MujocoModel(const MujocoModel &)            = delete;
    MujocoModel &operator=(const MujocoModel &) = delete;

    mjModel *model() const;
    mjData  *data() const;

    /// A fresh mjData of the same model (for forward kinematics aside).
    mjData *make_data() const;

    /// The id of object @p name of @p type; @p what names it in messages.
    int id(const mjtObj       type,
           const std::string &name,
           const std::string &what) const;

    /// The names of all objects of @p type.
    std::vector<std::string> names(const mjtObj type) const;

    /// The actuator driving joint @p joint, -1 if none.
    int actuator_of_joint(const int joint) const;

    /// Throw an InputError if a geom's solref time constant is under two
    /// time steps (MuJoCo 2.2 would clamp it without a word).
    void check_contact_time_constants() const;

    /// The warnings mj_loadXML() reported (empty if none).
    const std::string &warnings() const;

    const std::string file;

  private:
    mjModel    *m = nullptr;
    mjData     *d = nullptr;
    std::string load_warnings;
  };

  /// The MuJoCo geom type name ("capsule", ...) as the kinematics file has.
  std::string mujoco_geom_type_name(const int type);
} // namespace softgrasp

#endif
