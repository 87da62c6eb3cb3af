#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/io/hdf5_record.h>
#include <softgrasp/rigid/pose_trajectory.h>
#include <softgrasp/solvers/simulation.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// The first entry of @p now that @p before had otherwise ("'path' is
    /// 'x', was 'y'"), or "" if the two are alike.
    std::string changed_setting(const std::string &before,
                                const std::string &now)
    {
      if (before == now)
        return "";
      std::map<std::string, std::string> old;
      std::istringstream                 a(before), b(now);
      const auto                         split = [](const std::string &line)
      {
        const auto at = line.find(" = ");
        return std::make_pair(line.substr(0, at),
                              at == std::string::npos ? ""
                                                      : line.substr(at + 3));
      };
      for (std::string line; std::getline(a, line);)
        old.insert(split(line));
      for (std::string line; std::getline(b, line);)
      {
        const auto [name, value] = split(line);
        const auto it            = old.find(name);
        if (it == old.end())
          return "'" + name + "' is new";
        if (it->second != value)
          return "'" + name + "' is '" + value + "', was '" + it->second + "'";
      }
      return "an entry was removed";
    }

    /// The named time series of @p link that a record stores (but force).
    template <typename Link> auto series(Link &link)
    {
      return std::vector<std::pair<std::string, decltype(&link.time)>>{
          {"time", &link.time},
          {"normal", &link.normal},
          {"lateral", &link.lateral},
          {"friction", &link.friction},
          {"nodal_normal", &link.nodal_normal},
          {"closed_nodes", &link.closed},
          {"slipping_nodes", &link.slipping}};
    }

    Pose inverse(const Pose &p)
    {
      const Eigen::Quaterniond q = p.orientation.conjugate();
      return {-(q * p.position), q};
    }

    /// Copy the checkpoint of @p from into @p to (rank 0), replacing one
    /// there; all ranks wait for it.
    void copy_checkpoint(MPI_Comm           comm,
                         const std::string &from,
                         const std::string &to)
    {
      std::string error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        namespace fs = std::filesystem;
        std::error_code code;
        fs::create_directories(to, code);
        fs::remove_all(to + "/checkpoint", code);
        fs::copy(from + "/checkpoint",
                 to + "/checkpoint",
                 fs::copy_options::recursive,
                 code);
        if (code)
          error = "Cannot copy the checkpoint of '" + from + "' to '" + to +
                  "' (" + code.message() +
                  "). Fix: free disk space or choose a writable 'Output/"
                  "Directory'.";
      }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw InputError(error);
    }
  } // namespace

  KinematicsData pull_from(const KinematicsData &closing,
                           const KinematicsData &pull,
                           const double          t)
  {
    KinematicsData result = closing;
    result.time.clear();
    result.link_forces.clear(); // MuJoCo's forces belong to other states
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < closing.time.size(); ++i)
      if (closing.time[i] < t - 1e-12)
        kept.push_back(i);
    for (const auto i : kept)
      result.time.push_back(closing.time[i]);
    result.time.push_back(t);
    for (std::size_t j = 1; j < pull.time.size(); ++j)
      result.time.push_back(t + pull.time[j] - pull.time.front());

    for (std::size_t b = 0; b < closing.bodies.size(); ++b)
    {
      const auto &source = closing.bodies[b];
      auto       &body   = result.bodies[b];
      body.poses.clear();
      for (const auto i : kept)
        body.poses.push_back(source.poses[i]);
      const Pose at_t = PoseTrajectory(closing.time,
                                       source.poses,
                                       "kinematics body '" + source.name + "'")
                            .pose(t);
      body.poses.push_back(at_t);
      const auto &moved = pull.bodies[b];
      if (moved.name != source.name)
        throw InputError("The kinematics' pull phase lists body '" +
                         moved.name + "' where the indentation has '" +
                         source.name + "'. Fix: record both in one file.");
      const Pose start = inverse(moved.poses.front());
      for (std::size_t j = 1; j < moved.poses.size(); ++j)
        body.poses.push_back(moved.poses[j] * start * at_t);
    }
    // The joints hold the level's closure (the slide moves as recorded).
    for (std::size_t k = 0; k < result.joints.size(); ++k)
    {
      auto       &joint = result.joints[k];
      const auto &src   = closing.joints[k];
      joint.angle.clear();
      joint.target.clear();
      for (const auto i : kept)
      {
        joint.angle.push_back(src.angle[i]);
        joint.target.push_back(src.target[i]);
      }
      for (std::size_t j = 0; j < pull.time.size(); ++j)
      {
        const bool slide = j > 0 && pull.joints[k].angle.front() !=
                                        pull.joints[k].angle.back();
        joint.angle.push_back(slide
                                  ? pull.joints[k].angle[j]
                                  : src.angle[kept.empty() ? 0 : kept.back()]);
        joint.target.push_back(joint.angle.back());
      }
    }
    const double end = result.time.back();
    result.phases    = {
           {"indentation", 0, t, 0},
           {"pull", t, end, pull.phases.empty() ? 0 : pull.phases.back().amount}};
    return result;
  }

  PullSweepStudy::PullSweepStudy(MPI_Comm comm, ParameterHandler &prm)
      : comm(comm)
      , arm_study(comm, prm)
      , output(arm_study.inputs().solver.output.directory)
  {
    for (const auto &[name, value] : ParameterReader::flatten(prm))
      if (name.rfind("Output/", 0) != 0)
        settings += name + " = " + value + "\n";
  }

  std::string PullSweepStudy::level_directory(const unsigned int k) const
  {
    std::ostringstream name;
    name << output << "/level_" << std::setw(2) << std::setfill('0') << k;
    return name.str();
  }

  std::string PullSweepStudy::record_file(const unsigned int k) const
  {
    return level_directory(k) + "/level.h5";
  }

  std::vector<FeGripLevel>
  PullSweepStudy::recorded_levels(const std::vector<double> &forces) const
  {
    // Every rank reads the records (all need the levels' times).
    std::vector<FeGripLevel> levels;
    for (std::size_t k = 0; k < forces.size(); ++k)
    {
      const std::string file = record_file(k + 1);
      if (!std::filesystem::exists(file))
        break;
      levels.push_back(read_grip_level(file));
      const std::string change =
          changed_setting(levels.back().settings, settings);
      if (!change.empty())
        throw InputError("Level " + std::to_string(k + 1) + " in '" + file +
                         "' was computed with other settings: " + change +
                         ". Fix: start afresh in another 'Output/Directory', "
                         "or delete '" +
                         output + "/fe_closing' and the level_* directories.");
      const double recorded = levels.back().target_force;
      if (std::abs(recorded - forces[k]) > 1e-9 * forces[k])
        throw InputError(
            "Level " + std::to_string(k + 1) + " in '" + file +
            "' was closed to " + std::to_string(recorded) +
            " N; this sweep asks for " + std::to_string(forces[k]) +
            " N (its levels or the rigid stage changed). Fix: start afresh "
            "in another 'Output/Directory', or delete '" +
            output + "/fe_closing' and the level_* directories.");
    }
    return levels;
  }

  void PullSweepStudy::record(const FeGripLevel &level,
                              const unsigned int k) const
  {
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
      {
        std::filesystem::create_directories(level_directory(k));
        write_grip_level(level, record_file(k));
      }
      catch (const std::exception &e)
      {
        error = e.what();
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  std::vector<FeGripLevel>
  PullSweepStudy::close_to_levels(const KinematicsData      &kinematics,
                                  const std::string         &grip_link,
                                  const std::vector<double> &forces,
                                  const double               step)
  {
    std::vector<FeGripLevel> levels = recorded_levels(forces);
    if (levels.size() == forces.size())
      return levels;
    const auto     &phase  = kinematics.phase("indentation");
    const auto      cut    = kinematics.slice(phase.start_time, phase.end_time);
    SolverInputs<3> inputs = arm_study.inputs_for(cut);
    inputs.solver.time.end_time    = phase.end_time - phase.start_time;
    inputs.solver.output.directory = output + "/fe_closing";
    inputs.add_resume_setting("Study/Sweep", "grasp-and-pull");
    if (step > 0)
    {
      inputs.solver.time.step_size = step;
      inputs.solver.time.minimum_step =
          std::min(step, inputs.solver.time.minimum_step);
    }
    const auto [b, g] = IndentationStudy::link_index(
        inputs.bodies, grip_link, "Grasp-and-pull sweep/Grip link");

    // A killed sweep goes on from the closing's latest checkpoint.
    bool started = false;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      started = std::filesystem::exists(output + "/fe_closing/checkpoint") ||
                std::filesystem::exists(output + "/fe_closing/checkpoint.old");
    started = Utilities::MPI::broadcast(comm, started, 0);
    for (std::size_t k = levels.size(); k < forces.size(); ++k)
    {
      FeGripLevel level;
      level.target_force = forces[k];
      level.settings     = settings;
      if (k > 0 &&
          (!levels[k - 1].reached || levels[k - 1].reached_force >= forces[k]))
      { // the state of the level below: it reaches this one too, or the
        // closure ended below both
        level.reached_force = levels[k - 1].reached_force;
        level.time          = levels[k - 1].time;
        level.reached       = levels[k - 1].reached;
      }
      else
      {
        inputs.solver.checkpoint.resume = started;
        auto solver                     = Simulation<3>::create(comm, inputs);
        solver->set_stop_criterion(
            [&solver, b = b, g = g, target = forces[k]]()
            {
              const auto &latest = solver->contact_force_history().back();
              return latest.forces[b][g].normal_force() >= target;
            });
        solver->run();
        started             = true;
        const auto &latest  = solver->contact_force_history().back();
        level.reached_force = latest.forces[b][g].normal_force();
        level.time          = latest.time;
        level.reached       = solver->stopped_by_criterion();
      }
      if (level.reached)
        copy_checkpoint(
            comm, inputs.solver.output.directory, level_directory(k + 1));
      record(level, k + 1);
      levels.push_back(level);
    }
    return levels;
  }

  void PullSweepStudy::pull(const KinematicsData &kinematics,
                            const unsigned int    k,
                            FeGripLevel          &level,
                            const double          friction)
  {
    const auto &indentation = kinematics.phase("indentation");
    const auto &pull_phase  = kinematics.phase("pull");
    const auto  closing =
        kinematics.slice(indentation.start_time, indentation.end_time);
    const auto motion =
        kinematics.slice(pull_phase.start_time, pull_phase.end_time);
    const KinematicsData path       = pull_from(closing, motion, level.time);
    SolverInputs<3>      inputs     = arm_study.inputs_for(path);
    inputs.solver.output.directory  = level_directory(k);
    inputs.solver.checkpoint.resume = true;
    inputs.add_resume_setting("Study/Sweep", "grasp-and-pull");
    if (friction >= 0) // the resume settings keep the closing's
      inputs.contact.friction_coefficient = friction;
    auto solver = Simulation<3>::create(comm, inputs);
    try
    {
      solver->run();
      level.pulled = true;
    }
    catch (const SolverFailure &e)
    {
      level.failure = e.what();
    }
    const auto check  = arm_study.final_state_check(*solver);
    level.balance     = check.balance;
    level.penetration = check.penetration;
    level.links       = link_force_histories(solver->rigid_bodies(),
                                       solver->contact_force_history());
    // Keep the pull's records only (time from the level's start).
    for (auto &link : level.links)
      link = link.since(level.time);
    record(level, k);
  }

  void write_grip_level(const FeGripLevel &level, const std::string &filename)
  {
    Hdf5Record::write(filename,
                      [&](Hdf5Record::Group &file)
                      {
                        file.attribute("schema",
                                       std::string("softgrasp grip level"));
                        file.attribute("settings", level.settings);
                        file.attribute("target_force", level.target_force);
                        file.attribute("reached_force", level.reached_force);
                        file.attribute("time", level.time);
                        file.attribute("reached", int(level.reached));
                        file.attribute("pulled", int(level.pulled));
                        // HDF5 refuses empty strings: a failure is stored with
                        // a prefix
                        file.attribute("failure", "failure: " + level.failure);
                        file.attribute("balance", level.balance);
                        file.attribute("penetration", level.penetration);
                        file.attribute("links", int(level.links.size()));
                        for (std::size_t i = 0; i < level.links.size(); ++i)
                        {
                          const auto &link = level.links[i];
                          auto group = file.group("link_" + std::to_string(i));
                          group.attribute("name", link.link);
                          std::vector<double> force;
                          for (const auto &f : link.force)
                            force.insert(force.end(), {f[0], f[1], f[2]});
                          group.vector("force", force);
                          for (const auto &[name, values] : series(link))
                            group.vector(name, *values);
                        }
                      });
  }

  FeGripLevel read_grip_level(const std::string &filename)
  {
    FeGripLevel level;
    Hdf5Record::read(
        filename,
        "delete it (and its level's directory) to compute the level again",
        [&](const Hdf5Record::Reader &file)
        {
          const auto number = [&](const std::string &name)
          { return file.number_attribute("", name); };
          if (file.string_attribute("", "schema") != "softgrasp grip level")
            throw std::runtime_error("it is not a grip level record");
          level.settings      = file.string_attribute("", "settings");
          level.target_force  = number("target_force");
          level.reached_force = number("reached_force");
          level.time          = number("time");
          level.reached       = number("reached") != 0;
          level.pulled        = number("pulled") != 0;
          level.failure       = file.string_attribute("", "failure").substr(9);
          level.balance       = number("balance");
          level.penetration   = number("penetration");
          const int n         = static_cast<int>(number("links"));
          for (int i = 0; i < n; ++i)
          {
            const std::string group = "link_" + std::to_string(i);
            LinkForceHistory  link;
            link.link               = file.string_attribute(group, "name");
            link.time               = file.vector(group + "/time");
            const std::size_t m     = link.time.size();
            const auto        force = file.vector(group + "/force");
            if (force.size() != 3 * m)
              throw std::runtime_error("link " + link.link +
                                       " has datasets of different lengths");
            for (const auto &[name, values] : series(link))
            {
              *values = file.vector(group + "/" + name);
              if (values->size() != m)
                throw std::runtime_error("link " + link.link +
                                         " has datasets of different "
                                         "lengths");
            }
            for (std::size_t j = 0; j < m; ++j)
              link.force.emplace_back(
                  force[3 * j], force[3 * j + 1], force[3 * j + 2]);
            level.links.push_back(link);
          }
        });
    return level;
  }
} // namespace softgrasp
