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
                      Patterns::List(Patterns::Integer(1, 100000)),
                      "Elements per direction before refinement. Unit: 1.");
    prm.declare_entry("Grading",
                      per_direction<dim>("1"),
                      Patterns::List(Patterns::Double(0)),
                      "Per direction, the size ratio of neighbouring "
                      "elements from the lower to the upper corner: 1 is "
                      "uniform, > 1 grows towards the upper corner, < 1 "
                      "refines towards it (e.g. near a contact). With a "
                      "fine zone: the size ratio of neighbouring elements "
                      "away from the zone (>= 1). Unit: 1.");
    prm.declare_entry(
        "Fine zone",
        "",
        Patterns::Anything(),
        "Empty: none. Otherwise two corners 'x0, y0[, z0]; x1, y1[, z1]' of "
        "a box inside the block filled with uniform elements, "
        "'Subdivisions' of them per direction; outside it the elements grow "
        "by 'Grading' per element towards the block's faces, as many as "
        "fill it (a uniform fine zone under a contact followed by "
        "geometric growth). A direction in which the zone spans the block "
        "is uniform. Unit: m.");
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
    const std::string zone_text = prm.get("Fine zone");
    prm.leave_subsection();
    fine_zone.clear();
    if (!zone_text.empty())
    {
      const auto corners = Utilities::split_string_list(zone_text, ';');
      if (corners.size() != 2)
        throw InputError("Parameter 'Mesh/Block/Fine zone' = '" + zone_text +
                         "' needs two corners separated by ';'. Fix: give "
                         "'x0, y0, z0; x1, y1, z1' (m), or leave it empty.");
      for (const auto &corner : corners)
        fine_zone.push_back(parse_point<dim>(corner, "Mesh/Block/Fine zone"));
    }
    for (const double g : grading)
      if (!(g > 0))
        throw InputError("Parameter 'Mesh/Block/Grading' must be positive. "
                         "Fix: give size ratios > 0 (1 is uniform).");
    for (unsigned int d = 0; d < dim; ++d)
      if (!(upper[d] > lower[d]))
        throw InputError("Parameter 'Mesh/Block/Upper corner' must exceed "
                         "'Lower corner' in every coordinate. Fix: swap or "
                         "correct the corners (m).");
    if (!fine_zone.empty())
      for (unsigned int d = 0; d < dim; ++d)
      {
        if (!(fine_zone[0][d] < fine_zone[1][d]) ||
            fine_zone[0][d] < lower[d] - 1e-12 * (upper[d] - lower[d]) ||
            fine_zone[1][d] > upper[d] + 1e-12 * (upper[d] - lower[d]))
          throw InputError("Parameter 'Mesh/Block/Fine zone': its corners "
                           "must lie inside the block, the first below the "
                           "second in every coordinate. Fix: give a box "
                           "inside 'Lower corner' and 'Upper corner' (m).");
        if (grading[d] < 1)
          throw InputError("Parameter 'Mesh/Block/Grading' is below 1 with a "
                           "fine zone; there it is the growth away from the "
                           "zone. Fix: give ratios >= 1 (e.g. 1.3).");
      }
  }

  template <int dim>
  std::vector<double> BlockMesh<dim>::divisions(const unsigned int d) const
  {
    if (fine_zone.empty())
      return geometric_division(
          lower[d], upper[d], subdivisions[d], grading[d]);
    return zoned_division(lower[d],
                          upper[d],
                          fine_zone[0][d],
                          fine_zone[1][d],
                          subdivisions[d],
                          grading[d]);
  }

  template <int dim> double BlockMesh<dim>::n_coarse_cells() const
  {
    double n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= divisions(d).size() - 1;
    return n;
  }

  template <int dim>
  void
  BlockMesh<dim>::create_coarse_mesh(Triangulation<dim> &triangulation) const
  {
    std::vector<std::vector<double>> steps(dim);
    for (unsigned int d = 0; d < dim; ++d)
    {
      const auto x = divisions(d);
      for (unsigned int i = 0; i + 1 < x.size(); ++i)
        steps[d].push_back(x[i + 1] - x[i]);
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
