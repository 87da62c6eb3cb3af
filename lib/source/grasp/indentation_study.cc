#include <filesystem>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/grasp/grasp_pictures.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/mechanics/mechanics_solver.h>

namespace softgrasp
{
  using namespace dealii;

  void IndentationStudy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Indentation study");
    {
      prm.declare_entry("Kinematics file",
                        "kinematics.h5",
                        Patterns::FileName(),
                        "HDF5 kinematics file of the rigid-body simulator "
                        "(doc/kinematics_file.md), relative to "
                        "'Output/Directory'.");
      prm.declare_entry("Rigid stage",
                        "run",
                        Patterns::Selection("run|read"),
                        "run: simulate the grasp with MuJoCo first and write "
                        "the kinematics file; read: use the kinematics file "
                        "as it is (no MuJoCo needed).");
      prm.declare_entry("Object body",
                        "object",
                        Patterns::Anything(),
                        "Body of the grasped object in the kinematics file; "
                        "a generated ball mesh is centred at its position.");
      prm.declare_entry("Target link",
                        "",
                        Patterns::Anything(),
                        "Link (body/geom, e.g. thumb_proximal/"
                        "thumb_proximal_link) whose normal force ends the "
                        "run at 'Target normal force'; empty: none.");
      prm.declare_entry("Target normal force",
                        "0",
                        Patterns::Double(0),
                        "Normal force on the target link that ends the "
                        "indentation; 0: close by the whole recorded extra "
                        "joint angle. Unit: N.");
      prm.declare_entry("Pictures",
                        "true",
                        Patterns::Bool(),
                        "Write the PNG picture of the indented body and the "
                        "PNG force plot (needs gnuplot).");
    }
    prm.leave_subsection();
  }

  IndentationStudy::IndentationStudy(MPI_Comm comm, ParameterHandler &prm)
      : comm(comm)
      , prm(prm)
  {
    prm.enter_subsection("Indentation study");
    const CheckedSection section(prm, "Indentation study");
    file_name     = prm.get("Kinematics file");
    target_link   = Utilities::trim(prm.get("Target link"));
    target_force  = section.get_positive("Target normal force", "N", true);
    make_pictures = prm.get_bool("Pictures");
    run_rigid     = prm.get("Rigid stage") == "run";
    prm.leave_subsection();
    if (target_force > 0 && target_link.empty())
      throw InputError("'Indentation study/Target normal force' is set but "
                       "'Target link' is empty. Fix: name the link as "
                       "body/geom, or set the force to 0.");
  }

  std::string
  IndentationStudy::kinematics_file(const std::string &directory) const
  {
    if (!file_name.empty() && file_name[0] == '/')
      return file_name;
    return (std::filesystem::path(directory) / file_name).string();
  }

  const IndentationStudy::Summary &IndentationStudy::summary() const
  {
    return result;
  }

  const HistoryWriter &IndentationStudy::link_table() const
  {
    return table;
  }

  void IndentationStudy::run(const KinematicsData &kinematics)
  {
    const auto &phase = kinematics.phase("indentation");
    const auto  cut   = kinematics.slice(phase.start_time, phase.end_time);
    extra_angle       = phase.amount;

    // The study's settings of the solver's parameters.
    prm.enter_subsection("Time");
    prm.set("End time", phase.end_time - phase.start_time);
    prm.leave_subsection();
    prm.enter_subsection("Indentation study");
    const std::string object = prm.get("Object body");
    prm.leave_subsection();
    for (const auto &body : cut.bodies)
      if (body.name == object)
      {
        const auto &p = body.poses.front().position;
        prm.enter_subsection("Mesh");
        prm.enter_subsection("Ball");
        std::ostringstream center;
        center << std::setprecision(17) << p[0] << ", " << p[1] << ", " << p[2];
        prm.set("Center", center.str());
        prm.leave_subsection();
        prm.leave_subsection();
      }

    const auto solver_pointer       = MechanicsSolver<3>::create(comm, prm);
    auto      &solver               = *solver_pointer;
    solver.rigid_bodies()           = rigid_bodies_from(cut);
    const auto              &bodies = solver.rigid_bodies();
    std::vector<std::string> labels;
    for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
        labels.push_back(bodies.geom_label(b, g));
    if (!target_link.empty() &&
        std::find(labels.begin(), labels.end(), target_link) == labels.end())
    {
      std::string valid;
      for (const auto &l : labels)
        valid += (valid.empty() ? "" : ", ") + l;
      throw InputError("'Indentation study/Target link' = '" + target_link +
                       "' is not a link of the kinematics file. Fix: use one "
                       "of: " +
                       valid + ".");
    }
    if (target_force > 0)
      solver.set_stop_criterion(
          [&solver, this]()
          {
            const auto &history = solver.contact_history();
            return history.value(history.rows.size() - 1,
                                 target_link + ":normal_force") >= target_force;
          });
    solver.run();

    // Summary: closure, force balance on the body, penetration.
    const auto  &history  = solver.contact_history();
    const double t_end    = history.value(history.rows.size() - 1, "time");
    const double duration = phase.end_time - phase.start_time;
    result                = Summary();
    result.closure        = extra_angle * t_end / duration;
    result.target_met     = solver.stopped_by_criterion();
    result.steps          = history.rows.size() - 1;
    const auto forces   = solver.contact_output()->geom_forces(solver.system());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double          largest = 0;
    for (const auto &body : forces)
      for (const auto &f : body)
      {
        sum += f.force;
        largest = std::max(largest, f.force.norm());
      }
    Eigen::Vector3d support = Eigen::Vector3d::Zero();
    for (const auto &[id, r] : solver.system().reactions())
      for (unsigned int d = 0; d < 3; ++d)
        support[d] += r[d];
    result.balance = (sum - support).norm() / std::max(largest, 1e-300);
    double deepest = 0;
    for (const auto &node : solver.contact()->nodes())
      deepest = std::max(deepest, -node.gap);
    result.penetration = Utilities::MPI::max(deepest, comm);

    write_link_table(solver, cut);
    const auto &output = solver.parameters().output;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::cout << "\nIndentation: closure " << result.closure << " of "
                << extra_angle << " rad in " << result.steps << " steps"
                << (result.target_met ? " (target normal force reached)" : "")
                << ".\nForces on the links (N), finite elements | MuJoCo at "
                   "the same closure:\n";
      for (std::size_t l = 0; l < result.links.size(); ++l)
        std::cout << "  " << std::setw(40) << std::left << result.links[l]
                  << std::right << " normal " << std::setw(9)
                  << result.normal_fe[l] << " | " << std::setw(9)
                  << result.normal_rigid[l] << '\n';
      std::cout << "Force balance on the body: |sum of link forces - support "
                   "reaction| = "
                << result.balance << " x the largest link force.\n"
                << "Deepest penetration: " << result.penetration << " m.\n";
    }
    if (make_pictures)
    {
      write_grasp_picture(solver.system(),
                          cut,
                          t_end,
                          {1},
                          output.directory,
                          output.base_name,
                          std::cout);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        write_force_plot(output.base_name + "_links.csv",
                         result.links,
                         output.directory,
                         output.base_name,
                         std::cout);
    }
  }

  void IndentationStudy::write_link_table(const MechanicsSolver<3> &solver,
                                          const KinematicsData     &cut)
  {
    const auto  &history  = solver.contact_history();
    const double duration = cut.time.back() - cut.time.front();
    // Links: those that touch in either model.
    result.links.clear();
    for (const auto &h : cut.link_forces)
    {
      const std::string label = h.body + "/" + h.geom;
      double            fe = 0, rigid = 0;
      for (std::size_t row = 0; row < history.rows.size(); ++row)
        fe = std::max(fe, history.value(row, label + ":normal_force"));
      for (const auto &f : h.force)
        rigid = std::max(rigid, f.norm());
      if (fe > 0 || rigid > 0)
        result.links.push_back(label);
    }
    std::vector<std::string> columns = {"step", "time", "closure"};
    for (const auto &l : result.links)
      for (const char *part : {"FE_normal",
                               "FE_lateral",
                               "FE_friction",
                               "MJ_normal",
                               "MJ_lateral"})
        columns.push_back(l + ":" + part);
    table = HistoryWriter(solver.parameters().output.directory + "/" +
                          solver.parameters().output.base_name + "_links.csv");
    table.set_columns(columns);

    // MuJoCo's forces at time t, interpolated between the samples.
    const auto rigid_at = [&cut](const KinematicsData::LinkHistory &h,
                                 const double                       t,
                                 const bool                         normal)
    {
      const auto value = [&](const std::size_t i)
      {
        return normal ? h.normal_force[i].norm()
                      : (h.force[i] - h.normal_force[i]).norm();
      };
      std::size_t i = 0;
      while (i + 2 < cut.time.size() && cut.time[i + 1] < t)
        ++i;
      const double w = std::clamp(
          (t - cut.time[i]) / (cut.time[i + 1] - cut.time[i]), 0.0, 1.0);
      return (1 - w) * value(i) + w * value(i + 1);
    };
    result.normal_fe.assign(result.links.size(), 0);
    result.normal_rigid.assign(result.links.size(), 0);
    for (std::size_t row = 0; row < history.rows.size(); ++row)
    {
      const double        t      = history.value(row, "time");
      std::vector<double> values = {
          history.value(row, "step"), t, extra_angle * t / duration};
      for (std::size_t l = 0; l < result.links.size(); ++l)
      {
        const auto &label      = result.links[l];
        const auto  h          = std::find_if(cut.link_forces.begin(),
                                    cut.link_forces.end(),
                                    [&](const auto &x)
                                    { return x.body + "/" + x.geom == label; });
        result.normal_fe[l]    = history.value(row, label + ":normal_force");
        result.normal_rigid[l] = rigid_at(*h, t, true);
        values.insert(values.end(),
                      {result.normal_fe[l],
                       history.value(row, label + ":lateral_force"),
                       history.value(row, label + ":friction_force"),
                       result.normal_rigid[l],
                       rigid_at(*h, t, false)});
      }
      table.add_row(values);
    }
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      table.write();
  }
} // namespace softgrasp
