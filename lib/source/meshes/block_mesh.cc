#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/block_mesh.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// A list with one value for all directions or one per direction.
    template <int dim, typename T>
    std::vector<T> per_direction_list(const std::vector<T> &values,
                                      const std::string    &path)
    {
      if (values.size() != 1 && values.size() != dim)
        throw InputError("Parameter '" + path + "' has " +
                         std::to_string(values.size()) + " values; a " +
                         std::to_string(dim) + "D block needs " +
                         std::to_string(dim) +
                         " (one per direction) or 1 (the same in all). Fix: "
                         "give " +
                         std::to_string(dim) + " values.");
      return values.size() == dim ? values
                                  : std::vector<T>(dim, values.front());
    }
  } // namespace

  template <int dim>
  void BlockMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Block");
    prm.declare_entry("Lower corner",
                      per_direction<dim>("0"),
                      Patterns::Anything(),
                      "Corner with the smallest coordinates. Unit: m.");
    prm.declare_entry("Upper corner",
                      per_direction<dim>("0.01"),
                      Patterns::Anything(),
                      "Corner with the largest coordinates. Unit: m.");
    prm.declare_entry("Subdivisions",
                      per_direction<dim>("2"),
                      Patterns::List(Patterns::Integer(1)),
                      "Elements per direction before refinement. Unit: 1.");
    prm.declare_entry("Grading",
                      per_direction<dim>("1"),
                      Patterns::List(Patterns::Double(0)),
                      "Per direction, the size ratio of neighbouring "
                      "elements from the lower to the upper corner: 1 is "
                      "uniform, > 1 grows towards the upper corner, < 1 "
                      "refines towards it (e.g. near a contact). Unit: 1.");
    prm.leave_subsection();
  }

  template <int dim>
  void BlockMesh<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Block");
    lower =
        parse_point<dim>(prm.get("Lower corner"), "Mesh/Block/Lower corner");
    upper =
        parse_point<dim>(prm.get("Upper corner"), "Mesh/Block/Upper corner");
    std::vector<unsigned int> n;
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Subdivisions")))
      n.push_back(Utilities::string_to_int(s));
    subdivisions = per_direction_list<dim>(n, "Mesh/Block/Subdivisions");
    std::vector<double> ratios;
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Grading")))
      ratios.push_back(Utilities::string_to_double(s));
    grading = per_direction_list<dim>(ratios, "Mesh/Block/Grading");
    prm.leave_subsection();
    for (const double g : grading)
      if (!(g > 0))
        throw InputError("Parameter 'Mesh/Block/Grading' must be positive. "
                         "Fix: give size ratios > 0 (1 is uniform).");
    for (unsigned int d = 0; d < dim; ++d)
      if (!(upper[d] > lower[d]))
        throw InputError("Parameter 'Mesh/Block/Upper corner' must exceed "
                         "'Lower corner' in every coordinate. Fix: swap or "
                         "correct the corners (m).");
  }

  template <int dim>
  void
  BlockMesh<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    std::vector<std::vector<double>> steps(dim);
    for (unsigned int d = 0; d < dim; ++d)
    {
      double total = 0;
      for (unsigned int i = 0; i < subdivisions[d]; ++i)
        total += std::pow(grading[d], i);
      for (unsigned int i = 0; i < subdivisions[d]; ++i)
        steps[d].push_back((upper[d] - lower[d]) * std::pow(grading[d], i) /
                           total);
    }
    GridGenerator::subdivided_hyper_rectangle(
        triangulation, steps, lower, upper, true);
  }

  template class BlockMesh<2>;
  template class BlockMesh<3>;
} // namespace softgrasp

SOFTGRASP_REGISTER_MESH(softgrasp::BlockMesh,
                        block,
                        "block",
                        "an axis-parallel box of hexahedra, optionally graded")
