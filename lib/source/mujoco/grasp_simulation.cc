#include <algorithm>
#include <cmath>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/grasp_simulation.h>

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
    for (const auto &name : parameters.finger_joints)
    {
      const int j = mujoco.id(mjOBJ_JOINT, name, "joint");
      const int a = mujoco.actuator_of_joint(j);
      if ((m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) ||
          a < 0)
        throw InputError("Finger joint '" + name + "' of the scene '" +
                         mujoco.file +
                         "' is not a hinge or slide joint driven by an "
                         "actuator. Fix: list hinge or slide joints with "
                         "<position> actuators in 'Rigid environment/Finger "
                         "joints'.");
      const std::string unit = m->jnt_type[j] == mjJNT_HINGE ? "rad" : "m";
      if (!finger_joints.empty() && unit != joint_unit)
        throw InputError(
            "Finger joints '" +
            std::string(mj_id2name(m, mjOBJ_JOINT, finger_joints.front())) +
            "' and '" + name + "' of the scene '" + mujoco.file +
            "' are a hinge and a slide joint: 'Closing speed', 'Grip' and "
            "'Extra joint angle' are in one unit for all of them (rad, or m "
            "for slide joints). Fix: list joints of one type in 'Rigid "
            "environment/Finger joints'.");
      joint_unit = unit;
      finger_joints.push_back(j);
      finger_actuators.push_back(a);
    }
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
    recorded_joints    = finger_joints;
    recorded_actuators = finger_actuators;
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
  }

  double GraspSimulation::weight(const std::size_t k) const
  {
    const auto &w = parameters.indentation.joint_weights;
    return w.empty() ? 1.0 : w[k];
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

  bool GraspSimulation::touches_object(const int body) const
  {
    const mjModel *m = mujoco.model();
    const mjData  *d = mujoco.data();
    for (int c = 0; c < d->ncon; ++c)
    {
      const int b1 = m->geom_bodyid[d->contact[c].geom1];
      const int b2 = m->geom_bodyid[d->contact[c].geom2];
      if ((b1 == body && b2 == object_body) ||
          (b2 == body && b1 == object_body))
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
    const mjModel *m = mujoco.model();
    const int      a = mujoco.actuator_of_joint(joint);
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

  void GraspSimulation::close_joint(const std::size_t    k,
                                    std::vector<bool>   &touched,
                                    std::vector<double> &targets)
  {
    const mjModel *m  = mujoco.model();
    mjData        *d  = mujoco.data();
    const double   dt = m->opt.timestep;
    const int      j  = finger_joints[k];
    // A joint starts closing once its parent link's joint has touched
    // (proximal before distal: the finger wraps around the object).
    bool parent_closing = false;
    for (std::size_t p = 0; p < finger_joints.size(); ++p)
      parent_closing = parent_closing ||
                       (!touched[p] && m->jnt_bodyid[finger_joints[p]] ==
                                           m->body_parentid[m->jnt_bodyid[j]]);
    if (parent_closing)
      return;
    if (touches_object(m->jnt_bodyid[j]))
    {
      touched[k] = true;
      targets[k] = d->qpos[m->jnt_qposadr[j]] + parameters.grip;
      log << "  t = " << std::setw(6) << d->time
          << " s: " << mj_id2name(m, mjOBJ_JOINT, j) << " touches at "
          << d->qpos[m->jnt_qposadr[j]] << " " << joint_unit << ", target "
          << targets[k] << " " << joint_unit << "\n";
    }
    else
    {
      targets[k] += parameters.closing_speed * dt;
      const int a = finger_actuators[k];
      if (m->actuator_ctrllimited[a] &&
          targets[k] > m->actuator_ctrlrange[2 * a + 1])
        throw InputError(
            std::string("Joint '") + mj_id2name(m, mjOBJ_JOINT, j) +
            "' reached the end of its ctrlrange without touching the "
            "object. Fix: check that a positive target closes it (its axis "
            "must point the closing way: a joint that opens moves away from "
            "the object), or move the hand closer to the object ('Rigid "
            "environment/Base position').");
    }
    set_target(j, targets[k]);
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
    for (const int a : finger_actuators)
      equilibrium_targets.push_back(d->ctrl[a]);
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

  void GraspSimulation::close_to_equilibrium()
  {
    const mjModel      *m = mujoco.model();
    mjData             *d = mujoco.data();
    std::vector<bool>   touched(finger_joints.size(), false);
    std::vector<double> targets(finger_joints.size());
    for (std::size_t k = 0; k < finger_joints.size(); ++k)
    {
      targets[k] = d->qpos[m->jnt_qposadr[finger_joints[k]]];
      set_target(finger_joints[k], targets[k]);
    }
    log << "MuJoCo: closing the hand at " << parameters.closing_speed << " "
        << joint_unit << "/s, grip " << parameters.grip << " " << joint_unit
        << " beyond first touch\n";
    double next_sample = 0;
    record(0, d);
    while (std::find(touched.begin(), touched.end(), false) != touched.end())
    {
      if (d->time > parameters.maximum_time)
        throw InputError("The hand did not touch the object with every "
                         "finger joint's link within 'Maximum time' (" +
                         std::to_string(parameters.maximum_time) +
                         " s). Fix: move the hand closer ('Base position') or "
                         "raise the maximum time.");
      for (std::size_t k = 0; k < finger_joints.size(); ++k)
        if (!touched[k])
          close_joint(k, touched, targets);
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

  void
  GraspSimulation::forward_kinematics(const std::vector<double> &finger_angles,
                                      const double               slide)
  {
    const mjModel *m = mujoco.model();
    std::copy(equilibrium_qpos.begin(), equilibrium_qpos.end(), fk_data->qpos);
    for (std::size_t k = 0; k < finger_joints.size(); ++k)
      fk_data->qpos[m->jnt_qposadr[finger_joints[k]]] = finger_angles[k];
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
        << " more on "
        << (ind.joint_weights.empty() ? "every finger joint"
                                      : "the finger joints (times their "
                                        "weights)")
        << " in " << ind.samples << " samples\n";
    for (unsigned int s = 1; s <= ind.samples; ++s)
    {
      const double        closure = ind.extra_angle * s / ind.samples;
      std::vector<double> angles;
      for (std::size_t k = 0; k < finger_joints.size(); ++k)
      {
        set_target(finger_joints[k],
                   equilibrium_targets[k] + weight(k) * closure);
        angles.push_back(equilibrium_qpos[m->jnt_qposadr[finger_joints[k]]] +
                         weight(k) * closure);
      }
      const bool settled = settle(ind.settle_time, false);
      forward_kinematics(angles, slide0);
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
    const mjModel      *m      = mujoco.model();
    mjData             *d      = mujoco.data();
    const auto         &p      = parameters.pull;
    const double        start  = data.time.back();
    const double        slide0 = equilibrium_qpos[m->jnt_qposadr[slide_joint]];
    std::vector<double> angles;
    for (std::size_t k = 0; k < finger_joints.size(); ++k)
      angles.push_back(equilibrium_qpos[m->jnt_qposadr[finger_joints[k]]] +
                       weight(k) * parameters.indentation.extra_angle);
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
      forward_kinematics(angles, slide0 + p.distance * s / p.samples);
      record(start + p.duration * s / p.samples, fk_data);
    }
    data.phases.push_back({"pull", start, start + p.duration, p.distance, "m"});
  }
} // namespace softgrasp
