#ifndef softgrasp_base_gnuplot_h
#define softgrasp_base_gnuplot_h

#include <ostream>
#include <string>

namespace softgrasp
{
  /**
   * Run the gnuplot script @p script (a file name) in @p directory to make
   * PNG pictures. Without gnuplot, or if it fails, a line on @p log says so
   * and the data files stay; returns true on success.
   */
  bool run_gnuplot(const std::string &directory,
                   const std::string &script,
                   std::ostream      &log);
} // namespace softgrasp

#endif
