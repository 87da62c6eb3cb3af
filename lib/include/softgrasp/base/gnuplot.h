#ifndef softgrasp_base_gnuplot_h
#define softgrasp_base_gnuplot_h

#include <ostream>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Run the gnuplot script @p script (a file name) in @p directory to make
   * the PNG pictures @p pictures (names in @p directory). The script writes
   * each picture under AtomicFile::temporary_name(picture); a picture gets
   * its name only when gnuplot succeeded and the PNG is complete, so an
   * earlier picture is never replaced by a broken one. Without gnuplot, or
   * if it fails, a line on @p log says so and the data files stay; returns
   * true on success.
   */
  bool run_gnuplot(const std::string              &directory,
                   const std::string              &script,
                   const std::vector<std::string> &pictures,
                   std::ostream                   &log);
} // namespace softgrasp

#endif
