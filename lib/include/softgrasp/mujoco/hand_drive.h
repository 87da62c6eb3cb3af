#ifndef softgrasp_mujoco_hand_drive_h
#define softgrasp_mujoco_hand_drive_h

#include <softgrasp/mujoco/mujoco_model.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * One way the hand closes: a position actuator, the sign of its target
   * that closes, the share of a closure it takes, and the hinge or slide
   * joints it moves. Built from 'Finger joints' (one drive per joint, its
   * own actuator, sign +1) or from 'Closing actuators' (one drive per
   * actuator: the joints of its transmission, joint or fixed tendon, and
   * every joint an active <equality joint=...> couples to them).
   *
   * Closures are in the actuator's length: gear x joint coordinate for a
   * joint transmission (rad or m at gear 1), the tendon length for a fixed
   * tendon.
   */
  struct HandDrive
  {
    int              actuator = -1;
    double           sign     = 1; ///< +1 or -1: the target's closing way
    double           weight   = 1; ///< share of a closure ('Joint weights')
    std::vector<int> joints;       ///< hinge or slide joints it moves
    /// True if the joints do not follow the actuator alone: a tendon, a
    /// coupling by equality, or a gear other than 1.
    bool coupled = false;
    /// Actuator mode: the drive has touched once every joint's subtree
    /// touches the object; per-joint mode: once the joint's own body does.
    bool subtree_touch = false;
  };

  /**
   * The joints actuator @p actuator of @p model moves: its joint, or the
   * joints of its fixed tendon, closed under active joint equality
   * constraints. An InputError naming the actuator and the fix for any
   * other transmission (site, slider-crank, spatial tendon).
   */
  std::vector<int> driven_joints(const MujocoModel &model, const int actuator);

  /**
   * The hand's drives: from @p closing_actuators ("name" or "-name" for a
   * target that closes when it decreases) if not empty, else from
   * @p finger_joints. @p weights: one per drive, or empty (1 each). Sets
   * @p unit to "rad" (hinges) or "m" (slide joints). InputErrors name the
   * MJCF element and the fix: unknown names, an actuator that is not a
   * position servo, a mix of hinge and slide joints, both lists given.
   */
  std::vector<HandDrive>
  hand_drives(const MujocoModel              &model,
              const std::vector<std::string> &finger_joints,
              const std::vector<std::string> &closing_actuators,
              const std::vector<double>      &weights,
              std::string                    &unit);

  /**
   * The generalized force (nv) of the contact constraints in @p d (after
   * mj_forward()): J^T f over the contact rows only.
   */
  std::vector<double> contact_generalized_force(const mjModel *m, mjData *d);

  /**
   * The hand under a constant load: from state @p start, the drives'
   * actuators set to @p controls, every contact switched off (the model's
   * flag comes back afterwards) and replaced by the constant generalized
   * force @p load (contact_generalized_force() at the equilibrium), MuJoCo
   * steps until the drives' joints are at rest (every speed under
   * @p velocity_tolerance after a window of @p window s) or @p max_time s
   * have passed. Returns the settled qpos (all of it); @p settled says
   * whether it came to rest. At the equilibrium targets the hand stays
   * where it is; a closure beyond them moves it as if the object gave way
   * at the equilibrium force: joints held by springs or loaded by the
   * object keep their balance, the free ones (and those coupled to them by
   * tendons, equalities and gears) take the closure.
   */
  std::vector<double> loaded_hand_qpos(mjModel                      *model,
                                       const mjData                 *start,
                                       const std::vector<double>    &load,
                                       const std::vector<HandDrive> &drives,
                                       const std::vector<double>    &controls,
                                       const double velocity_tolerance,
                                       const double window,
                                       const double max_time,
                                       bool        &settled);

  /**
   * The length of actuator @p a (joint or fixed-tendon transmission) at
   * the joint positions @p qpos: gear x the joint's coordinate, or gear x
   * the sum of the tendon's coefficients times its joints' coordinates.
   * Unlike mjData::actuator_length it follows qpos right after mj_step().
   */
  double actuator_length(const mjModel *m, const mjtNum *qpos, const int a);

  /**
   * The closing actuators that the keyframe @p key of @p model commands:
   * every position servo but those in @p exclude (the base's pull) whose
   * target in the keyframe differs from its length at qpos0, as "name"
   * where the keyframe's target is larger and "-name" where it is smaller
   * (the closing sign). InputErrors: an unknown keyframe (the valid ones
   * listed), a keyframe that moves no actuator.
   */
  std::vector<std::string>
  keyframe_closing_actuators(const MujocoModel      &model,
                             const std::string      &key,
                             const std::vector<int> &exclude);

  /// Name of actuator @p a with its closing sign ("-grip" or "grip").
  std::string drive_name(const mjModel *m, const HandDrive &drive);
} // namespace softgrasp

#endif
