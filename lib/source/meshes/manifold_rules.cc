#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>
#include <limits>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/manifold_rules.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// "a b c" -> ("a", "b c"), both trimmed.
    std::pair<std::string, std::string> first_word(const std::string &text)
    {
      const std::string trimmed = Utilities::trim(text);
      const auto        space   = trimmed.find_first_of(" \t");
      if (space == std::string::npos)
        return {trimmed, ""};
      return {trimmed.substr(0, space), Utilities::trim(trimmed.substr(space))};
    }

    std::string ids_of(const std::set<unsigned int> &ids)
    {
      std::string out;
      for (const auto id : ids)
        out += (out.empty() ? "" : ", ") + std::to_string(id);
      return out.empty() ? "none" : out;
    }

    const char *grammar =
        " Fix: write rules as 'boundary <id>: sphere <centre>', 'boundary "
        "<id>: cylinder <axis> through <point>' or 'material <id>: "
        "transfinite' (also sphere or cylinder), separated by ';'; points "
        "and directions as comma-separated coordinates in m.";
  } // namespace

  namespace
  {
    /**
     * The id @p text of a rule on a boundary (@p boundary) or a material:
     * a whole number within deal.II's
     * range of boundary (material) ids, 0 to 2^32 - 2 (the largest value
     * marks interior faces, or no material); anything else would wrap
     * around to another id.
     */
    unsigned int parse_id(const std::string &text,
                          const bool         boundary,
                          const std::string &problem)
    {
      const unsigned long long largest =
          boundary ? numbers::internal_face_boundary_id - 1ull
                   : numbers::invalid_material_id - 1ull;
      const std::string trimmed = Utilities::trim(text);
      const bool        digits =
          !trimmed.empty() && trimmed.size() <= 12 &&
          trimmed.find_first_not_of("0123456789") == std::string::npos;
      if (!digits || std::stoull(trimmed) > largest)
        throw InputError(problem + "has the id '" + trimmed +
                         "', which is not a whole number from 0 to " +
                         std::to_string(largest) + " (deal.II's " +
                         (boundary ? "boundary" : "material") +
                         " ids). Fix: give the id that the mesh file "
                         "assigns." +
                         grammar);
      return static_cast<unsigned int>(std::stoull(trimmed));
    }
  } // namespace

  template <int dim>
  ManifoldRules<dim>::ManifoldRules(const std::string &text,
                                    const std::string &path)
      : path(path)
  {
    for (const std::string &entry : Utilities::split_string_list(text, ';'))
    {
      const auto colon             = entry.find(':');
      const auto [target, id_text] = first_word(
          colon == std::string::npos ? entry : entry.substr(0, colon));
      const std::string problem = "Parameter '" + path + "': the rule '" +
                                  Utilities::trim(entry) + "' ";
      Rule rule;
      if (colon == std::string::npos ||
          (target != "boundary" && target != "material"))
        throw InputError(problem +
                         "does not start with 'boundary <id>:' or "
                         "'material <id>:'." +
                         grammar);
      rule.target = target == "boundary" ? Rule::Target::boundary
                                         : Rule::Target::material;
      rule.id =
          parse_id(id_text, rule.target == Rule::Target::boundary, problem);
      const auto [kind, arguments] = first_word(entry.substr(colon + 1));
      if (kind == "sphere")
      {
        rule.kind  = Rule::Kind::sphere;
        rule.point = parse_point<dim>(arguments, path);
      }
      else if (kind == "cylinder")
      {
        if (dim != 3)
          throw InputError(problem + "asks for a cylinder in 2D. Fix: use "
                                     "'sphere <centre>' (a circle).");
        const auto through = arguments.find("through");
        if (through == std::string::npos)
          throw InputError(problem + "has no 'through <point>'." + grammar);
        rule.kind  = Rule::Kind::cylinder;
        rule.axis  = parse_point<dim>(arguments.substr(0, through), path);
        rule.point = parse_point<dim>(arguments.substr(through + 7), path);
        if (!(rule.axis.norm() > 0))
          throw InputError(problem + "has a zero axis direction." + grammar);
        rule.axis /= rule.axis.norm();
      }
      else if (kind == "transfinite")
      {
        if (rule.target != Rule::Target::material)
          throw InputError(problem + "puts 'transfinite' on a boundary; it "
                                     "is a volume manifold. Fix: use "
                                     "'material <id>: transfinite'.");
        if (!arguments.empty())
          throw InputError(problem +
                           "gives 'transfinite' arguments; it "
                           "takes none." +
                           grammar);
        rule.kind = Rule::Kind::transfinite;
      }
      else
        throw InputError(problem + "has the unknown kind '" + kind +
                         "'. Fix: use sphere, cylinder or transfinite.");
      for (unsigned int k = 0; k < rules.size(); ++k)
        if (rules[k].target == rule.target && rules[k].id == rule.id)
          throw InputError("Parameter '" + path + "': the rules '" + texts[k] +
                           "' and '" + Utilities::trim(entry) + "' both give " +
                           target + " id " + std::to_string(rule.id) +
                           " a manifold. Fix: keep one of them.");
      rules.push_back(rule);
      texts.push_back(Utilities::trim(entry));
    }
  }

  template <int dim>
  void ManifoldRules<dim>::set_manifold_ids(Triangulation<dim> &tria) const
  {
    std::set<unsigned int> boundary_ids, material_ids;
    for (const auto &cell : tria.active_cell_iterators())
    {
      material_ids.insert(cell->material_id());
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          boundary_ids.insert(face->boundary_id());
    }
    std::set<unsigned int> named_boundaries;
    for (const Rule &rule : rules)
    {
      const bool  boundary = rule.target == Rule::Target::boundary;
      const auto &present  = boundary ? boundary_ids : material_ids;
      if (present.count(rule.id) == 0)
        throw InputError("Parameter '" + path + "' gives " +
                         (boundary ? "boundary" : "material") + " id " +
                         std::to_string(rule.id) +
                         " a manifold, but the mesh has no such id (it has " +
                         ids_of(present) + "). Fix: use the mesh's ids.");
      if (boundary)
        named_boundaries.insert(rule.id);
    }
    for (unsigned int k = 0; k < rules.size(); ++k)
      if (rules[k].target == Rule::Target::boundary &&
          rules[k].kind != Rule::Kind::transfinite)
        check_fit(tria, k);
      else if (rules[k].kind != Rule::Kind::transfinite)
        check_cells_fit(tria, k);
    for (unsigned int k = 0; k < rules.size(); ++k)
      if (rules[k].target == Rule::Target::material)
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->material_id() == rules[k].id)
          {
            cell->set_all_manifold_ids(k);
            if (rules[k].kind == Rule::Kind::transfinite)
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() &&
                    named_boundaries.count(face->boundary_id()) == 0)
                  face->set_manifold_id(numbers::flat_manifold_id);
          }
    for (unsigned int k = 0; k < rules.size(); ++k)
      if (rules[k].target == Rule::Target::boundary)
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == rules[k].id)
              face->set_all_manifold_ids(k);
  }

  template <int dim>
  void ManifoldRules<dim>::check_fit(const Triangulation<dim> &tria,
                                     const unsigned int        k) const
  {
    const Rule &rule   = rules[k];
    const auto  radius = [&rule](const Point<dim> &x)
    { return rule.from_centre(x).norm(); };
    double worst = 0, worst_size = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == rule.id)
        {
          double lo = std::numeric_limits<double>::max(), hi = 0;
          for (const unsigned int v : face->vertex_indices())
          {
            lo = std::min(lo, radius(face->vertex(v)));
            hi = std::max(hi, radius(face->vertex(v)));
          }
          const double size = face->diameter();
          if ((hi - lo) / 2 > 0.01 * size &&
              (hi - lo) / 2 / size > worst / std::max(worst_size, 1e-300))
            worst = (hi - lo) / 2, worst_size = size;
        }
    if (worst > 0)
    {
      std::ostringstream message;
      message << "Parameter '" << path << "': the rule '" << texts[k]
              << "' does not fit the mesh: a face of boundary id " << rule.id
              << " has vertices " << worst << " m from the "
              << (rule.kind == Rule::Kind::sphere ? "sphere" : "cylinder")
              << " through them (the face is " << worst_size
              << " m across; allowed: 1 % of that). Fix: give the "
              << (rule.kind == Rule::Kind::sphere ? "centre" : "axis")
              << " in the mesh file's coordinates times 'Scale' (m), or the "
                 "id of the curved surface.";
      throw InputError(message.str());
    }
  }

  template <int dim>
  void ManifoldRules<dim>::check_cells_fit(const Triangulation<dim> &tria,
                                           const unsigned int        k) const
  {
    const Rule &rule        = rules[k];
    const auto  from_centre = [&rule](const Point<dim> &x)
    { return rule.from_centre(x); };
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() == rule.id)
        for (const unsigned int l : cell->line_indices())
        {
          const Point<dim>     a  = cell->line(l)->vertex(0);
          const Point<dim>     b  = cell->line(l)->vertex(1);
          const Tensor<1, dim> da = from_centre(a), db = from_centre(b);
          const double         length = (b - a).norm();
          const double         ra = da.norm(), rb = db.norm();
          // off one sphere (cylinder) / off the ray from the centre (axis)
          // through a, of b
          const double tangential = std::abs(ra - rb);
          const double radial     = ra > 0 && da * db > 0
                                        ? (db - (db * da) / (ra * ra) * da).norm()
                                        : length;
          const double off        = std::min(tangential, radial);
          if (off <= 0.01 * length)
            continue;
          std::ostringstream message;
          message << "Parameter '" << path << "': the rule '" << texts[k]
                  << "' does not fit the mesh: a cell of material id "
                  << rule.id << " has an edge from (" << a << ") to (" << b
                  << ") m that neither lies on one "
                  << (rule.kind == Rule::Kind::sphere ? "sphere" : "cylinder")
                  << " about the "
                  << (rule.kind == Rule::Kind::sphere ? "centre" : "axis")
                  << " nor points to it (" << off << " m off, on an edge "
                  << length << " m long; allowed: 1 % of that). Fix: give the "
                  << (rule.kind == Rule::Kind::sphere ? "centre" : "axis")
                  << " in the mesh file's coordinates times 'Scale' (m); "
                     "for cells of another shape, or cells that hold the "
                  << (rule.kind == Rule::Kind::sphere ? "centre" : "axis")
                  << ", use 'material " << rule.id << ": transfinite'.";
          throw InputError(message.str());
        }
  }

  template <int dim>
  void ManifoldRules<dim>::attach(Triangulation<dim>   &tria,
                                  const Placement<dim> &placement) const
  {
    // The geometric manifolds first: a transfinite one reads them.
    for (unsigned int k = 0; k < rules.size(); ++k)
    {
      const Rule &rule = rules[k];
      if (rule.kind == Rule::Kind::sphere)
        tria.set_manifold(k, SphericalManifold<dim>(placement(rule.point)));
      else if (rule.kind == Rule::Kind::cylinder)
      {
        if constexpr (dim == 3)
          tria.set_manifold(k,
                            CylindricalManifold<3>(placement.rotate(rule.axis),
                                                   placement(rule.point)));
      }
    }
    for (unsigned int k = 0; k < rules.size(); ++k)
      if (rules[k].kind == Rule::Kind::transfinite)
      {
        TransfiniteInterpolationManifold<dim> blend;
        blend.initialize(tria);
        tria.set_manifold(k, blend);
      }
  }

  template class ManifoldRules<2>;
  template class ManifoldRules<3>;
} // namespace softgrasp
