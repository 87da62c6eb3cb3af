#ifndef softgrasp_base_progress_reporter_h
#define softgrasp_base_progress_reporter_h

#include <chrono>
#include <ostream>
#include <string>

namespace softgrasp
{
  /**
   * One progress line per step of a long run: step, time, step size,
   * iterations, wall time and the estimated time left, extrapolated from the
   * wall time spent per unit of simulated time so far.
   */
  class ProgressReporter
  {
  public:
    /// Start timing a run that goes from @p start_time to @p end_time (s).
    void start(const double start_time, const double end_time);

    /// Wall time since start() (s).
    double elapsed() const;

    /// Estimated wall time left (s) at simulated time @p time; -1 unknown.
    double eta(const double time) const;

    /// "1m 05s"-style duration.
    static std::string format_duration(const double seconds);

  private:
    std::chrono::steady_clock::time_point wall_start;
    double                                t_start = 0, t_end = 1;
  };
} // namespace softgrasp

#endif
