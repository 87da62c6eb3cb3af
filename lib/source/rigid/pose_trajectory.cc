#include <algorithm>
#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/pose_trajectory.h>
#include <sstream>

namespace softgrasp
{
  PoseTrajectory::PoseTrajectory(const Pose &pose)
      : sample_times{0.0}
      , samples{pose}
  {
  }

  PoseTrajectory::PoseTrajectory(const std::vector<double> &times,
                                 const std::vector<Pose>   &poses,
                                 const std::string         &source)
      : sample_times(times)
      , samples(poses)
  {
    auto fail = [&](const std::size_t i, const std::string &what)
    {
      std::ostringstream message;
      message << "The pose trajectory from " << source << " is invalid at "
              << "sample " << i << ": " << what << ". Fix: " << source
              << " must give strictly increasing finite times (s), finite "
                 "positions (m) and non-zero unit quaternions (w, x, y, z).";
      throw InputError(message.str());
    };
    if (times.empty())
      fail(0, "there are no samples");
    if (times.size() != poses.size())
      fail(std::min(times.size(), poses.size()),
           std::to_string(times.size()) + " times but " +
               std::to_string(poses.size()) + " poses");
    for (std::size_t i = 0; i < times.size(); ++i)
    {
      if (!std::isfinite(times[i]))
        fail(i, "the time is not finite");
      if (i > 0 && !(times[i] > times[i - 1]))
        fail(i, "the time does not increase");
      if (!samples[i].position.allFinite())
        fail(i, "the position is not finite");
      const double norm = samples[i].orientation.coeffs().norm();
      if (!std::isfinite(norm))
        fail(i, "the quaternion is not finite");
      if (norm < 1e-12)
        fail(i, "the quaternion is zero");
      samples[i].orientation.normalize();
    }
  }

  Pose PoseTrajectory::pose(const double time) const
  {
    if (time <= sample_times.front())
      return samples.front();
    if (time >= sample_times.back())
      return samples.back();
    const auto upper =
        std::upper_bound(sample_times.begin(), sample_times.end(), time);
    const std::size_t i = (upper - sample_times.begin()) - 1;
    const double      s =
        (time - sample_times[i]) / (sample_times[i + 1] - sample_times[i]);
    Pose p;
    p.position = (1 - s) * samples[i].position + s * samples[i + 1].position;
    // Eigen's slerp takes the shorter arc
    p.orientation = samples[i].orientation.slerp(s, samples[i + 1].orientation);
    return p;
  }

  const std::vector<double> &PoseTrajectory::times() const
  {
    return sample_times;
  }
} // namespace softgrasp
