#include <algorithm>
#include <cmath>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/grasp_simulation.h>
#include <softgrasp/rigid/triangle_mesh_shape.h>

namespace softgrasp
{
  namespace
  {
    /**
     * The surface of the mesh geom @p g as MuJoCo holds it after compiling
     * the model (re-centred in the geom's frame, which geom_pos and
     * geom_quat place): the finite element link is exactly MuJoCo's.
     */
    void
    add_mesh_surface(const mjModel *m, const int g, KinematicsData::Geom &geom)
    {
      const int mesh = m->geom_dataid[g];
      for (int v = 0; v < m->mesh_vertnum[mesh]; ++v)
      {
        const float *p = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + v);
        geom.vertices.emplace_back(p[0], p[1], p[2]);
      }
      for (int f = 0; f < m->mesh_facenum[mesh]; ++f)
      {
        const int *t = m->mesh_face + 3 * (m->mesh_faceadr[mesh] + f);
        geom.triangles.push_back(
            std::array<unsigned, 3>{{static_cast<unsigned>(t[0]),
                                     static_cast<unsigned>(t[1]),
                                     static_cast<unsigned>(t[2])}});
      }
    }
  } // namespace
  namespace
  {
    double max_abs(const mjtNum *values, const int n)
    {
      double result = 0;
      for (int i = 0; i < n; ++i)
        result = std::max(result, std::abs(values[i]));
      return result;
    }
  } // namespace

  GraspSimulation::GraspSimulation(const GraspParameters &parameters,
                                   std::ostream          &log)
      : parameters(parameters)
      , log(log)
      , mujoco(parameters.scene_file)
  {
    if (!mujoco.warnings().empty())
      log << "MuJoCo warning while loading " << mujoco.file << ": "
          << mujoco.warnings() << '\n';
    mujoco.check_contact_time_constants();
    const mjModel *m = mujoco.model();
    object_body      = mujoco.id(mjOBJ_BODY, parameters.object_body, "body");
    base_body        = mujoco.id(mjOBJ_BODY, parameters.base_body, "body");
    auto closing     = parameters.closing_actuators;
    if (!parameters.closing_keyframe.empty())
    {
      if (!closing.empty())
        throw InputError("'Rigid environment/Closing keyframe' and 'Closing "
                         "actuators' are both given. Fix: leave one empty.");
      const int pull =
          mj_name2id(m, mjOBJ_JOINT, parameters.pull.slide_joint.c_str());
      closing = keyframe_closing_actuators(
          mujoco,
          parameters.closing_keyframe,
          {pull >= 0 ? mujoco.actuator_of_joint(pull) : -1});
      log << "MuJoCo: keyframe '" << parameters.closing_keyframe
          << "' closes the hand by";
      for (const auto &name : closing)
        log << ' ' << name;
      log << '\n';
    }
    drives = hand_drives(mujoco,
                         parameters.finger_joints,
                         closing,
                         parameters.indentation.joint_weights,
                         joint_unit);
    coupled_drives =
        std::any_of(drives.begin(),
                    drives.end(),
                    [](const HandDrive &drive) { return drive.coupled; });
    for (const auto &name : parameters.contact_links)
      required_links.push_back(mujoco.id(mjOBJ_GEOM, name, "geom"));
    // The slide joint is recorded whenever the scene has it (the base may
    // give way along it while grasping); a pull needs it.
    slide_joint =
        mj_name2id(m, mjOBJ_JOINT, parameters.pull.slide_joint.c_str());
    if (parameters.pull.distance > 0 || slide_joint >= 0)
    {
      slide_joint =
          mujoco.id(mjOBJ_JOINT, parameters.pull.slide_joint, "joint");
      if (m->jnt_type[slide_joint] != mjJNT_SLIDE ||
          mujoco.actuator_of_joint(slide_joint) < 0)
        throw InputError("'Rigid environment/Pull/Slide joint' = '" +
                         parameters.pull.slide_joint +
                         "' is not a slide joint with an actuator. Fix: name "
                         "the base's slide joint.");
    }
    for (const auto &drive : drives)
      for (const int j : drive.joints)
        if (std::find(recorded_joints.begin(), recorded_joints.end(), j) ==
            recorded_joints.end())
        {
          recorded_joints.push_back(j);
          recorded_actuators.push_back(drive.actuator);
        }
    if (slide_joint >= 0)
    {
      recorded_joints.push_back(slide_joint);
      recorded_actuators.push_back(mujoco.actuator_of_joint(slide_joint));
    }
    // The hand: every body but the world and the object's subtree; its
    // geoms are the links whose forces are recorded.
    for (int b = 1; b < m->nbody; ++b)
    {
      bool in_object = false;
      for (int p = b; p > 0; p = m->body_parentid[p])
        in_object = in_object || p == object_body;
      if (!in_object)
        hand_bodies.push_back(b);
    }
    for (int g = 0; g < m->ngeom; ++g)
      if (std::find(hand_bodies.begin(),
                    hand_bodies.end(),
                    m->geom_bodyid[g]) != hand_bodies.end())
      {
        if (m->geom_type[g] == mjGEOM_HFIELD)
          throw InputError(
              "Hand geom '" + std::string(mj_id2name(m, mjOBJ_GEOM, g)) +
              "' is a height field, which the kinematics file cannot "
              "carry. Fix: model the link with a mesh or primitive geoms.");
        if (m->geom_type[g] == mjGEOM_MESH)
        { // the finite element link needs a closed, oriented surface: say
          // so now, not after the rigid stage
          KinematicsData::Geom mesh;
          add_mesh_surface(m, g, mesh);
          const TriangleMeshShape check(
              mesh.vertices,
              mesh.triangles,
              "mesh of the hand geom '" +
                  std::string(mj_id2name(m, mjOBJ_GEOM, g)) + "' (scene '" +
                  mujoco.file + "', as MuJoCo compiled it)");
        }
        link_geoms.push_back(g);
      }
    fk_data = mujoco.make_data();
  }

  GraspSimulation::~GraspSimulation()
  {
    if (fk_data)
      mj_deleteData(fk_data);
    if (equilibrium_data)
      mj_deleteData(equilibrium_data);
    if (closing_start)
      mj_deleteData(closing_start);
  }

  const MujocoModel &GraspSimulation::model() const
  {
    return mujoco;
  }

  void GraspSimulation::place_base()
  {
    mjModel *m = mujoco.model();
    for (int i = 0; i < 3; ++i)
      m->body_pos[3 * base_body + i] = parameters.base_position[i];
    const auto &q                   = parameters.base_orientation;
    m->body_quat[4 * base_body]     = q.w();
    m->body_quat[4 * base_body + 1] = q.x();
    m->body_quat[4 * base_body + 2] = q.y();
    m->body_quat[4 * base_body + 3] = q.z();
    if (slide_joint >= 0) // the slider moves along the world pull axis
    {
      const Eigen::Vector3d local = q.conjugate() * parameters.pull.axis;
      for (int i = 0; i < 3; ++i)
        m->jnt_axis[3 * slide_joint + i] = local[i];
    }
    mj_resetData(m, mujoco.data());
    mj_forward(m, mujoco.data());
  }

  KinematicsData GraspSimulation::run()
  {
    place_base();
    data        = KinematicsData();
    data.source = "softgrasp GraspSimulation (MuJoCo " +
                  std::to_string(mj_version()) + "), scene " + mujoco.file;
    const mjModel *m = mujoco.model();
    for (const int b : hand_bodies)
    {
      KinematicsData::Body body;
      body.name = mj_id2name(m, mjOBJ_BODY, b);
      for (const int g : link_geoms)
        if (m->geom_bodyid[g] == b)
        {
          KinematicsData::Geom geom;
          geom.name                = mj_id2name(m, mjOBJ_GEOM, g);
          geom.type                = mujoco_geom_type_name(m->geom_type[g]);
          geom.size                = {m->geom_size[3 * g],
                                      m->geom_size[3 * g + 1],
                                      m->geom_size[3 * g + 2]};
          geom.local_pose.position = {m->geom_pos[3 * g],
                                      m->geom_pos[3 * g + 1],
                                      m->geom_pos[3 * g + 2]};
          geom.local_pose.orientation =
              Eigen::Quaterniond(m->geom_quat[4 * g],
                                 m->geom_quat[4 * g + 1],
                                 m->geom_quat[4 * g + 2],
                                 m->geom_quat[4 * g + 3]);
          if (m->geom_type[g] == mjGEOM_MESH)
            add_mesh_surface(m, g, geom);
          body.geoms.push_back(geom);
        }
      data.bodies.push_back(body);
    }
    { // the object's body too, for placing the finite element body
      KinematicsData::Body body;
      body.name = mj_id2name(m, mjOBJ_BODY, object_body);
      data.bodies.push_back(body);
    }
    for (const int j : recorded_joints)
      data.joints.push_back({mj_id2name(m, mjOBJ_JOINT, j), {}, {}});
    for (const int g : link_geoms)
    {
      KinematicsData::LinkHistory h;
      h.body = mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[g]);
      h.geom = mj_id2name(m, mjOBJ_GEOM, g);
      data.link_forces.push_back(h);
    }

    close_to_equilibrium();
    indent();
    if (parameters.pull.distance > 0)
      pull();
    log << "MuJoCo: " << data.time.size() << " samples recorded\n";
    return data;
  }

  std::string GraspSimulation::fastest_joint() const
  {
    const mjModel *m    = mujoco.model();
    const mjData  *d    = mujoco.data();
    int            best = 0;
    for (int i = 1; i < m->nv; ++i)
      if (std::abs(d->qvel[i]) > std::abs(d->qvel[best]))
        best = i;
    const char *name = mj_id2name(m, mjOBJ_JOINT, m->dof_jntid[best]);
    return name ? name : "unnamed";
  }

  bool GraspSimulation::touches_object(const int     body,
                                       const bool    subtree,
                                       const mjData *data) const
  {
    const mjModel *m     = mujoco.model();
    const mjData  *d     = data ? data : mujoco.data();
    auto           below = [&](int b)
    {
      for (; b > 0; b = subtree ? m->body_parentid[b] : 0)
        if (b == body)
          return true;
      return false;
    };
    for (int c = 0; c < d->ncon; ++c)
    {
      const int b1 = m->geom_bodyid[d->contact[c].geom1];
      const int b2 = m->geom_bodyid[d->contact[c].geom2];
      if ((below(b1) && b2 == object_body) || (below(b2) && b1 == object_body))
        return true;
    }
    return false;
  }

  std::vector<std::string> GraspSimulation::missing_links() const
  {
    const auto forces = link_contact_forces(
        mujoco.model(), mujoco.data(), object_body, required_links);
    std::vector<std::string> missing;
    for (std::size_t i = 0; i < required_links.size(); ++i)
      if (forces[i].n_contacts == 0)
        missing.push_back(parameters.contact_links[i]);
    return missing;
  }

  void GraspSimulation::set_target(const int joint, const double value)
  {
    set_control(mujoco.actuator_of_joint(joint), value);
  }

  void GraspSimulation::set_control(const int a, const double value)
  {
    const mjModel *m = mujoco.model();
    // MuJoCo 2.2 clamps ctrl to ctrlrange without a word: say it instead.
    if (m->actuator_ctrllimited[a] &&
        (value < m->actuator_ctrlrange[2 * a] - 1e-12 ||
         value > m->actuator_ctrlrange[2 * a + 1] + 1e-12))
      throw InputError(
          "The target " + std::to_string(value) + " of actuator '" +
          mj_id2name(m, mjOBJ_ACTUATOR, a) + "' lies outside its ctrlrange [" +
          std::to_string(m->actuator_ctrlrange[2 * a]) + ", " +
          std::to_string(m->actuator_ctrlrange[2 * a + 1]) +
          "], where MuJoCo would clamp it silently. Fix: lower 'Grip' or "
          "'Indentation/Extra joint angle', move the hand closer ('Base "
          "position'), or widen the ctrlrange in the scene.");
    mujoco.data()->ctrl[a] = value;
  }

  namespace
  {
    /// World pose of body @p b in @p d (after kinematics).
    Pose body_pose(const mjData *d, const int b)
    {
      Pose pose;
      pose.position = {d->xpos[3 * b], d->xpos[3 * b + 1], d->xpos[3 * b + 2]};
      pose.orientation = Eigen::Quaterniond(d->xquat[4 * b],
                                            d->xquat[4 * b + 1],
                                            d->xquat[4 * b + 2],
                                            d->xquat[4 * b + 3]);
      return pose;
    }
  } // namespace

  void GraspSimulation::record(const double time, const mjData *pose_data)
  {
    const mjModel *m = mujoco.model();
    mjData        *d = mujoco.data();
    if (!data.time.empty() && time <= data.time.back())
      return;
    // After mj_step() the positions have moved on from the kinematics and
    // contacts of the step: bring them in line with the current state.
    mj_forward(m, d);
    data.time.push_back(time);
    // the hand's bodies, then the object (KinematicsData's body order)
    for (std::size_t i = 0; i < hand_bodies.size(); ++i)
      data.bodies[i].poses.push_back(body_pose(pose_data, hand_bodies[i]));
    data.bodies.back().poses.push_back(body_pose(pose_data, object_body));
    for (std::size_t k = 0; k < recorded_joints.size(); ++k)
    {
      const int j = recorded_joints[k];
      data.joints[k].angle.push_back(pose_data->qpos[m->jnt_qposadr[j]]);
      data.joints[k].target.push_back(d->ctrl[recorded_actuators[k]]);
    }
    const auto forces = link_contact_forces(m, d, object_body, link_geoms);
    for (std::size_t k = 0; k < forces.size(); ++k)
    {
      data.link_forces[k].force.push_back(forces[k].force);
      data.link_forces[k].normal_force.push_back(forces[k].normal_force);
    }
  }

  bool GraspSimulation::settle(const double max_time, const bool require_links)
  {
    const mjModel *m          = mujoco.model();
    mjData        *d          = mujoco.data();
    const double   start      = d->time;
    auto           forces_now = [&]()
    { return link_contact_forces(m, d, object_body, link_geoms); };
    auto previous = forces_now();
    while (d->time - start < max_time)
    {
      const double window_end = d->time + parameters.settle_window;
      while (d->time < window_end)
        mj_step(m, d);
      const auto current = forces_now();
      double     largest = 0, change = 0;
      for (std::size_t k = 0; k < current.size(); ++k)
      {
        largest = std::max(largest, current[k].force.norm());
        change =
            std::max(change, (current[k].force - previous[k].force).norm());
      }
      previous        = current;
      const bool rest = max_abs(d->qvel, m->nv) < parameters.velocity_tolerance;
      const bool steady = change <= parameters.force_tolerance * largest;
      const bool links  = !require_links || missing_links().empty();
      if (rest && steady && links && largest > 0)
        return true;
    }
    return false;
  }

  void GraspSimulation::hold_until_settled()
  {
    const mjModel *m = mujoco.model();
    mjData        *d = mujoco.data();
    // Hold the targets and let the grasp settle, recording as it goes.
    const double max_time = parameters.maximum_time - d->time;
    bool         settled  = false;
    while (!settled && d->time < parameters.maximum_time)
    {
      settled = settle(std::min(parameters.sample_interval, max_time), true);
      record(d->time, d);
    }
    if (!settled)
    {
      std::string missing;
      for (const auto &l : missing_links())
        missing += " " + l;
      throw InputError(
          "MuJoCo did not reach the equilibrium grasp within 'Maximum time' "
          "(" +
          std::to_string(parameters.maximum_time) + " s): largest speed " +
          std::to_string(max_abs(d->qvel, m->nv)) + " (joint '" +
          fastest_joint() + "')" +
          (missing.empty() ? "" : ", links without contact:" + missing) +
          ". Fix: raise the maximum time or the tolerances, place the hand so "
          "that every contact link can reach the object, or shorten 'Contact "
          "links'.");
    }
  }

  void GraspSimulation::record_equilibrium()
  {
    const mjModel *m      = mujoco.model();
    mjData        *d      = mujoco.data();
    data.equilibrium_time = d->time;
    data.phases.push_back({"closing", 0, d->time, 0});
    equilibrium_qpos.assign(d->qpos, d->qpos + m->nq);
    if (equilibrium_data == nullptr)
      equilibrium_data = mujoco.make_data();
    mj_copyData(equilibrium_data, m, d);
    for (const auto &drive : drives)
      equilibrium_targets.push_back(d->ctrl[drive.actuator]);
    if (coupled_drives)
    { // the loaded hand at the equilibrium targets: where closures start
      equilibrium_load = contact_generalized_force(m, d);
      bool settled     = false;
      loaded_baseline  = loaded_hand_qpos(mujoco.model(),
                                         d,
                                         equilibrium_load,
                                         drives,
                                         equilibrium_targets,
                                         1e-2 * parameters.velocity_tolerance,
                                         parameters.settle_window,
                                         parameters.maximum_time,
                                         settled);
      if (!settled)
        log << "MuJoCo: the loaded hand did not come to rest within "
               "'Maximum time' at the equilibrium targets\n";
    }
    const auto forces = link_contact_forces(m, d, object_body, link_geoms);
    log << "MuJoCo: equilibrium grasp at t = " << d->time << " s\n";
    for (std::size_t k = 0; k < link_geoms.size(); ++k)
      if (forces[k].n_contacts > 0)
      {
        data.equilibrium_forces.push_back(
            {data.link_forces[k].body,
             data.link_forces[k].geom,
             forces[k].force,
             -forces[k].normal}); // link -> object
        log << "  " << std::setw(24) << std::left << data.link_forces[k].geom
            << std::right << " normal " << std::setw(8)
            << forces[k].normal_force.norm() << " N, lateral " << std::setw(8)
            << forces[k].lateral_force().norm() << " N\n";
      }
  }

  void GraspSimulation::apply_closure(const double closure)
  {
    for (std::size_t k = 0; k < drives.size(); ++k)
      set_control(drives[k].actuator,
                  equilibrium_targets[k] +
                      drives[k].sign * drives[k].weight * closure);
  }

  void GraspSimulation::closed_pose(const double closure, const double slide)
  {
    mjModel *m = mujoco.model();
    std::copy(equilibrium_qpos.begin(), equilibrium_qpos.end(), fk_data->qpos);
    if (!coupled_drives) // one joint per drive at gear 1: the closure itself
      for (const auto &drive : drives)
        fk_data->qpos[m->jnt_qposadr[drive.joints.front()]] +=
            drive.sign * drive.weight * closure;
    else
    {
      if (closure != loaded_closure)
      {
        std::vector<double> controls;
        for (std::size_t k = 0; k < drives.size(); ++k)
          controls.push_back(equilibrium_targets[k] +
                             drives[k].sign * drives[k].weight * closure);
        bool settled   = false;
        loaded_qpos    = loaded_hand_qpos(m,
                                       equilibrium_data,
                                       equilibrium_load,
                                       drives,
                                       controls,
                                       1e-2 * parameters.velocity_tolerance,
                                       parameters.settle_window,
                                       parameters.maximum_time,
                                       settled);
        loaded_closure = closure;
        if (!settled)
          log << "  (the loaded hand did not come to rest within "
                 "'Maximum time' at closure "
              << closure << ")\n";
      }
      // the equilibrium pose plus the loaded hand's motion from its baseline
      for (const int j : recorded_joints)
        if (j != slide_joint)
        {
          const int q = m->jnt_qposadr[j];
          fk_data->qpos[q] += loaded_qpos[q] - loaded_baseline[q];
        }
    }
    if (slide_joint >= 0)
      fk_data->qpos[m->jnt_qposadr[slide_joint]] = slide;
    mj_kinematics(m, fk_data);
  }

  void GraspSimulation::indent()
  {
    const mjModel *m     = mujoco.model();
    const auto    &ind   = parameters.indentation;
    const double   start = data.equilibrium_time;
    const double   slide0 =
        slide_joint >= 0 ? equilibrium_qpos[m->jnt_qposadr[slide_joint]] : 0;
    log << "MuJoCo: indentation, " << ind.extra_angle << " " << joint_unit
        << " more on " << (ind.joint_weights.empty() ? "every " : "the ")
        << (drives.front().subtree_touch ? "closing actuator" : "finger joint")
        << (ind.joint_weights.empty() ? "" : "s (times their weights)")
        << " in " << ind.samples << " samples\n";
    for (unsigned int s = 1; s <= ind.samples; ++s)
    {
      const double closure = ind.extra_angle * s / ind.samples;
      apply_closure(closure);
      const bool settled = settle(ind.settle_time, false);
      closed_pose(closure, slide0);
      record(start + ind.duration * s / ind.samples, fk_data);
      log << "  closure " << std::setw(6) << closure << " " << joint_unit
          << (settled ? "" : " (MuJoCo not settled within 'Settle time')")
          << '\n';
    }
    data.phases.push_back({"indentation",
                           start,
                           start + ind.duration,
                           ind.extra_angle,
                           joint_unit});
  }

  void GraspSimulation::pull()
  {
    const mjModel *m      = mujoco.model();
    mjData        *d      = mujoco.data();
    const auto    &p      = parameters.pull;
    const double   start  = data.time.back();
    const double   slide0 = equilibrium_qpos[m->jnt_qposadr[slide_joint]];
    log << "MuJoCo: pull of " << p.distance << " m in " << p.duration << " s\n";
    const double t0 = d->time;
    for (unsigned int s = 1; s <= p.samples; ++s)
    {
      const double t_end = t0 + p.duration * s / p.samples;
      while (d->time < t_end)
      {
        const double fraction = std::min(1.0, (d->time - t0) / p.duration);
        set_target(slide_joint, slide0 + p.distance * fraction);
        mj_step(m, d);
      }
      closed_pose(parameters.indentation.extra_angle,
                  slide0 + p.distance * s / p.samples);
      record(start + p.duration * s / p.samples, fk_data);
    }
    data.phases.push_back({"pull", start, start + p.duration, p.distance, "m"});
  }
} // namespace softgrasp
