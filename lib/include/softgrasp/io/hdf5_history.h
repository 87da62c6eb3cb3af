#ifndef softgrasp_io_hdf5_history_h
#define softgrasp_io_hdf5_history_h

#include <softgrasp/io/history_writer.h>
#include <string>

namespace softgrasp
{
  /**
   * Write a per-step table (a HistoryWriter's columns and rows) as an HDF5
   * file that analysis scripts can slice without parsing text. Columns named
   * "<path>:<quantity>" go to the group <path> (e.g. "finger/link"), other
   * columns to the root; the three columns "<quantity>_x, _y, _z" become one
   * (steps x 3) dataset "<quantity>", any other column a dataset of length
   * steps. The root has the attribute "schema" = @p schema. The file is
   * written under a temporary name and renamed. Every dataset carries its
   * unit in the attribute "unit" (forces per metre of thickness for
   * @p dim = 2). Call on one rank only.
   */
  void write_history_hdf5(const HistoryWriter &table,
                          const std::string   &filename,
                          const std::string   &schema,
                          const unsigned int   dim);
} // namespace softgrasp

#endif
