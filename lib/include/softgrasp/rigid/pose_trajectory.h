#ifndef softgrasp_rigid_pose_trajectory_h
#define softgrasp_rigid_pose_trajectory_h

#include <softgrasp/rigid/pose.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A rigid body's motion: poses at increasing times (s), interpolated
   * linearly in position and spherically-linearly (slerp, shortest arc) in
   * orientation; constant before the first and after the last sample.
   *
   * Construction validates the samples: times strictly increasing and
   * finite, positions finite, quaternions finite and non-zero (they are
   * normalised); a violation is an InputError naming @p source and the
   * sample index.
   */
  class PoseTrajectory
  {
  public:
    /// A body at rest at @p pose.
    explicit PoseTrajectory(const Pose &pose = Pose());

    PoseTrajectory(const std::vector<double> &times,
                   const std::vector<Pose>   &poses,
                   const std::string         &source);

    /// The pose at time @p time (s).
    Pose pose(const double time) const;

    const std::vector<double> &times() const;

  private:
    std::vector<double> sample_times;
    std::vector<Pose>   samples;
  };
} // namespace softgrasp

#endif
