#include <cmath>
#include <cstdio>
#include <softgrasp/base/progress_reporter.h>

namespace softgrasp
{
  void ProgressReporter::start(const double start_time, const double end_time)
  {
    wall_start = std::chrono::steady_clock::now();
    t_start    = start_time;
    t_end      = end_time;
  }

  double ProgressReporter::elapsed() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         wall_start)
        .count();
  }

  double ProgressReporter::eta(const double time) const
  {
    if (!(time > t_start))
      return -1;
    return elapsed() / (time - t_start) * std::max(0.0, t_end - time);
  }

  std::string ProgressReporter::format_duration(const double seconds)
  {
    if (seconds < 0)
      return "?";
    char       buffer[64];
    const long s = std::lround(seconds);
    if (s < 60)
      std::snprintf(buffer, sizeof(buffer), "%.1fs", seconds);
    else if (s < 3600)
      std::snprintf(buffer, sizeof(buffer), "%ldm %02lds", s / 60, s % 60);
    else
      std::snprintf(
          buffer, sizeof(buffer), "%ldh %02ldm", s / 3600, (s % 3600) / 60);
    return buffer;
  }
} // namespace softgrasp
