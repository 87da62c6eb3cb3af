#ifndef softgrasp_mujoco_grasp_parameters_h
#define softgrasp_mujoco_grasp_parameters_h

#include <Eigen/Geometry>
#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The "Rigid environment" subsection: the MuJoCo scene, the hand's
   * placement, how it closes to the equilibrium grasp, and the indentation
   * and pull phases recorded after it. SI units: m, s, rad, N.
   */
  struct GraspParameters
  {
    static void declare_parameters(dealii::ParameterHandler &prm);
    /// Relative file names are taken relative to @p base_directory.
    void parse_parameters(dealii::ParameterHandler &prm,
                          const std::string        &base_directory);

    std::string              scene_file;       ///< MJCF
    std::string              object_body;      ///< the grasped body
    std::string              base_body;        ///< the hand's base body
    Eigen::Vector3d          base_position;    ///< m, world
    Eigen::Quaterniond       base_orientation; ///< w, x, y, z
    std::vector<std::string> finger_joints; ///< hinge or slide, with actuators
    /// Position actuators that close the hand ("-name": closes as its
    /// target decreases); if given, 'finger_joints' must be empty.
    std::vector<std::string> closing_actuators;
    /// A <keyframe> of the scene whose ctrl is the closed hand: its
    /// actuators (and their signs) close the hand; empty: not used.
    std::string              closing_keyframe;
    std::vector<std::string> contact_links; ///< geoms touching at equilibrium
    double                   closing_speed = 0.5; ///< rad/s (m/s: slide joints)
    double                   grip = 0.1; ///< rad (m) beyond first touch
    double                   velocity_tolerance = 1e-3; ///< m/s and rad/s
    double force_tolerance = 1e-3; ///< relative change per window
    double settle_window   = 0.05; ///< s
    double maximum_time    = 10;   ///< s of simulated closing
    double sample_interval = 0.01; ///< s between recorded samples

    struct Indentation
    {
      double extra_angle = 0.2; ///< rad (m) added to every finger joint
      /// Per closing actuator (or finger joint), the fraction of extra_angle
      /// it closes (1 each if empty); also how the grip levels raise the
      /// actuator targets.
      std::vector<double> joint_weights;
      unsigned int        samples     = 10; ///< steps of the closure
      double              duration    = 1;  ///< s, pseudo-time of the phase
      double              settle_time = 1; ///< s of MuJoCo time per sample, max
    } indentation;

    struct Pull
    {
      std::string     slide_joint = "pull";
      Eigen::Vector3d axis        = Eigen::Vector3d::UnitX(); ///< world
      double          distance    = 0; ///< m; 0: no pull phase
      double          duration    = 1; ///< s of MuJoCo time
      unsigned int    samples     = 10;
    } pull;
  };
} // namespace softgrasp

#endif
