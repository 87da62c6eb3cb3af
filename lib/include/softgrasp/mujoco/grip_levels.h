#ifndef softgrasp_mujoco_grip_levels_h
#define softgrasp_mujoco_grip_levels_h

#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * How the rigid simulator runs the grasp-and-pull at grip levels
   * (GraspSimulation::grip_levels()). A level is a normal force on one
   * link (the paper takes the thumb's proximal link). SI units.
   */
  struct GripLevelSettings
  {
    std::string  grip_link; ///< geom name of the link that sets a level
    unsigned int levels        = 13;   ///< evenly spaced from lowest to highest
    double       lowest_force  = 0;    ///< N on the grip link; 0: equilibrium
    double       highest_force = 40;   ///< N on the grip link
    double       pull_distance = 0.02; ///< m the hand base moves along the axis
    double       pull_speed    = 0.02; ///< m/s of the slide actuator's target
    /// N/m: the slide servo's gain during the pulls (a robot arm carrying
    /// the hand holds its path); its joint is then critically damped.
    double       pull_stiffness  = 1e5;
    unsigned int samples         = 40;   ///< records over one pull
    double       settle_time     = 2;    ///< s of MuJoCo time per closure tried
    double       force_tolerance = 0.01; ///< relative miss of a level's force
    double       maximum_closure = 0.6;  ///< rad beyond the equilibrium targets
    /// A link slides when its mean tangential speed relative to the object
    /// over the second half of the pull exceeds this fraction of the speed.
    double slide_fraction = 0.1;
  };

  /// The grip forces (N) of @p settings' levels, lowest first, given the
  /// equilibrium's grip force @p equilibrium (N).
  std::vector<double> grip_level_forces(const GripLevelSettings &settings,
                                        const double             equilibrium);

  /// One link's forces over a pull (N; m/s for the slip speed).
  struct RigidLinkPull
  {
    std::string         body, geom;
    std::vector<double> normal;  ///< |sum (n n^T) f|, N
    std::vector<double> lateral; ///< |sum (I - n n^T) f|, N
    /// The force on the link against the pull: -f . axis (N).
    std::vector<double> drag;
    /// Force-weighted mean tangential speed of the link's contact points
    /// relative to the object (m/s).
    std::vector<double> slip_speed;
    /// Means over every time step of the second half of the pull (N, m/s).
    double normal_mean = 0, lateral_mean = 0, drag_mean = 0, slip_mean = 0;
    bool   slides = false; ///< slip_mean > slide_fraction x pull speed
  };

  /// The rigid simulator's answer at one grip level.
  struct RigidGripLevel
  {
    double       target_force  = 0; ///< N
    double       reached_force = 0; ///< N on the grip link, settled
    double       closure  = 0;     ///< rad added to every finger joint's target
    bool         matched  = false; ///< reached within the tolerance
    unsigned int trials   = 0;     ///< closures simulated to find it
    double       friction = 0; ///< MuJoCo's sliding friction of the grip link
    std::vector<double>        time;  ///< s since the start of the pull
    std::vector<double>        slide; ///< m the base moved along the axis
    std::vector<RigidLinkPull> links; ///< every hand geom
  };
} // namespace softgrasp

#endif
