#include <algorithm>
#include <cmath>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mujoco/grasp_simulation.h>

namespace softgrasp
{
  std::vector<double> grip_level_forces(const GripLevelSettings &settings,
                                        const double             equilibrium)
  {
    const double low =
        settings.lowest_force > 0 ? settings.lowest_force : equilibrium;
    std::vector<double> forces;
    for (unsigned int k = 0; k < settings.levels; ++k)
      forces.push_back(settings.levels == 1
                           ? settings.highest_force
                           : low + (settings.highest_force - low) * k /
                                       (settings.levels - 1.0));
    return forces;
  }

  double GraspSimulation::grip_force_at(const double             closure,
                                        const int                grip_geom,
                                        const GripLevelSettings &settings)
  {
    const mjModel *m = mujoco.model();
    mjData        *d = mujoco.data();
    mj_copyData(d, m, equilibrium_data);
    apply_closure(closure);
    const double end     = d->time + settings.settle_time;
    const double average = end - parameters.settle_window;
    double       sum = 0, weight = 0;
    while (d->time < end)
    {
      mj_step(m, d);
      if (d->time >= average)
      {
        mj_forward(m, d);
        const auto f = link_contact_forces(m, d, object_body, {grip_geom});
        sum += f[0].normal_force.norm();
        weight += 1;
      }
    }
    return weight > 0 ? sum / weight : 0;
  }

  namespace
  {
    /// The servo of a position-controlled arm during the pull, while it
    /// lives: gain @p stiffness (N/m), the slide joint critically damped
    /// for the hand's @p mass (kg); the scene's own values come back
    /// afterwards, also when the pull throws.
    class PullServo
    {
    public:
      PullServo(mjModel     *model,
                const int    actuator,
                const int    dof,
                const double stiffness,
                const double mass)
          : model(model)
          , actuator(actuator)
          , dof(dof)
          , gain(model->actuator_gainprm[mjNGAIN * actuator])
          , bias(model->actuator_biasprm[mjNBIAS * actuator + 1])
          , damping(model->dof_damping[dof])
      {
        model->actuator_gainprm[mjNGAIN * actuator]     = stiffness;
        model->actuator_biasprm[mjNBIAS * actuator + 1] = -stiffness;
        model->dof_damping[dof] = 2 * std::sqrt(stiffness * mass);
      }
      ~PullServo()
      {
        model->actuator_gainprm[mjNGAIN * actuator]     = gain;
        model->actuator_biasprm[mjNBIAS * actuator + 1] = bias;
        model->dof_damping[dof]                         = damping;
      }
      PullServo(const PullServo &)            = delete;
      PullServo &operator=(const PullServo &) = delete;

    private:
      mjModel     *model;
      const int    actuator, dof;
      const double gain, bias, damping;
    };

    /// Adds one step's link forces and slip speeds to the level's sums.
    void add_to_means(const std::vector<LinkContactForce> &f,
                      const std::vector<double>           &v,
                      const Eigen::Vector3d               &axis,
                      RigidGripLevel                      &level)
    {
      for (std::size_t k = 0; k < f.size(); ++k)
      {
        auto &link = level.links[k];
        link.normal_mean += f[k].normal_force.norm();
        link.lateral_mean += f[k].lateral_force().norm();
        link.drag_mean += -f[k].force.dot(axis);
        link.slip_mean += v[k];
      }
    }

    /// The sums over @p n steps as means; whether each link slides.
    void finish_means(const unsigned int       n,
                      const GripLevelSettings &settings,
                      RigidGripLevel          &level)
    {
      for (auto &link : level.links)
      {
        const double steps = std::max(1u, n);
        link.normal_mean /= steps;
        link.lateral_mean /= steps;
        link.drag_mean /= steps;
        link.slip_mean /= steps;
        link.slides =
            link.normal_mean > 0 &&
            link.slip_mean > settings.slide_fraction * settings.pull_speed;
      }
    }
  } // namespace

  void GraspSimulation::pull_at_level(const GripLevelSettings &settings,
                                      RigidGripLevel          &level)
  {
    const mjModel *m           = mujoco.model();
    mjData        *d           = mujoco.data();
    const int      address     = m->jnt_qposadr[slide_joint];
    const double   slide0      = d->qpos[address];
    const double   duration    = settings.pull_distance / settings.pull_speed;
    const double   t0          = d->time;
    const double   interval    = duration / settings.samples;
    const Eigen::Vector3d axis = parameters.pull.axis.normalized();
    const PullServo       servo(mujoco.model(),
                          mujoco.actuator_of_joint(slide_joint),
                          m->jnt_dofadr[slide_joint],
                          settings.pull_stiffness,
                          m->body_subtreemass[base_body]);

    level.links.clear();
    for (const int g : link_geoms)
    {
      RigidLinkPull link;
      link.body = mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[g]);
      link.geom = mj_id2name(m, mjOBJ_GEOM, g);
      level.links.push_back(link);
    }
    auto sample = [&]()
    {
      mj_forward(m, d);
      level.time.push_back(d->time - t0);
      level.slide.push_back(d->qpos[address] - slide0);
      const auto forces = link_contact_forces(m, d, object_body, link_geoms);
      const auto speeds = link_slip_speeds(m, d, object_body, link_geoms);
      for (std::size_t k = 0; k < link_geoms.size(); ++k)
      {
        level.links[k].normal.push_back(forces[k].normal_force.norm());
        level.links[k].lateral.push_back(forces[k].lateral_force().norm());
        level.links[k].drag.push_back(-forces[k].force.dot(axis));
        level.links[k].slip_speed.push_back(speeds[k]);
      }
    };
    sample();
    // The slide target moves the distance at the pull speed; the base lags
    // it by the drag over the servo's stiffness (level.slide records where
    // it is).
    double       next  = t0 + interval;
    unsigned int n_avg = 0;
    while (d->time - t0 < duration - 0.5 * m->opt.timestep)
    {
      const double moved =
          std::min(1.0, (d->time - t0) / duration) * settings.pull_distance;
      set_target(slide_joint, slide0 + moved);
      mj_step(m, d);
      if (d->time - t0 >= 0.5 * duration)
      { // means over every step: MuJoCo's sliding contacts chatter
        mj_forward(m, d);
        add_to_means(link_contact_forces(m, d, object_body, link_geoms),
                     link_slip_speeds(m, d, object_body, link_geoms),
                     axis,
                     level);
        ++n_avg;
      }
      if (d->time >= next - 0.5 * m->opt.timestep)
      {
        sample();
        next += interval;
      }
    }
    if (level.time.back() < d->time - t0 - 0.5 * m->opt.timestep)
      sample();
    finish_means(n_avg, settings, level);
  }

  void GraspSimulation::find_closure(const double             low,
                                     const double             low_force,
                                     const int                grip_geom,
                                     const GripLevelSettings &settings,
                                     RigidGripLevel          &level)
  {
    const double tolerance = settings.force_tolerance * level.target_force;
    // Bracket the target from the level below, then regula falsi
    // (Illinois): the force grows with the closure.
    double a = low, fa = low_force - level.target_force;
    double b = std::max(a + 0.02, 2 * a), fb = 0;
    for (;;)
    {
      b  = std::min(b, settings.maximum_closure);
      fb = grip_force_at(b, grip_geom, settings) - level.target_force;
      ++level.trials;
      if (fb >= 0 || b >= settings.maximum_closure)
        break;
      a = b, fa = fb;
      b = 2 * b;
    }
    double c = b, fc = fb;
    if (fa >= 0)
      c = a, fc = fa;
    int side = 0;
    while (std::abs(fc) > tolerance && fb >= 0 && fa < 0 && level.trials < 30)
    {
      c  = (a * fb - b * fa) / (fb - fa);
      fc = grip_force_at(c, grip_geom, settings) - level.target_force;
      ++level.trials;
      if (fc > 0)
      {
        b = c, fb = fc;
        if (side == 1)
          fa *= 0.5;
        side = 1;
      }
      else
      {
        a = c, fa = fc;
        if (side == -1)
          fb *= 0.5;
        side = -1;
      }
    }
    // Leave the simulation at the chosen closure, settled, for the pull.
    level.reached_force = grip_force_at(c, grip_geom, settings);
    level.closure       = c;
    level.matched =
        std::abs(level.reached_force - level.target_force) <= 2 * tolerance;
  }

  std::vector<RigidGripLevel>
  GraspSimulation::grip_levels(const GripLevelSettings &settings)
  {
    if (equilibrium_data == nullptr)
      throw InputError("Grip levels need the equilibrium state: run the "
                       "rigid stage first.");
    if (slide_joint < 0)
      throw InputError("The scene '" + mujoco.file + "' has no slide joint '" +
                       parameters.pull.slide_joint +
                       "' to pull the hand with. Fix: name the base's slide "
                       "joint in 'Rigid environment/Pull/Slide joint'.");
    const int grip_geom = mujoco.id(mjOBJ_GEOM, settings.grip_link, "geom");
    // MuJoCo combines two geoms' friction by their maximum.
    const mjModel *m        = mujoco.model();
    double         friction = m->geom_friction[3 * grip_geom];
    for (int g = 0; g < m->ngeom; ++g)
      if (m->geom_bodyid[g] == object_body)
        friction = std::max(friction, m->geom_friction[3 * g]);
    std::vector<RigidGripLevel> levels;
    double                      low = 0; // closure of the level before
    double low_force                = grip_force_at(0, grip_geom, settings);
    log << "MuJoCo: grip levels on " << settings.grip_link
        << " (equilibrium: " << low_force << " N), pull of "
        << settings.pull_distance << " m at " << settings.pull_speed
        << " m/s\n";
    if (settings.lowest_force == 0 && low_force >= settings.highest_force)
      throw InputError(
          "MuJoCo's grip force on " + settings.grip_link +
          " at the equilibrium state (" + std::to_string(low_force) +
          " N) is not below the highest grip level (" +
          std::to_string(settings.highest_force) +
          " N), so there are no levels between them. Fix: lower 'Rigid "
          "environment/Grip' (the closure beyond first touch) or raise "
          "'Grasp-and-pull sweep/Highest grip force'.");
    for (const double target : grip_level_forces(settings, low_force))
    {
      RigidGripLevel level;
      level.target_force = target;
      level.friction     = friction;
      find_closure(low, low_force, grip_geom, settings, level);
      low       = level.closure;
      low_force = level.reached_force;
      pull_at_level(settings, level);
      log << "  level " << std::setw(2) << levels.size() + 1 << ": "
          << std::setw(7) << level.reached_force << " N (target " << target
          << " N) at closure " << std::setw(8) << level.closure << " "
          << joint_unit << ", " << level.trials << " trials"
          << (level.matched ? "" : " (not reached: 'Maximum closure')") << '\n';
      levels.push_back(std::move(level));
    }
    return levels;
  }
} // namespace softgrasp
