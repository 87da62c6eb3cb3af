#include <cmath>
#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/parameter_reader.h>
#include <sstream>

namespace softgrasp
{
  namespace
  {
    double parse_number(const std::string &text, const std::string &path)
    {
      const std::string trimmed  = dealii::Utilities::trim(text);
      std::size_t       consumed = 0;
      double            value    = 0;
      try
      {
        value = std::stod(trimmed, &consumed);
      }
      catch (const std::exception &)
      {
        consumed = 0;
      }
      if (trimmed.empty() || consumed != trimmed.size() ||
          !std::isfinite(value))
        throw InputError("Parameter '" + path + "' has the value '" + trimmed +
                         "', which is not a finite number. Fix: set it to a "
                         "number such as 1e3.");
      return value;
    }
  } // namespace

  CheckedSection::CheckedSection(const dealii::ParameterHandler &prm,
                                 std::string                     path)
      : prm(prm)
      , path(std::move(path))
  {
  }

  void CheckedSection::declare_number(dealii::ParameterHandler &prm,
                                      const std::string        &name,
                                      const std::string        &documentation)
  {
    prm.declare_entry(name, "", dealii::Patterns::Anything(), documentation);
  }

  std::string CheckedSection::path_of(const std::string &name) const
  {
    return path.empty() ? name : path + "/" + name;
  }

  bool CheckedSection::is_set(const std::string &name) const
  {
    return !dealii::Utilities::trim(prm.get(name)).empty();
  }

  double CheckedSection::get_number(const std::string &name) const
  {
    if (!is_set(name))
      throw InputError("Parameter '" + path_of(name) +
                       "' is not set. Fix: add 'set " + name +
                       " = <value>' to subsection '" + path +
                       "' of the parameter file.");
    return parse_number(prm.get(name), path_of(name));
  }

  double CheckedSection::get_positive(const std::string &name,
                                      const std::string &unit,
                                      const bool         allow_zero) const
  {
    const double value = get_number(name);
    if (value < 0 || (!allow_zero && value == 0))
    {
      std::ostringstream msg;
      msg << "Parameter '" << path_of(name) << "' is " << value
          << (unit.empty() ? "" : " " + unit) << ", but it must be "
          << (allow_zero ? "zero or positive, range [0, inf)"
                         : "positive, range (0, inf)")
          << (unit.empty() ? "" : " " + unit)
          << ". Fix: give its magnitude in SI units.";
      throw InputError(msg.str());
    }
    return value;
  }

  double CheckedSection::get_in_range(const std::string &name,
                                      const double       lower,
                                      const double       upper,
                                      const bool         closed_upper,
                                      const std::string &unit) const
  {
    const double value = get_number(name);
    if (value < lower || value > upper || (!closed_upper && value == upper))
    {
      std::ostringstream msg;
      msg << "Parameter '" << path_of(name) << "' is " << value
          << ", outside its allowed range [" << lower << ", " << upper
          << (closed_upper ? "]" : ")") << (unit.empty() ? "" : " " + unit)
          << ". Fix: choose a value in that range.";
      throw InputError(msg.str());
    }
    return value;
  }

  std::vector<double>
  CheckedSection::get_number_list(const std::string &name) const
  {
    if (!is_set(name))
      throw InputError("Parameter '" + path_of(name) +
                       "' is not set. Fix: give a comma-separated list of "
                       "numbers.");
    std::vector<double> values;
    for (const auto &item :
         dealii::Utilities::split_string_list(prm.get(name), ','))
      values.push_back(parse_number(item, path_of(name)));
    return values;
  }

  std::vector<std::string> entries_changed_from_default(
      dealii::ParameterHandler                              &prm,
      const std::function<void(dealii::ParameterHandler &)> &declare)
  {
    dealii::ParameterHandler defaults;
    declare(defaults);
    std::vector<std::string> changed;
    for (const auto &[path, default_value] : ParameterReader::flatten(defaults))
    {
      const auto parts = dealii::Utilities::split_string_list(path, '/');
      for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        prm.enter_subsection(parts[i]);
      const std::string value = dealii::Utilities::trim(prm.get(parts.back()));
      for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        prm.leave_subsection();
      if (value != default_value)
        changed.push_back(path);
    }
    return changed;
  }
} // namespace softgrasp
