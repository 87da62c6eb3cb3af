#ifndef softgrasp_mujoco_grasp_simulation_h
#define softgrasp_mujoco_grasp_simulation_h

#include <memory>
#include <ostream>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grip_levels.h>
#include <softgrasp/mujoco/hand_drive.h>
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
   *  1. "closing": every drive's actuator target (HandDrive: a finger
   *     joint's own actuator, or a closing actuator with the joints it
   *     moves) ramps at the closing speed until its joints touch the
   *     object, then is set to the actuator length at touch plus the grip;
   *     the simulation continues until the equilibrium state: every contact
   *     link touches, every joint is at rest and the link forces have
   *     settled. Recorded from MuJoCo's state (simulated time).
   *  2. "indentation": the drives close further, by extra_angle * k/samples
   *     (times each drive's weight). The recorded poses are the
   *     equilibrium pose plus that closure, with the object where it was
   *     (what the finite element solver drives): forward kinematics for
   *     drives that move one joint at gear 1; otherwise the motion the
   *     same command gives the hand with the object's contact forces held
   *     at their equilibrium values (loaded_hand_qpos()), so couplings,
   *     tendons, gears and springs are honoured. The
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
    /// One time step of closing drive @p k: it waits for the drive of its
    /// parent link's joint, stops at first touch with its target 'Grip'
    /// beyond, or moves its target on.
    void close_drive(const std::size_t    k,
                     std::vector<bool>   &touched,
                     std::vector<double> &targets);
    /// Whether drive @p k touches the object (HandDrive::subtree_touch).
    bool drive_touches(const std::size_t k) const;
    /// Whether drive @p k, moved the other way from the start of the
    /// closing (in a copy of it), brings a link onto the object within its
    /// ctrlrange and 'Maximum time': tells a wrong sign from a short reach.
    /// @p reach: drive_reach() where that stops.
    bool other_sign_touches(const std::size_t k, double &reach) const;
    /// The closest distance (m) from a geom centre below a joint of drive
    /// @p k to the object's centre, in @p d.
    double drive_reach(const std::size_t k, const mjData *d) const;
    /// The InputError for drive @p k that ran out of @p what (its
    /// ctrlrange, or time) without touching.
    [[noreturn]] void never_touched(const std::size_t  k,
                                    const std::string &what) const;
    /// Drive @p k in messages: its joint, or its actuator with its sign.
    std::string drive_label(const std::size_t k) const;
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
    /// Whether a geom of body @p body (or, with @p subtree, of a body
    /// below it) touches the object.
    /// In @p d, or the simulation's data if null.
    bool touches_object(const int     body,
                        const bool    subtree = false,
                        const mjData *d       = nullptr) const;
    /// The joint of the fastest degree of freedom (for messages).
    std::string              fastest_joint() const;
    std::vector<std::string> missing_links() const;
    void                     set_target(const int joint, const double value);
    /// Set actuator @p a's target, refusing one outside its ctrlrange.
    void set_control(const int a, const double value);
    /// Every drive's target at @p closure beyond the equilibrium targets.
    void apply_closure(const double closure);
    /// fk_data = the equilibrium pose with the drives closed by @p closure
    /// and the base slid to @p slide (see the class comment).
    void closed_pose(const double closure, const double slide);
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

    const GraspParameters  parameters;
    std::ostream          &log;
    MujocoModel            mujoco;
    mjData                *fk_data          = nullptr;
    mjData                *equilibrium_data = nullptr; ///< state at equilibrium
    mjData                *closing_start    = nullptr; ///< before closing
    int                    object_body, base_body, slide_joint = -1;
    std::vector<HandDrive> drives;
    /// Whether a drive is coupled (its poses then come from the loaded hand).
    bool             coupled_drives = false;
    std::vector<int> link_geoms;
    /// The drives' joints' unit: "rad" (hinges) or "m" (slide joints).
    std::string joint_unit = "rad";
    /// The joints in the file (the drives', then the slide joint) and
    /// their actuators.
    std::vector<int>    recorded_joints, recorded_actuators;
    std::vector<int>    required_links;
    std::vector<int>    hand_bodies;
    std::vector<double> equilibrium_qpos, equilibrium_targets;
    /// Coupled drives: the contacts' generalized force at the equilibrium,
    /// and the loaded hand at the equilibrium targets (qpos).
    std::vector<double> equilibrium_load, loaded_baseline;
    /// The loaded hand's qpos at closure loaded_closure (pulls reuse it).
    std::vector<double> loaded_qpos;
    double              loaded_closure = -1;
    KinematicsData      data;
  };
} // namespace softgrasp

#endif
