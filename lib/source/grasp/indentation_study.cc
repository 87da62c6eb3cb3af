#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/grasp/grasp_pictures.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  void IndentationStudy::declare_parameters(ParameterHandler &prm)
  {
    GraspStudyParameters::declare_parameters(prm);
  }

  IndentationStudy::IndentationStudy(MPI_Comm comm, ParameterHandler &prm)
      : comm(comm)
      , solver_inputs(SolverInputs<3>::parse(prm))
  {
    parameters.parse_parameters(prm);
  }

  std::string
  IndentationStudy::kinematics_file(const std::string &directory) const
  {
    const std::string &name = parameters.kinematics_file;
    if (!name.empty() && name[0] == '/')
      return name;
    return (std::filesystem::path(directory) / name).string();
  }

  const IndentationStudy::Summary &IndentationStudy::summary() const
  {
    return result;
  }

  const HistoryWriter &IndentationStudy::link_table() const
  {
    return table;
  }

  const std::vector<LinkForceHistory> &IndentationStudy::link_forces() const
  {
    return fe_links;
  }

  std::string IndentationStudy::rigid_scene(const std::string &scene_file,
                                            const std::string &) const
  {
    return scene_file;
  }

  void IndentationStudy::place_tissue(SolverInputs<3>    &inputs,
                                      const Placement<3> &placement)
  {
    inputs.mesh.placement = placement;
    for (const auto id : inputs.materials.material_ids())
      inputs.materials.set(id,
                           inputs.materials.get(id).placed(
                               placement.rotation, placement.translation));
  }

  void IndentationStudy::set_up_tissue(SolverInputs<3> &inputs,
                                       const Pose      &object) const
  {
    Placement<3> placement;
    for (unsigned int d = 0; d < 3; ++d)
      placement.translation[d] = object.position[d];
    if (parameters.placement == GraspStudyParameters::Placement::pose)
    {
      const Eigen::Matrix3d R = object.orientation.toRotationMatrix();
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          placement.rotation[i][j] = R(i, j);
    }
    place_tissue(inputs, placement);
  }

  void IndentationStudy::postprocess(const Simulation<3> &,
                                     const KinematicsData &)
  {
  }

  void IndentationStudy::assess_injury(const Simulation<3> &solver)
  {
    const auto  &records = solver.contact_force_history();
    const double time    = records.empty() ? 0 : records.back().time;
    injury_assessment.compute(solver.system(),
                              solver.materials(),
                              solver.contact(),
                              solver.contact_output(),
                              solver.rigid_bodies(),
                              time,
                              parameters.injury);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const auto       &output = solver.parameters().output;
    const std::string base   = output.directory + "/" + output.base_name;
    injury_assessment.write_csv(base + "_injury.csv",
                                base + "_skin_pressure.csv");
    injury_assessment.print(std::cout);
  }

  namespace
  {
    std::string join(const std::vector<std::string> &items)
    {
      std::string out;
      for (const auto &item : items)
        out += (out.empty() ? "" : ", ") + item;
      return out;
    }

    /// The placement as text, for the checkpoint's resume settings.
    std::string describe(const Placement<3> &p)
    {
      std::ostringstream out;
      out << std::setprecision(17) << p.rotation << " | " << p.translation;
      return out.str();
    }
  } // namespace

  SolverInputs<3> IndentationStudy::inputs_for(const KinematicsData &cut) const
  {
    SolverInputs<3> inputs             = solver_inputs;
    inputs.solver.time.end_time        = cut.time.back() - cut.time.front();
    inputs.bodies                      = rigid_bodies_from(cut);
    const KinematicsData::Body *object = nullptr;
    for (const auto &body : cut.bodies)
      if (body.name == parameters.object_body)
        object = &body;
    if (object == nullptr)
      throw InputError("'Indentation study/Object body' = '" +
                       parameters.object_body +
                       "' is not a body of the kinematics file. Fix: name "
                       "the grasped object's body.");
    set_up_tissue(inputs, object->poses.front());
    inputs.add_resume_setting("Study/Placement",
                              describe(inputs.mesh.placement));
    return inputs;
  }

  std::pair<unsigned int, unsigned int>
  IndentationStudy::link_index(const RigidBodySet &bodies,
                               const std::string  &label,
                               const std::string  &entry)
  {
    std::vector<std::string> labels;
    for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
      {
        if (bodies.geom_label(b, g) == label)
          return {b, g};
        labels.push_back(bodies.geom_label(b, g));
      }
    throw InputError("'" + entry + "' = '" + label +
                     "' is not a link of the kinematics file. Fix: use one "
                     "of: " +
                     join(labels) + ".");
  }

  void IndentationStudy::run(const KinematicsData &kinematics)
  {
    const auto &first = kinematics.phase(parameters.phases.front());
    const auto &last  = kinematics.phase(parameters.phases.back());
    for (const auto &name : parameters.phases)
      kinematics.phase(name); // each must exist
    const auto cut = kinematics.slice(first.start_time, last.end_time);
    extra_angle    = 0;
    for (const auto &p : kinematics.phases)
      if (p.name == "indentation")
      {
        extra_angle  = p.amount;
        closure_unit = p.unit;
      }

    // The study's typed settings of the solver.
    SolverInputs<3> inputs      = inputs_for(cut);
    inputs.solver.time.end_time = last.end_time - first.start_time;
    inputs.add_resume_setting("Study/Phases", join(parameters.phases));
    std::pair<unsigned int, unsigned int> target;
    if (!parameters.target_link.empty())
      target = link_index(inputs.bodies,
                          parameters.target_link,
                          "Indentation study/Target link");

    const auto solver_pointer = Simulation<3>::create(comm, inputs);
    auto      &solver         = *solver_pointer;
    if (parameters.target_force > 0)
    {
      const auto [b, g] = target;
      solver.set_stop_criterion(
          [&solver, b = b, g = g, this]()
          {
            const auto &latest = solver.contact_force_history().back();
            return latest.forces[b][g].normal_force() >=
                   parameters.target_force;
          });
    }
    solver.run();
    fe_links = link_force_histories(solver.rigid_bodies(),
                                    solver.contact_force_history());
    summarise(solver, cut);
    write_link_table(solver, cut);
    assess_injury(solver);
    postprocess(solver, cut);
  }
} // namespace softgrasp
