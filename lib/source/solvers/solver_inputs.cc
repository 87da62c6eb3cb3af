#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/solvers/solver_inputs.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    template <typename T> T parsed(ParameterHandler &prm)
    {
      T object;
      object.parse_parameters(prm);
      return object;
    }

    /// The entries a resume must not change: the dimension, the element,
    /// the mesh, the materials, contact, rigid bodies and the integrator
    /// (which decides the fields a checkpoint holds).
    std::vector<std::pair<std::string, std::string>>
    settings_to_keep(const ParameterHandler &prm)
    {
      const std::vector<std::string>                   prefixes = {"Dimension",
                                                                   "Finite element/",
                                                                   "Mesh/",
                                                                   "Materials/",
                                                                   "Contact/",
                                                                   "Rigid bodies/",
                                                                   "Time/Integrator"};
      std::vector<std::pair<std::string, std::string>> kept;
      for (const auto &entry : ParameterReader::flatten(prm))
        for (const auto &prefix : prefixes)
          if (entry.first.rfind(prefix, 0) == 0)
          {
            kept.push_back(entry);
            break;
          }
      return kept;
    }
  } // namespace

  template <int dim>
  SolverInputs<dim> SolverInputs<dim>::parse(ParameterHandler &prm)
  {
    SolverInputs<dim> inputs;
    inputs.solver              = parsed<SolverParameters>(prm);
    inputs.mesh                = parsed<MeshFactory<dim>>(prm);
    inputs.materials           = parsed<MaterialLibrary>(prm);
    inputs.boundary_conditions = parsed<BoundaryConditions<dim>>(prm);
    inputs.contact             = parsed<ContactParameters>(prm);
    inputs.bodies              = parsed<RigidBodySet>(prm);
    inputs.resume_settings     = settings_to_keep(prm);
    return inputs;
  }

  template <int dim>
  void SolverInputs<dim>::add_resume_setting(const std::string &name,
                                             const std::string &value)
  {
    resume_settings.emplace_back(name, value);
  }

  template struct SolverInputs<2>;
  template struct SolverInputs<3>;
} // namespace softgrasp
