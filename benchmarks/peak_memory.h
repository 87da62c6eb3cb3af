// Peak resident memory of this process, shared by the benchmark programs.
#ifndef softgrasp_benchmarks_peak_memory_h
#define softgrasp_benchmarks_peak_memory_h

#include <fstream>
#include <string>

namespace
{
  /// VmHWM of /proc/self/status (MB); 0 where it is not available.
  inline double peak_memory_mb()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return std::stod(line.substr(6)) / 1024.0;
    return 0;
  }
} // namespace

#endif
