#ifndef softgrasp_base_parameter_checks_h
#define softgrasp_base_parameter_checks_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <softgrasp/base/input_error.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /**
   * Range-checked reading of numbers from the current subsection of a
   * dealii::ParameterHandler. On violation it throws an InputError naming
   * the full parameter path (e.g. "Materials/Material 1/neo-Hookean/Shear
   * modulus"), the value found, the allowed range and the fix.
   *
   * Required numbers are declared with an empty default (see
   * declare_number()) so that "not set" is detected and reported.
   */
  class CheckedSection
  {
  public:
    /// @p prm must already be inside the subsection that @p path names.
    CheckedSection(const dealii::ParameterHandler &prm, std::string path);

    /// Declare a number entry with an empty default (set it or leave unset).
    static void declare_number(dealii::ParameterHandler &prm,
                               const std::string        &name,
                               const std::string        &documentation);

    /// Full path of entry @p name, for messages.
    std::string path_of(const std::string &name) const;

    /// True if the entry has a non-empty value.
    bool is_set(const std::string &name) const;

    /// A finite number; throws if unset or malformed.
    double get_number(const std::string &name) const;

    /// A number > 0 (or >= 0 if @p allow_zero); @p unit appears in messages.
    double get_positive(const std::string &name,
                        const std::string &unit,
                        const bool         allow_zero = false) const;

    /// A number in [lower, upper) or, if @p closed_upper, [lower, upper].
    double get_in_range(const std::string &name,
                        const double       lower,
                        const double       upper,
                        const bool         closed_upper,
                        const std::string &unit) const;

    /// A non-empty comma-separated list of finite numbers.
    std::vector<double> get_number_list(const std::string &name) const;

    const dealii::ParameterHandler &prm;
    const std::string               path;
  };

  /**
   * The entries that @p declare (a plugin's declare_parameters(), which
   * declares its own subsections) would declare and that @p prm, inside the
   * subsection where they are declared, holds with a value other than
   * their default: paths relative to that subsection ("File/Manifolds").
   * Used to refuse the settings of a plugin that is not chosen, which would
   * otherwise be ignored without a word.
   */
  std::vector<std::string> entries_changed_from_default(
      dealii::ParameterHandler                              &prm,
      const std::function<void(dealii::ParameterHandler &)> &declare);

  /// The choices of an enum's .prm spelling table @p table, "a|b|c", for
  /// a Patterns::Selection.
  template <typename Enum>
  std::string
  choice_pattern(const std::vector<std::pair<std::string, Enum>> &table)
  {
    std::string out;
    for (const auto &entry : table)
      out += (out.empty() ? "" : "|") + entry.first;
    return out;
  }

  /// The value @p name spells in @p table (Patterns::Selection has
  /// validated it; an InputError listing the choices otherwise).
  template <typename Enum>
  Enum lookup_choice(const std::vector<std::pair<std::string, Enum>> &table,
                     const std::string                               &name)
  {
    for (const auto &entry : table)
      if (entry.first == name)
        return entry.second;
    throw InputError("Unknown choice '" + name +
                     "'. Fix: use one of: " + choice_pattern(table) + ".");
  }
} // namespace softgrasp

#endif
