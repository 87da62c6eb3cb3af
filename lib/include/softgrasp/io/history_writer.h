#ifndef softgrasp_io_history_writer_h
#define softgrasp_io_history_writer_h

#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A per-run table of per-step scalars written as CSV (one header line,
   * one row per converged step). The whole file is rewritten atomically
   * after every row, so it is always complete and a restarted run continues
   * it without duplicate rows.
   */
  class HistoryWriter
  {
  public:
    explicit HistoryWriter(std::string filename = "");

    void set_columns(const std::vector<std::string> &names);
    void add_row(const std::vector<double> &values);

    /// Write the CSV file (call on one MPI rank only).
    void write() const;

    /// Value of column @p name in row @p row; throws if there is none.
    double value(const std::size_t row, const std::string &name) const;

    std::string                      filename;
    std::vector<std::string>         columns;
    std::vector<std::vector<double>> rows;
  };
} // namespace softgrasp

#endif
