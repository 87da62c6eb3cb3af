#include <cmath>
#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/mesh_generator.h>

namespace softgrasp
{
  using namespace dealii;

  std::vector<double> geometric_division(const double       a,
                                         const double       b,
                                         const unsigned int n,
                                         const double       ratio)
  {
    double total = 0;
    for (unsigned int i = 0; i < n; ++i)
      total += std::pow(ratio, i);
    std::vector<double> x = {a};
    for (unsigned int i = 0; i < n; ++i)
      x.push_back(x.back() + (b - a) * std::pow(ratio, i) / total);
    x.back() = b;
    return x;
  }

  namespace
  {
    /// Cells of a geometric progression (first size @p h * @p g, ratio
    /// @p g) that fill @p distance.
    unsigned int
    cells_to_fill(const double distance, const double h, const double g)
    {
      unsigned int n   = 0;
      double       sum = 0, size = h;
      while (sum < distance * (1 - 1e-9) && n < 1000)
      {
        size *= g;
        sum += size;
        ++n;
      }
      return std::max(n, 1u);
    }
  } // namespace

  std::vector<double> zoned_division(const double       a,
                                     const double       b,
                                     const double       zone_begin,
                                     const double       zone_end,
                                     const unsigned int zone_cells,
                                     const double       growth)
  {
    const double        h   = (zone_end - zone_begin) / zone_cells;
    const double        tol = 1e-9 * (b - a);
    std::vector<double> x;
    if (zone_begin > a + tol)
    {
      const auto left = geometric_division(
          zone_begin, a, cells_to_fill(zone_begin - a, h, growth), growth);
      x.assign(left.rbegin(), left.rend());
      x.pop_back();
    }
    const auto zone = geometric_division(zone_begin, zone_end, zone_cells, 1);
    x.insert(x.end(), zone.begin(), zone.end());
    if (zone_end < b - tol)
    {
      const auto right = geometric_division(
          zone_end, b, cells_to_fill(b - zone_end, h, growth), growth);
      x.insert(x.end(), right.begin() + 1, right.end());
    }
    x.front() = a;
    x.back()  = b;
    return x;
  }

  template <int dim> std::string per_direction(const std::string &value)
  {
    return dim == 2 ? value + ", " + value
                    : value + ", " + value + ", " + value;
  }

  template <int dim>
  Point<dim> parse_point(const std::string &text, const std::string &path)
  {
    std::vector<double> values;
    try
    {
      values = Utilities::string_to_double(Utilities::split_string_list(text));
    }
    catch (...)
    {
    }
    if (values.size() != dim)
      throw InputError("Parameter '" + path + "' = '" + text + "' needs " +
                       std::to_string(dim) +
                       " comma-separated coordinates (m) in a " +
                       std::to_string(dim) +
                       "D problem. Fix: give one number per coordinate.");
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
    {
      if (!std::isfinite(values[d]))
        throw InputError("Parameter '" + path + "' = '" + text +
                         "' has a coordinate that is not a finite number. "
                         "Fix: give finite coordinates (m).");
      p[d] = values[d];
    }
    return p;
  }

  template std::string per_direction<2>(const std::string &);
  template std::string per_direction<3>(const std::string &);
  template Point<2>    parse_point<2>(const std::string &, const std::string &);
  template Point<3>    parse_point<3>(const std::string &, const std::string &);
} // namespace softgrasp
