// The closing phase of GraspSimulation: every drive closes until it
// touches the object, then the grasp settles to the equilibrium state.
#include <algorithm>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/grasp_simulation.h>

namespace softgrasp
{
  std::string GraspSimulation::drive_label(const std::size_t k) const
  {
    const mjModel *m = mujoco.model();
    return drives[k].subtree_touch
               ? "actuator '" + drive_name(m, drives[k]) + "'"
               : "joint '" +
                     std::string(
                         mj_id2name(m, mjOBJ_JOINT, drives[k].joints.front())) +
                     "'";
  }

  bool GraspSimulation::drive_touches(const std::size_t k) const
  {
    const mjModel *m = mujoco.model();
    for (const int j : drives[k].joints)
      if (!touches_object(m->jnt_bodyid[j], drives[k].subtree_touch))
        return false;
    return true;
  }

  double GraspSimulation::drive_reach(const std::size_t k,
                                      const mjData     *d) const
  {
    const mjModel                          *m       = mujoco.model();
    double                                  closest = 1e300;
    const Eigen::Map<const Eigen::Vector3d> centre(d->xpos + 3 * object_body);
    for (const int j : drives[k].joints)
      for (int g = 0; g < m->ngeom; ++g)
        for (int b = m->geom_bodyid[g]; b > 0; b = m->body_parentid[b])
          if (b == m->jnt_bodyid[j])
          {
            const Eigen::Map<const Eigen::Vector3d> x(d->geom_xpos + 3 * g);
            closest = std::min(closest, (x - centre).norm());
            break;
          }
    return closest;
  }

  bool GraspSimulation::other_sign_touches(const std::size_t k,
                                           double           &reach) const
  {
    mjModel     *m      = mujoco.model();
    mjData      *d      = mujoco.make_data();
    const int    a      = drives[k].actuator;
    const double step   = -drives[k].sign * parameters.closing_speed;
    bool         ranged = true, touched = false;
    mj_copyData(d, m, closing_start);
    while (ranged && !touched && d->time < parameters.maximum_time)
    {
      d->ctrl[a] += step * m->opt.timestep;
      ranged = !m->actuator_ctrllimited[a] ||
               (d->ctrl[a] >= m->actuator_ctrlrange[2 * a] &&
                d->ctrl[a] <= m->actuator_ctrlrange[2 * a + 1]);
      mj_step(m, d);
      for (const int j : drives[k].joints)
        touched = touched || touches_object(m->jnt_bodyid[j], true, d);
    }
    reach = drive_reach(k, d);
    mj_deleteData(d);
    return touched;
  }

  void GraspSimulation::never_touched(const std::size_t  k,
                                      const std::string &what) const
  {
    // The other way touches, or it leads towards the object while the
    // closing led away (a short range may stop it before it touches).
    double       other_reach = 0;
    const bool   touches     = other_sign_touches(k, other_reach);
    const double start       = drive_reach(k, closing_start);
    const double now         = drive_reach(k, mujoco.data());
    const bool   opens       = touches || (other_reach < start && now > start);
    std::string  fix =
        opens ? (drives[k].subtree_touch
                      ? "write '" + std::string(drives[k].sign > 0 ? "-" : "") +
                           mj_id2name(mujoco.model(),
                                      mjOBJ_ACTUATOR,
                                      drives[k].actuator) +
                           "' in 'Rigid environment/Closing actuators'"
                      : "turn the joint's axis so that a positive target "
                        "closes it, or name its actuator with a '-' in "
                        "'Rigid environment/Closing actuators'")
               : "move the hand closer to the object ('Rigid "
                 "environment/Base position'), or widen the actuator's "
                 "ctrlrange and the joints' range";
    throw InputError(
        "The " + drive_label(k) + " reached the end of its " + what +
        " without touching the object" +
        (opens
             ? std::string(touches ? ", while the opposite target brings "
                                     "its links onto it"
                                   : ": its links moved away from the "
                                     "object, and the opposite target "
                                     "moves them towards it") +
                   ": the closing sign opens the hand"
             : ", and neither does the opposite target: the hand cannot reach "
               "the object") +
        ". Fix: " + fix + ".");
  }

  void GraspSimulation::close_drive(const std::size_t    k,
                                    std::vector<bool>   &touched,
                                    std::vector<double> &targets)
  {
    const mjModel   *m     = mujoco.model();
    mjData          *d     = mujoco.data();
    const HandDrive &drive = drives[k];
    const int        a     = drive.actuator;
    // A drive starts closing once the drive of its parent link's joint has
    // touched (proximal before distal: the finger wraps around the object).
    for (std::size_t p = 0; p < drives.size(); ++p)
      for (const int jp : drives[p].joints)
        for (const int j : drive.joints)
          if (p != k && !touched[p] &&
              m->jnt_bodyid[jp] == m->body_parentid[m->jnt_bodyid[j]])
            return;
    if (drive_touches(k))
    {
      touched[k]          = true;
      const double length = actuator_length(m, d->qpos, a);
      targets[k]          = length + drive.sign * parameters.grip;
      log << "  t = " << std::setw(6) << d->time << " s: "
          << (drive.subtree_touch
                  ? drive_name(m, drive)
                  : mj_id2name(m, mjOBJ_JOINT, drive.joints.front()))
          << " touches at " << length << " " << joint_unit << ", target "
          << targets[k] << " " << joint_unit << "\n";
    }
    else
    {
      targets[k] += drive.sign * parameters.closing_speed * m->opt.timestep;
      if (m->actuator_ctrllimited[a] &&
          (targets[k] > m->actuator_ctrlrange[2 * a + 1] ||
           targets[k] < m->actuator_ctrlrange[2 * a]))
        never_touched(k, "ctrlrange");
    }
    set_control(a, targets[k]);
  }

  void GraspSimulation::close_to_equilibrium()
  {
    const mjModel      *m = mujoco.model();
    mjData             *d = mujoco.data();
    std::vector<bool>   touched(drives.size(), false);
    std::vector<double> targets(drives.size());
    mj_forward(m, d);
    log << "MuJoCo: the hand closes by";
    for (std::size_t k = 0; k < drives.size(); ++k)
    {
      if (drives[k].subtree_touch)
      {
        log << (k ? "; " : " ") << drive_label(k) << " (joints";
        for (const int j : drives[k].joints)
          log << ' ' << mj_id2name(m, mjOBJ_JOINT, j);
        log << ')';
      }
      else
        log << (k ? ", " : " ") << drive_label(k);
      targets[k] = actuator_length(m, d->qpos, drives[k].actuator);
      set_control(drives[k].actuator, targets[k]);
    }
    if (closing_start == nullptr)
      closing_start = mujoco.make_data();
    mj_copyData(closing_start, m, d);
    log << "\nMuJoCo: closing the hand at " << parameters.closing_speed << " "
        << joint_unit << "/s, grip " << parameters.grip << " " << joint_unit
        << " beyond first touch\n";
    double next_sample = 0;
    record(0, d);
    while (std::find(touched.begin(), touched.end(), false) != touched.end())
    {
      if (d->time > parameters.maximum_time)
        never_touched(std::find(touched.begin(), touched.end(), false) -
                          touched.begin(),
                      "'Maximum time' (" +
                          std::to_string(parameters.maximum_time) + " s)");
      for (std::size_t k = 0; k < drives.size(); ++k)
        if (!touched[k])
          close_drive(k, touched, targets);
      mj_step(m, d);
      if (d->time >= next_sample)
      {
        record(d->time, d);
        next_sample += parameters.sample_interval;
      }
    }
    hold_until_settled();
    record_equilibrium();
  }

} // namespace softgrasp
