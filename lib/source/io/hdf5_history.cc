#include <deal.II/base/utilities.h>
#include <map>
#include <optional>
#include <softgrasp/io/hdf5_history.h>
#include <softgrasp/io/hdf5_record.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// The unit of a contact-history quantity, for the dataset attribute.
    std::string unit_of(const std::string &quantity, const unsigned int dim)
    {
      if (quantity == "M")
        return dim == 2 ? "N" : "N m"; // 2D: per metre of thickness
      if (quantity.rfind("F", 0) == 0 ||
          quantity.find("force") != std::string::npos)
        return dim == 2 ? "N/m" : "N";
      if (quantity == "area")
        return dim == 2 ? "m" : "m^2";
      if (quantity == "time")
        return "s";
      return "1";
    }
  } // namespace

  void write_history_hdf5(const HistoryWriter &table,
                          const std::string   &filename,
                          const std::string   &schema,
                          const unsigned int   dim)
  {
    // Group the columns: (group, quantity) -> column indices (1 or x,y,z).
    std::map<std::pair<std::string, std::string>, std::vector<unsigned int>>
                             datasets;
    std::vector<std::string> order_of_groups;
    for (unsigned int c = 0; c < table.columns.size(); ++c)
    {
      const std::string &name  = table.columns[c];
      const auto         colon = name.find(':');
      const std::string  group =
          colon == std::string::npos ? "" : name.substr(0, colon);
      std::string quantity =
          colon == std::string::npos ? name : name.substr(colon + 1);
      const std::size_t n = quantity.size();
      if (n > 2 && quantity[n - 2] == '_' &&
          (quantity[n - 1] == 'x' || quantity[n - 1] == 'y' ||
           quantity[n - 1] == 'z'))
        quantity = quantity.substr(0, n - 2);
      datasets[{group, quantity}].push_back(c);
    }

    Hdf5Record::write(
        filename,
        [&](Hdf5Record::Group &file)
        {
          file.attribute("schema", schema);
          const unsigned int steps = table.rows.size();
          for (const auto &[key, columns] : datasets)
          {
            std::vector<double> values;
            for (unsigned int r = 0; r < steps; ++r)
              for (const unsigned int c : columns)
                values.push_back(table.rows[r][c]);
            auto group = key.first.empty() ? std::optional<Hdf5Record::Group>()
                                           : file.group(key.first);
            (group ? *group : file)
                .dataset(key.second, values, steps, columns.size())
                .attribute("unit", unit_of(key.second, dim));
          }
        });
  }
} // namespace softgrasp
