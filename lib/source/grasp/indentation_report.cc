#include <algorithm>
#include <iomanip>
#include <iostream>
#include <softgrasp/grasp/grasp_pictures.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/solvers/simulation.h>

namespace softgrasp
{
  using namespace dealii;

  void IndentationStudy::summarise(const Simulation<3>  &solver,
                                   const KinematicsData &cut)
  {
    const auto  &records  = solver.contact_force_history();
    const double t_end    = records.empty() ? 0 : records.back().time;
    const double duration = cut.time.back() - cut.time.front();
    result                = Summary();
    result.closure        = extra_angle * std::min(t_end / duration, 1.0);
    result.target_met     = solver.stopped_by_criterion();
    result.steps          = records.empty() ? 0 : records.size() - 1;
    const auto check      = final_state_check(solver);
    result.balance        = check.balance;
    result.penetration    = check.penetration;
  }

  IndentationStudy::StateCheck
  IndentationStudy::final_state_check(const Simulation<3> &solver) const
  {
    const auto &records = solver.contact_force_history();
    // Force balance on the body: the link forces against the supports.
    Eigen::Vector3d sum     = Eigen::Vector3d::Zero();
    double          largest = 0;
    if (!records.empty())
      for (const auto &body : records.back().forces)
        for (const auto &f : body)
        {
          sum += f.force;
          largest = std::max(largest, f.force.norm());
        }
    Eigen::Vector3d support = Eigen::Vector3d::Zero();
    for (const auto &[id, r] : solver.system().reactions())
      for (unsigned int d = 0; d < 3; ++d)
        support[d] += r[d];
    StateCheck check;
    check.balance  = (sum - support).norm() / std::max(largest, 1e-300);
    double deepest = 0;
    for (const auto &node : solver.contact()->nodes())
      deepest = std::max(deepest, -node.gap);
    check.penetration = Utilities::MPI::max(deepest, comm);
    return check;
  }

  namespace
  {
    /// MuJoCo's normal (or tangential) force on link @p h at time @p t,
    /// interpolated between the samples of @p cut (N).
    double rigid_force_at(const KinematicsData              &cut,
                          const KinematicsData::LinkHistory &h,
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
    }
  } // namespace

  std::pair<std::vector<const LinkForceHistory *>,
            std::vector<const KinematicsData::LinkHistory *>>
  IndentationStudy::touching_links(const KinematicsData &cut)
  {
    result.links.clear();
    std::vector<const LinkForceHistory *>            fe;
    std::vector<const KinematicsData::LinkHistory *> rigid;
    for (const auto &h : cut.link_forces)
    {
      const std::string label = h.body + "/" + h.geom;
      const auto        link =
          std::find_if(fe_links.begin(),
                       fe_links.end(),
                       [&](const auto &l) { return l.link == label; });
      double most = 0;
      for (const auto &f : h.force)
        most = std::max(most, f.norm());
      const double fe_most =
          link == fe_links.end() ? 0 : link->largest_normal();
      if (link != fe_links.end() && (fe_most > 0 || most > 0))
      {
        result.links.push_back(label);
        fe.push_back(&*link);
        rigid.push_back(&h);
      }
    }
    return {fe, rigid};
  }

  void IndentationStudy::print_links() const
  {
    std::cout << "\nIndentation: closure " << result.closure << " of "
              << extra_angle << " " << closure_unit << " in " << result.steps
              << " steps"
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

  void IndentationStudy::write_link_table(const Simulation<3>  &solver,
                                          const KinematicsData &cut)
  {
    const double duration            = cut.time.back() - cut.time.front();
    const auto [fe, rigid]           = touching_links(cut);
    std::vector<std::string> columns = {"step", "time", "closure"};
    for (const auto &l : result.links)
      for (const char *part : {"FE_normal",
                               "FE_lateral",
                               "FE_friction",
                               "MJ_normal",
                               "MJ_lateral"})
        columns.push_back(l + ":" + part);
    const auto &output = solver.parameters().output;
    table =
        HistoryWriter(output.directory + "/" + output.base_name + "_links.csv");
    table.set_columns(columns);

    result.normal_fe.assign(result.links.size(), 0);
    result.normal_rigid.assign(result.links.size(), 0);
    const auto &records = solver.contact_force_history();
    for (std::size_t row = 0; row < records.size(); ++row)
    {
      const double        t      = records[row].time;
      std::vector<double> values = {double(records[row].step),
                                    t,
                                    extra_angle * std::min(t / duration, 1.0)};
      for (std::size_t l = 0; l < result.links.size(); ++l)
      {
        result.normal_fe[l]    = fe[l]->normal[row];
        result.normal_rigid[l] = rigid_force_at(cut, *rigid[l], t, true);
        values.insert(values.end(),
                      {result.normal_fe[l],
                       fe[l]->lateral[row],
                       fe[l]->friction[row],
                       result.normal_rigid[l],
                       rigid_force_at(cut, *rigid[l], t, false)});
      }
      table.add_row(values);
    }
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      table.write();
      print_links();
    }
    if (parameters.pictures)
    {
      const double t_end = records.empty() ? 0 : records.back().time;
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
                         closure_unit,
                         output.directory,
                         output.base_name,
                         std::cout);
    }
  }
} // namespace softgrasp
