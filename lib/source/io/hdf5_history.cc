#include <deal.II/base/hdf5.h>
#include <deal.II/lac/full_matrix.h>
#include <map>
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
        [&](HDF5::File &file)
        {
          file.set_attribute("schema", schema);
          std::map<std::string, HDF5::Group> groups;
          const auto group_of = [&](const std::string &path) -> HDF5::Group &
          {
            auto it = groups.find(path);
            if (it != groups.end())
              return it->second;
            // create the nested groups of "a/b" one level at a time
            HDF5::Group *parent = &file;
            std::string  so_far;
            for (const auto &part : Utilities::split_string_list(path, '/'))
            {
              so_far += (so_far.empty() ? "" : "/") + part;
              auto found = groups.find(so_far);
              if (found == groups.end())
                found =
                    groups.emplace(so_far, parent->create_group(part)).first;
              parent = &found->second;
            }
            return *parent;
          };
          const unsigned int steps = table.rows.size();
          for (const auto &[key, columns] : datasets)
          {
            HDF5::Group &group = key.first.empty() ? file : group_of(key.first);
            FullMatrix<double> values(steps, columns.size());
            for (unsigned int r = 0; r < steps; ++r)
              for (unsigned int k = 0; k < columns.size(); ++k)
                values(r, k) = table.rows[r][columns[k]];
            if (columns.size() == 1)
            {
              std::vector<double> column(steps);
              for (unsigned int r = 0; r < steps; ++r)
                column[r] = values(r, 0);
              auto dataset = group.create_dataset<double>(key.second, {steps});
              if (steps > 0)
                dataset.write(column);
              dataset.set_attribute("unit", unit_of(key.second, dim));
            }
            else
            {
              auto dataset = group.create_dataset<double>(
                  key.second,
                  {steps, static_cast<unsigned int>(columns.size())});
              if (steps > 0)
                dataset.write(values);
              dataset.set_attribute("unit", unit_of(key.second, dim));
            }
          }
        });
  }
} // namespace softgrasp
