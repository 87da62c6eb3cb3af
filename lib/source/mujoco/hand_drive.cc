#include <algorithm>
#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/hand_drive.h>

namespace softgrasp
{
  namespace
  {
    std::string name_of(const mjModel *m, const mjtObj type, const int id)
    {
      const char *name = mj_id2name(m, type, id);
      return name ? name : "#" + std::to_string(id);
    }

    /// A <position> servo: no activation, fixed gain kp, bias -kp * length.
    bool is_position_servo(const mjModel *m, const int a)
    {
      const double kp = m->actuator_gainprm[mjNGAIN * a];
      return m->actuator_dyntype[a] == mjDYN_NONE &&
             m->actuator_gaintype[a] == mjGAIN_FIXED &&
             m->actuator_biastype[a] == mjBIAS_AFFINE && kp > 0 &&
             std::abs(m->actuator_biasprm[mjNBIAS * a + 1] + kp) <= 1e-12 * kp;
    }

    /// Add every joint an active joint equality couples to @p joints.
    bool add_equality_couplings(const mjModel *m, std::vector<int> &joints)
    {
      bool coupled = false, grown = true;
      while (grown)
      {
        grown = false;
        for (int e = 0; e < m->neq; ++e)
        {
          if (m->eq_type[e] != mjEQ_JOINT || !m->eq_active[e] ||
              m->eq_obj2id[e] < 0)
            continue;
          const int  a = m->eq_obj1id[e], b = m->eq_obj2id[e];
          const auto has = [&](const int j) {
            return std::find(joints.begin(), joints.end(), j) != joints.end();
          };
          if (has(a) != has(b))
          {
            joints.push_back(has(a) ? b : a);
            grown = coupled = true;
          }
        }
      }
      return coupled;
    }

    /// The drive of closing actuator @p entry ("name" or "-name").
    HandDrive actuator_drive(const MujocoModel &model, const std::string &entry)
    {
      const mjModel *m    = model.model();
      const bool     neg  = !entry.empty() && entry[0] == '-';
      const auto     name = neg ? entry.substr(1) : entry;
      HandDrive      drive;
      drive.actuator      = model.id(mjOBJ_ACTUATOR, name, "actuator");
      drive.sign          = neg ? -1 : 1;
      drive.subtree_touch = true;
      if (!is_position_servo(m, drive.actuator))
        throw InputError("Actuator '" + name + "' of the scene '" + model.file +
                         "' is not a position servo: the grasp studies "
                         "close the hand by moving actuator targets. Fix: "
                         "drive the hand with a <position> actuator, or "
                         "name one in 'Rigid environment/Closing "
                         "actuators'.");
      drive.joints  = driven_joints(model, drive.actuator);
      drive.coupled = drive.joints.size() > 1 ||
                      m->actuator_trntype[drive.actuator] != mjTRN_JOINT ||
                      m->actuator_gear[6 * drive.actuator] != 1;
      return drive;
    }

    /// The drive of finger joint @p name: its own actuator, sign +1.
    HandDrive joint_drive(const MujocoModel &model, const std::string &name)
    {
      const mjModel *m = model.model();
      const int      j = model.id(mjOBJ_JOINT, name, "joint");
      HandDrive      drive;
      drive.actuator = model.actuator_of_joint(j);
      if ((m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) ||
          drive.actuator < 0)
        throw InputError("Finger joint '" + name + "' of the scene '" +
                         model.file +
                         "' is not a hinge or slide joint driven by an "
                         "actuator. Fix: list hinge or slide joints with "
                         "<position> actuators in 'Rigid environment/Finger "
                         "joints', or name the actuators that close the "
                         "hand in 'Closing actuators'.");
      drive.joints  = {j};
      drive.coupled = m->actuator_gear[6 * drive.actuator] != 1;
      return drive;
    }
  } // namespace

  std::vector<int> driven_joints(const MujocoModel &model, const int actuator)
  {
    const mjModel    *m    = model.model();
    const std::string name = name_of(m, mjOBJ_ACTUATOR, actuator);
    std::vector<int>  joints;
    const int         target = m->actuator_trnid[2 * actuator];
    if (m->actuator_trntype[actuator] == mjTRN_JOINT)
      joints.push_back(target);
    else if (m->actuator_trntype[actuator] == mjTRN_TENDON)
    {
      for (int w = m->tendon_adr[target];
           w < m->tendon_adr[target] + m->tendon_num[target];
           ++w)
      {
        if (m->wrap_type[w] != mjWRAP_JOINT)
          throw InputError("Actuator '" + name + "' drives the spatial " +
                           "tendon '" + name_of(m, mjOBJ_TENDON, target) +
                           "' of the scene '" + model.file +
                           "': the grasp studies follow joint coordinates "
                           "only. Fix: couple the joints by a <fixed> "
                           "tendon or an <equality joint=...>.");
        joints.push_back(m->wrap_objid[w]);
      }
    }
    else
      throw InputError("Actuator '" + name + "' of the scene '" + model.file +
                       "' has a site or slider-crank transmission. Fix: "
                       "close the hand with actuators on a joint or a "
                       "<fixed> tendon.");
    add_equality_couplings(m, joints);
    for (const int j : joints)
      if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE)
        throw InputError("Actuator '" + name + "' moves the joint '" +
                         name_of(m, mjOBJ_JOINT, j) + "' of the scene '" +
                         model.file +
                         "', which is neither a hinge nor a slide joint. "
                         "Fix: drive fingers on hinge or slide joints.");
    return joints;
  }

  std::vector<HandDrive>
  hand_drives(const MujocoModel              &model,
              const std::vector<std::string> &finger_joints,
              const std::vector<std::string> &closing_actuators,
              const std::vector<double>      &weights,
              std::string                    &unit)
  {
    const mjModel *m = model.model();
    if (!closing_actuators.empty() && !finger_joints.empty())
      throw InputError("'Rigid environment/Finger joints' and 'Closing "
                       "actuators' are both given. Fix: name the actuators "
                       "that close the hand and leave 'Finger joints' empty "
                       "(set Finger joints =), or the reverse.");
    std::vector<HandDrive> drives;
    for (const auto &a : closing_actuators)
      drives.push_back(actuator_drive(model, a));
    for (const auto &j : finger_joints)
      drives.push_back(joint_drive(model, j));
    if (drives.empty())
      throw InputError("Neither 'Rigid environment/Closing actuators' nor "
                       "'Finger joints' names what closes the hand. Fix: "
                       "name the position actuators that close it in "
                       "'Rigid environment/Closing actuators' (or a "
                       "keyframe of the closed hand in 'Closing keyframe', "
                       "or joints with their own servos in 'Finger "
                       "joints').");
    if (!weights.empty() && weights.size() != drives.size())
      throw InputError("'Rigid environment/Indentation/Joint weights' has " +
                       std::to_string(weights.size()) + " values for " +
                       std::to_string(drives.size()) +
                       " drives. Fix: give one weight per entry of 'Closing "
                       "actuators' (or 'Finger joints'), or none.");
    unit = "";
    std::string first;
    for (std::size_t k = 0; k < drives.size(); ++k)
    {
      drives[k].weight = weights.empty() ? 1.0 : weights[k];
      for (const int j : drives[k].joints)
      {
        const std::string u = m->jnt_type[j] == mjJNT_HINGE ? "rad" : "m";
        if (!unit.empty() && u != unit)
          throw InputError(
              "Joints '" + first + "' and '" + name_of(m, mjOBJ_JOINT, j) +
              "' of the scene '" + model.file +
              "' are a hinge and a slide joint: 'Closing speed', 'Grip' and "
              "'Extra joint angle' are in one unit for all of them (rad, or "
              "m for slide joints). Fix: close the hand with joints of one "
              "type.");
        unit  = u;
        first = first.empty() ? name_of(m, mjOBJ_JOINT, j) : first;
      }
    }
    return drives;
  }

  namespace
  {
    /// Switches MuJoCo's contacts off while it lives.
    class ContactsOff
    {
    public:
      explicit ContactsOff(mjModel *model)
          : model(model)
          , flags(model->opt.disableflags)
      {
        model->opt.disableflags |= mjDSBL_CONTACT;
      }
      ~ContactsOff()
      {
        model->opt.disableflags = flags;
      }
      ContactsOff(const ContactsOff &)            = delete;
      ContactsOff &operator=(const ContactsOff &) = delete;

    private:
      mjModel  *model;
      const int flags;
    };
  } // namespace

  std::vector<double> contact_generalized_force(const mjModel *m, mjData *d)
  {
    std::vector<mjtNum> f(d->efc_force, d->efc_force + d->nefc);
    for (int i = 0; i < d->nefc; ++i)
      if (d->efc_type[i] != mjCNSTR_CONTACT_FRICTIONLESS &&
          d->efc_type[i] != mjCNSTR_CONTACT_PYRAMIDAL &&
          d->efc_type[i] != mjCNSTR_CONTACT_ELLIPTIC)
        f[i] = 0;
    std::vector<double> result(m->nv, 0.0);
    if (d->nefc > 0)
      mj_mulJacTVec(m, d, result.data(), f.data());
    return result;
  }

  std::vector<double> loaded_hand_qpos(mjModel                      *m,
                                       const mjData                 *start,
                                       const std::vector<double>    &load,
                                       const std::vector<HandDrive> &drives,
                                       const std::vector<double>    &controls,
                                       const double velocity_tolerance,
                                       const double window,
                                       const double max_time,
                                       bool        &settled)
  {
    const ContactsOff off(m);
    mjData           *d = mj_makeData(m);
    mj_copyData(d, m, start);
    std::copy(load.begin(), load.end(), d->qfrc_applied);
    std::vector<int> dofs;
    for (std::size_t k = 0; k < drives.size(); ++k)
    {
      d->ctrl[drives[k].actuator] = controls[k];
      for (const int j : drives[k].joints)
        dofs.push_back(m->jnt_dofadr[j]);
    }
    const double t0 = d->time;
    settled         = false;
    while (!settled && d->time - t0 < max_time)
    {
      const double end = d->time + window;
      while (d->time < end)
        mj_step(m, d);
      double fastest = 0;
      for (const int v : dofs)
        fastest = std::max(fastest, std::abs(d->qvel[v]));
      settled = fastest < velocity_tolerance;
    }
    std::vector<double> qpos(d->qpos, d->qpos + m->nq);
    mj_deleteData(d);
    return qpos;
  }

  std::vector<std::string>
  keyframe_closing_actuators(const MujocoModel      &model,
                             const std::string      &key,
                             const std::vector<int> &exclude)
  {
    const mjModel           *m = model.model();
    const int                k = model.id(mjOBJ_KEY, key, "keyframe");
    std::vector<std::string> result;
    for (int a = 0; a < m->nu; ++a)
    {
      if (std::find(exclude.begin(), exclude.end(), a) != exclude.end() ||
          !is_position_servo(m, a))
        continue;
      const double change = m->key_ctrl[k * m->nu + a] - m->actuator_length0[a];
      if (std::abs(change) > 1e-12 * (1 + std::abs(m->actuator_length0[a])))
        result.push_back((change < 0 ? "-" : "") +
                         name_of(m, mjOBJ_ACTUATOR, a));
    }
    if (result.empty())
      throw InputError("The keyframe '" + key + "' of the scene '" +
                       model.file +
                       "' gives every position servo of the hand the target "
                       "it has at rest (qpos0), so it says nothing about how "
                       "the hand closes. Fix: give the closed hand's targets "
                       "in its ctrl, or name the actuators in 'Rigid "
                       "environment/Closing actuators'.");
    return result;
  }

  double actuator_length(const mjModel *m, const mjtNum *qpos, const int a)
  {
    const int    target = m->actuator_trnid[2 * a];
    const double gear   = m->actuator_gear[6 * a];
    if (m->actuator_trntype[a] == mjTRN_JOINT)
      return gear * qpos[m->jnt_qposadr[target]];
    double length = 0;
    for (int w = m->tendon_adr[target];
         w < m->tendon_adr[target] + m->tendon_num[target];
         ++w)
      length += m->wrap_prm[w] * qpos[m->jnt_qposadr[m->wrap_objid[w]]];
    return gear * length;
  }

  std::string drive_name(const mjModel *m, const HandDrive &drive)
  {
    return (drive.sign < 0 ? "-" : "") +
           name_of(m, mjOBJ_ACTUATOR, drive.actuator);
  }
} // namespace softgrasp
