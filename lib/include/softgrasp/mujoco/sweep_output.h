#ifndef softgrasp_mujoco_sweep_output_h
#define softgrasp_mujoco_sweep_output_h

#include <ostream>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/mujoco/grip_levels.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The rigid simulator's grip levels as tables:
   *  - @p summary_file: one row per level and link: the target and reached
   *    grip force and the closure of the level, then the link's normal,
   *    lateral and drag force at the end of the pull, their means over the
   *    second half of it and their maxima over it, its slip speed at the
   *    end and whether it slides;
   *  - @p pulls_file: every sample of every pull (level, time, slide, then
   *    per link normal, lateral, drag and slip speed).
   * Both written whole or not at all (AtomicFile). Units: N, m, s, rad.
   */
  void write_rigid_levels(const std::vector<RigidGripLevel> &levels,
                          const std::string                 &summary_file,
                          const std::string                 &pulls_file);

  /// One grip level's point of the sweep's figure (N): the grip force the
  /// level reached, and the grip link's normal and lateral force averaged
  /// over the second half of the pull (steady sliding or sticking) and the
  /// largest lateral force over the pull.
  struct SweepPoint
  {
    unsigned int level = 0;
    double grip_force = 0, normal_mean = 0, lateral_mean = 0, lateral_max = 0;
    double friction_mean = 0; ///< finite elements: friction-only part
  };

  /// The grip link's points of @p levels (one per level).
  std::vector<SweepPoint>
  grip_link_points(const std::vector<RigidGripLevel> &levels,
                   const std::string                 &grip_geom);

  /// The grip link's points of the finite element levels that were pulled
  /// (means over the second half of the pull).
  std::vector<SweepPoint> grip_link_points(const std::vector<FeGripLevel> &fe,
                                           const std::string &grip_label);

  /**
   * The finite element levels as tables: @p summary_file, one row per level
   * and link (target and reached grip force, closure time, whether pulled,
   * the link's normal, lateral, friction-only and nodal normal force
   * (LinkForceHistory::nodal_normal) at the end of the pull and their means
   * over its second half, its closed and sliding nodes at the end, the
   * mean fraction of its closed nodes that slide over the second half and
   * whether that is above one half: the link slides); @p pulls_file, every
   * record of every pull. Units: N, s.
   */
  void write_fe_levels(const std::vector<FeGripLevel> &levels,
                       const std::string              &summary_file,
                       const std::string              &pulls_file);

  /**
   * The sweep's figure (PNG, as the paper's fig. 10) in @p directory:
   * lateral against normal force on the grip link, the rigid simulator's
   * levels as one line and the finite element levels as another, points
   * coloured by level, with the line mu N; a second panel splits the
   * finite element lateral force into its friction-only part and the rest
   * (pressure of the tissue against the link) per level. Data in
   * <base>_figure.dat, the script <base>_figure.gnuplot.
   */
  void write_sweep_figure(const std::vector<SweepPoint> &rigid,
                          const std::vector<SweepPoint> &fe,
                          const double                   friction,
                          const std::string             &grip_link,
                          const std::string             &directory,
                          const std::string             &base,
                          std::ostream                  &log);
  /**
   * What the rigid stage of the sweep leaves for its later stages (the
   * finite element levels, a collect run): the grip forces of the levels,
   * MuJoCo's friction coefficient and the grip link's points, with the
   * settings that produced them (a changed setting means the rigid stage
   * runs again).
   */
  struct RigidSweepRecord
  {
    std::string             settings;     ///< text of the inputs
    double                  friction = 0; ///< MuJoCo's largest geom mu
    std::vector<double>     targets;      ///< N, one per level
    std::vector<SweepPoint> points;       ///< the grip link, per level
  };

  /// Write @p record to @p filename (HDF5, whole or not at all).
  void write_rigid_record(const RigidSweepRecord &record,
                          const std::string      &filename);

  /// The record written by write_rigid_record(); an InputError naming the
  /// file and the fix if it is damaged.
  RigidSweepRecord read_rigid_record(const std::string &filename);
} // namespace softgrasp

#endif
