#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/io/history_writer.h>
#include <sstream>
#include <stdexcept>

namespace softgrasp
{
  HistoryWriter::HistoryWriter(std::string filename)
      : filename(std::move(filename))
  {
  }

  void HistoryWriter::set_columns(const std::vector<std::string> &names)
  {
    columns = names;
  }

  void HistoryWriter::add_row(const std::vector<double> &values)
  {
    if (values.size() != columns.size())
      throw std::logic_error("HistoryWriter: row has " +
                             std::to_string(values.size()) + " values for " +
                             std::to_string(columns.size()) + " columns");
    rows.push_back(values);
  }

  void HistoryWriter::write() const
  {
    std::ostringstream out;
    for (std::size_t c = 0; c < columns.size(); ++c)
      out << (c ? "," : "") << columns[c];
    out << "\n" << std::setprecision(12);
    for (const auto &row : rows)
    {
      for (std::size_t c = 0; c < row.size(); ++c)
        out << (c ? "," : "") << row[c];
      out << "\n";
    }
    AtomicFile::write(filename, out.str());
  }

  double HistoryWriter::value(const std::size_t  row,
                              const std::string &name) const
  {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name)
        return rows.at(row).at(c);
    throw std::out_of_range("history has no column '" + name + "'");
  }
} // namespace softgrasp
