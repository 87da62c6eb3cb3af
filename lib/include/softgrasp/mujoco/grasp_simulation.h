#ifndef softgrasp_mujoco_grasp_simulation_h
#define softgrasp_mujoco_grasp_simulation_h

#include <memory>
#include <ostream>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grip_levels.h>
#include <softgrasp/mujoco/link_forces.h>
#include <softgrasp/mujoco/mujoco_model.h>

namespace softgrasp
{
  /**
   * The rigid half of the framework: MuJoCo closes the hand around the
   * object to the equilibrium grasp, then records the phases the finite
   * element solver replays, all into one KinematicsData (written with
   * write_kinematics_file()):
   *
   *  1. "closing": every finger joint's actuator target ramps at the
   *     closing speed until that joint's link touches the object, then is
   *     set to the touch angle plus the grip; the simulation continues
   *     until the equilibrium state: every contact link touches, every
   *     joint is at rest and the link forces have settled. Recorded from
   *     MuJoCo's state (simulated time).
   *  2. "indentation": the finger joints are closed further, by
   *     extra_angle * k/samples (times each joint's weight). The recorded poses
   * are MuJoCo's forward kinematics of the equilibrium angles plus that closure
   * with the object where it was (what the finite element solver drives); the
   *     recorded forces are MuJoCo's own, settled at the same actuator
   *     targets (the rigid model's answer to the same command).
   *  3. "pull" (if a distance is set): the base moves along the slide
   *     joint; poses by forward kinematics, forces from the simulation.
   *
   * Times after the equilibrium are pseudo-times (the phase durations).
   */
  class GraspSimulation
  {
  public:
    GraspSimulation(const GraspParameters &parameters, std::ostream &log);
    ~GraspSimulation();

    /// Run all phases; throws an InputError if no equilibrium is reached.
    KinematicsData run();

    const MujocoModel &model() const;

    /**
     * After run(): the grasp-and-pull at each grip level of @p settings,
     * each from the equilibrium state. A level's closure c (added to every
     * finger joint's actuator target, times the joint's weight) is found by
     * regula falsi on the settled normal force of the grip link (MuJoCo's own
     * answer to the command); then, holding those targets, the slide actuator's
     * target moves the pull distance at the pull speed, recording every link's
     * forces and slip speed and where the base is. Levels above what the hand
     * can reach within the maximum closure come back with matched = false.
     */
    std::vector<RigidGripLevel> grip_levels(const GripLevelSettings &settings);

  private:
    void place_base();
    void close_to_equilibrium();
    /// One time step of closing finger joint @p k (index into
    /// finger_joints): it waits for its parent link's joint, stops at first
    /// touch with its target @p grip beyond, or moves its target on.
    void close_joint(const std::size_t    k,
                     std::vector<bool>   &touched,
                     std::vector<double> &targets);
    /// Hold the targets until the grasp settles (recording as it goes); an
    /// InputError naming what moves or misses contact if it never does.
    void hold_until_settled();
    /// The equilibrium state: time, phase, state copy, targets and the
    /// links' contact forces (logged).
    void record_equilibrium();
    void indent();
    void pull();
    /// Step until at rest with settled forces, at most @p max_time (s).
    bool settle(const double max_time, const bool require_links);
    bool touches_object(const int body) const;
    /// The joint of the fastest degree of freedom (for messages).
    std::string              fastest_joint() const;
    std::vector<std::string> missing_links() const;
    void                     set_target(const int joint, const double value);
    /// The share of a closure that finger joint @p k takes (Joint weights).
    double weight(const std::size_t k) const;
    /// Append a sample: poses from @p pose_data, forces from the simulation.
    void record(const double time, const mjData *pose_data);
    /// The grip link's normal force (N) after settle_time at closure c
    /// from the equilibrium state, averaged over the last settle window.
    double grip_force_at(const double             closure,
                         const int                grip_geom,
                         const GripLevelSettings &settings);
    /**
     * The closure (rad) at which the grip force on @p grip_geom meets
     * @p level's target within @p tolerance (N): bracketed from the level
     * below (closure @p low, force @p low_force), then regula falsi. The
     * simulation is left at that closure, settled; sets the level's force,
     * closure, trials and whether it was met.
     */
    void find_closure(const double             low,
                      const double             low_force,
                      const int                grip_geom,
                      const GripLevelSettings &settings,
                      RigidGripLevel          &level);
    /// The pull of one level, from the state grip_force_at() left.
    void pull_at_level(const GripLevelSettings &settings,
                       RigidGripLevel          &level);
    /// Forward kinematics of the equilibrium with joint angles changed.
    void forward_kinematics(const std::vector<double> &finger_angles,
                            const double               slide);

    const GraspParameters parameters;
    std::ostream         &log;
    MujocoModel           mujoco;
    mjData               *fk_data          = nullptr;
    mjData               *equilibrium_data = nullptr; ///< state at equilibrium
    int                   object_body, base_body, slide_joint = -1;
    std::vector<int>      finger_joints, finger_actuators, link_geoms;
    /// The finger joints' unit: "rad" (hinges) or "m" (slide joints).
    std::string joint_unit = "rad";
    /// The joints in the file (fingers, then the slide joint) and their
    /// actuators.
    std::vector<int>    recorded_joints, recorded_actuators;
    std::vector<int>    required_links;
    std::vector<int>    hand_bodies;
    std::vector<double> equilibrium_qpos, equilibrium_targets;
    KinematicsData      data;
  };
} // namespace softgrasp

#endif
