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
      p[d] = values[d];
    return p;
  }

  template std::string per_direction<2>(const std::string &);
  template std::string per_direction<3>(const std::string &);
  template Point<2>    parse_point<2>(const std::string &, const std::string &);
  template Point<3>    parse_point<3>(const std::string &, const std::string &);
} // namespace softgrasp
