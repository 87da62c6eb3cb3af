#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/mechanics/boundary_conditions.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    const char *kinds[] = {"Dirichlet", "Traction", "Pressure"};

    std::vector<types::boundary_id> parse_ids(const std::string &text)
    {
      std::vector<types::boundary_id> ids;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        ids.push_back(
            static_cast<types::boundary_id>(Utilities::string_to_int(item)));
      return ids;
    }

    std::string subsection(const std::string &kind, const types::boundary_id id)
    {
      return kind + " boundary " + std::to_string(static_cast<unsigned>(id));
    }

    template <int dim> std::string variables()
    {
      return dim == 2 ? "x,y,t" : "x,y,z,t";
    }

    template <int dim>
    std::shared_ptr<FunctionParser<dim>>
    make_function(const std::string &expressions,
                  const unsigned int n_components,
                  const std::string &path,
                  const std::string &unit)
    {
      auto function = std::make_shared<FunctionParser<dim>>(n_components);
      try
      {
        function->initialize(variables<dim>(),
                             expressions,
                             {{"pi", numbers::PI}},
                             /*time_dependent=*/true);
        // muParser compiles lazily: evaluate once so that errors surface
        // now, not in the middle of a run.
        for (unsigned int c = 0; c < n_components; ++c)
          function->value(Point<dim>(), c);
      }
      catch (const ExceptionBase &e)
      {
        throw InputError(
            "Parameter '" + path + "' = '" + expressions +
            "' is not a valid expression list: it needs " +
            std::to_string(n_components) +
            " muParser expression(s) separated by ';' in the variables " +
            variables<dim>() + " (" + unit + "). Fix: correct the expression.");
      }
      return function;
    }
  } // namespace

  template <int dim>
  void BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Dirichlet boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundary ids with prescribed displacement; each has "
                      "a subsection 'Dirichlet boundary <id>'.");
    prm.declare_entry("Traction boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundary ids with a dead-load traction; each has a "
                      "subsection 'Traction boundary <id>'.");
    prm.declare_entry("Pressure boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundary ids with a follower pressure; each has a "
                      "subsection 'Pressure boundary <id>'.");
    prm.declare_entry("Gravity",
                      dim == 2 ? "0; 0" : "0; 0; 0",
                      Patterns::Anything(),
                      "Body acceleration, one expression per component in "
                      "x, y[, z] (m) and t (s), separated by ';'. Multiplied "
                      "by the reference density. Unit: m/s^2.");
    prm.leave_subsection();
  }

  template <int dim>
  void BoundaryConditions<dim>::add_passes(ParameterReader &reader)
  {
    reader.add_pass(
        [](ParameterHandler &prm)
        {
          prm.enter_subsection("Boundary conditions");
          for (const std::string kind : kinds)
            for (const auto id : parse_ids(prm.get(kind + " boundary ids")))
            {
              prm.enter_subsection(subsection(kind, id));
              if (kind == "Dirichlet")
              {
                prm.declare_entry(
                    "Components",
                    dim == 2 ? "x, y" : "x, y, z",
                    Patterns::MultipleSelection(dim == 2 ? "x|y" : "x|y|z"),
                    "Displacement components prescribed on this boundary.");
                prm.declare_entry("Displacement",
                                  dim == 2 ? "0; 0" : "0; 0; 0",
                                  Patterns::Anything(),
                                  "Prescribed displacement, one expression per "
                                  "component (all dim of them; unselected ones "
                                  "are ignored) in x, y[, z] (m) and t (s), "
                                  "separated by ';'. Unit: m.");
              }
              else if (kind == "Traction")
                prm.declare_entry("Traction",
                                  dim == 2 ? "0; 0" : "0; 0; 0",
                                  Patterns::Anything(),
                                  "Dead-load traction per unit reference area, "
                                  "one expression per component in x, y[, z] "
                                  "(m) and t (s). Unit: Pa.");
              else
                prm.declare_entry("Pressure",
                                  "0",
                                  Patterns::Anything(),
                                  "Follower pressure on the deformed surface "
                                  "(positive pushes inward), an expression in "
                                  "x, y[, z] (m) and t (s). Unit: Pa.");
              prm.leave_subsection();
            }
          prm.leave_subsection();
        });
  }

  template <int dim>
  void BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    dirichlet.clear();
    tractions.clear();
    pressures.clear();
    prm.enter_subsection("Boundary conditions");
    const std::string base = "Boundary conditions/";
    for (const auto id : parse_ids(prm.get("Dirichlet boundary ids")))
    {
      prm.enter_subsection(subsection("Dirichlet", id));
      std::vector<bool> mask(dim, false);
      for (const std::string &c :
           Utilities::split_string_list(prm.get("Components"), ','))
        mask[c[0] - 'x'] = true;
      dirichlet.push_back(
          {id,
           ComponentMask(mask),
           make_function<dim>(prm.get("Displacement"),
                              dim,
                              base + subsection("Dirichlet", id) +
                                  "/Displacement",
                              "m")});
      prm.leave_subsection();
    }
    for (const auto id : parse_ids(prm.get("Traction boundary ids")))
    {
      prm.enter_subsection(subsection("Traction", id));
      tractions.push_back(
          {id,
           make_function<dim>(prm.get("Traction"),
                              dim,
                              base + subsection("Traction", id) + "/Traction",
                              "Pa")});
      prm.leave_subsection();
    }
    for (const auto id : parse_ids(prm.get("Pressure boundary ids")))
    {
      prm.enter_subsection(subsection("Pressure", id));
      pressures.push_back(
          {id,
           make_function<dim>(prm.get("Pressure"),
                              1,
                              base + subsection("Pressure", id) + "/Pressure",
                              "Pa")});
      prm.leave_subsection();
    }
    const std::string g = prm.get("Gravity");
    body_acceleration   = make_function<dim>(g, dim, base + "Gravity", "m/s^2");
    gravity_is_zero     = true;
    for (const std::string &e : Utilities::split_string_list(g, ';'))
      if (Utilities::trim(e) != "0" && Utilities::trim(e) != "0.0")
        gravity_is_zero = false;
    prm.leave_subsection();
  }

  template <int dim> void BoundaryConditions<dim>::set_time(const double time)
  {
    for (auto &d : dirichlet)
      d.displacement->set_time(time);
    for (auto &t : tractions)
      t.traction->set_time(time);
    for (auto &p : pressures)
      p.pressure->set_time(time);
    if (body_acceleration)
      body_acceleration->set_time(time);
  }

  template <int dim>
  Tensor<1, dim> BoundaryConditions<dim>::gravity(const Point<dim> &X) const
  {
    Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g[d] = body_acceleration->value(X, d);
    return g;
  }

  template <int dim> bool BoundaryConditions<dim>::has_gravity() const
  {
    return !gravity_is_zero;
  }

  template <int dim> bool BoundaryConditions<dim>::has_follower_loads() const
  {
    return !pressures.empty();
  }

  template <int dim>
  std::vector<types::boundary_id>
  BoundaryConditions<dim>::reaction_boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const auto &d : dirichlet)
      ids.push_back(d.boundary_id);
    return ids;
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace softgrasp
