#ifndef softgrasp_grasp_limb_scene_h
#define softgrasp_grasp_limb_scene_h

#include <deal.II/base/parameter_handler.h>
#include <softgrasp/grasp/limb_surface.h>
#include <softgrasp/rigid/pose.h>
#include <string>

namespace softgrasp
{
  /**
   * The rigid arm of a MuJoCo grasp scene, made from the finite element
   * limb's skin surface (LimbSurface), so that the two cannot disagree: its
   * geom is that surface (MuJoCo collides with its convex hull), its body
   * ("object") hangs from the shoulder on a damped ball joint with a restoring
   * stiffness, gravity on: the upper arm of a casualty lying on their back,
   * lifted clear of the ground and held by the shoulder for a grasp from
   * above (doc/studies.md).
   *
   * Frames: the arm body's origin is the shoulder end of the limb's axis;
   * the limb's axis (its own x) runs along the body's y axis, its own z
   * along the body's z (up), so the limb's frame sits at
   * limb_frame_in_body(). The body starts at (0, -L/2, 0) in the world:
   * the limb's centre at the world's origin.
   */
  struct LimbScene
  {
    double density            = 1050; ///< of the whole arm, kg/m^3
    double shoulder_damping   = 20;   ///< N m s/rad
    double shoulder_stiffness = 50;   ///< N m/rad
    /// false: the arm is held fixed (no shoulder joint), as the finite
    /// element humerus is, e.g. for a pull along the arm.
    bool         shoulder_joint = true;
    unsigned int facets         = 96; ///< around the skin surface

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);

    /// The pose of the limb's own frame in the arm body's frame, for a limb
    /// of @p length (m) along its axis.
    static Pose limb_frame_in_body(const double length);

    /**
     * Write <directory>/mujoco_arm_skin.stl (@p limb in the body frame;
     * the arm's mass is the density times its volume) and
     * <directory>/mujoco_arm_scene.xml, which includes
     * @p hand_file (the hand MJCF) and holds the arm; returns the scene's
     * path.
     */
    std::string write(const LimbSurface &limb,
                      const std::string &hand_file,
                      const std::string &directory) const;
  };
} // namespace softgrasp

#endif
