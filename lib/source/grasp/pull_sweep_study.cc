#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/file_checksum.h>
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
    /// Entries that do not change a recorded level's result: the time
    /// steps (they shape only what is still to compute; every record keeps
    /// the value it was computed with).
    bool numerical(const std::string &name)
    {
      return name == "Time/Time step" || name == "Time/Minimum time step" ||
             name == "Grasp-and-pull sweep/Closing time step";
    }

    /// The first entry of @p now that @p before had otherwise ("'path' is
    /// 'x', was 'y'"), or "" if the two are alike but for numerical()
    /// entries and those of sections not in the settings (Checkpoint).
    std::string changed_setting(const std::string &before,
                                const std::string &now)
    {
      if (before == now)
        return "";
      const auto entries = [](const std::string &text)
      {
        std::map<std::string, std::string> result;
        std::istringstream                 in(text);
        for (std::string line; std::getline(in, line);)
        {
          const auto at   = line.find(" = ");
          const auto name = line.substr(0, at);
          if (!numerical(name) && name.rfind("Checkpoint/", 0) != 0)
            result[name] = at == std::string::npos ? "" : line.substr(at + 3);
        }
        return result;
      };
      const auto old = entries(before), current = entries(now);
      for (const auto &[name, value] : current)
      {
        const auto it = old.find(name);
        if (it == old.end())
          return "'" + name + "' is new";
        if (it->second != value)
          return "'" + name + "' is '" + value + "', was '" + it->second + "'";
      }
      return old.size() == current.size() ? "" : "an entry was removed";
    }

    /// Remove @p path (a file or folder) on rank 0; all ranks wait.
    void remove_on_root(MPI_Comm comm, const std::string &path)
    {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code code;
        std::filesystem::remove_all(path, code);
      }
      MPI_Barrier(comm);
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
      if (name.rfind("Output/", 0) != 0 && name.rfind("Checkpoint/", 0) != 0)
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

  std::string PullSweepStudy::closing_file(const unsigned int k) const
  {
    return level_directory(k) + "/closing.h5";
  }

  std::string PullSweepStudy::closed_state_of(const unsigned int k) const
  {
    const std::string manifest =
        level_directory(k) + "/closed/checkpoint/manifest.txt";
    return std::filesystem::is_regular_file(manifest) ? file_checksum(manifest)
                                                      : "";
  }

  void PullSweepStudy::forget_level(const unsigned int k) const
  {
    for (const auto &file : {record_file(k), closing_file(k)})
      remove_on_root(comm, file);
    remove_on_root(comm, level_directory(k) + "/closed");
  }

  std::vector<std::optional<FeGripLevel>>
  PullSweepStudy::read_records(const std::vector<double> &forces,
                               std::ostream              *log) const
  {
    // Every rank reads the records (all need the levels' times).
    std::vector<std::optional<FeGripLevel>> records(forces.size());
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    for (unsigned int k = 1; k <= forces.size(); ++k)
    {
      // no closing record, no level (doc/studies.md: deleting closing.h5
      // computes the level again), whatever else is left of it
      if (!std::filesystem::exists(closing_file(k)))
      {
        if (log != nullptr && std::filesystem::exists(level_directory(k)))
          forget_level(k);
        continue;
      }
      const std::string file  = std::filesystem::exists(record_file(k))
                                    ? record_file(k)
                                    : closing_file(k);
      FeGripLevel       level = read_grip_level(file);
      const auto fix = ". Fix: start afresh in another 'Output/Directory', "
                       "or delete '" +
                       output + "/fe_closing' and the level_* directories.";
      const std::string change = changed_setting(level.settings, settings);
      if (!change.empty())
        throw InputError("Level " + std::to_string(k) + " in '" + file +
                         "' was computed with other settings: " + change + fix);
      if (std::abs(level.target_force - forces[k - 1]) > 1e-9 * forces[k - 1])
        throw InputError(
            "Level " + std::to_string(k) + " in '" + file + "' was closed to " +
            std::to_string(level.target_force) + " N; this sweep asks for " +
            std::to_string(forces[k - 1]) +
            " N (its levels or the rigid stage changed)" + fix);
      if (level.state_level == 0 || level.state_level > k)
        level.state_level = k;
      if (log != nullptr && level.reached && !level.finished() &&
          !level.closed_state.empty() &&
          closed_state_of(k) != level.closed_state)
      {
        if (root)
          *log << "Level " << k << ": its closed state '" << level_directory(k)
               << "/closed' is not the one its record '" << file
               << "' was closed to (its checksum differs: swapped with or "
                  "copied from another level, or changed); the level is "
                  "closed again.\n";
        forget_level(k);
        continue;
      }
      records[k - 1] = std::move(level);
    }
    return records;
  }

  std::vector<FeGripLevel>
  PullSweepStudy::recorded_levels(const std::vector<double> &forces) const
  {
    std::vector<FeGripLevel> levels;
    for (auto &record : read_records(forces))
    {
      if (!record)
        break;
      levels.push_back(std::move(*record));
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
        // the closing's record; the full one once the level is finished
        if (!level.finished() || !level.reached)
          write_grip_level(level, closing_file(k));
        if (level.finished())
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

  void PullSweepStudy::drop_shared(
      std::vector<std::optional<FeGripLevel>> &records) const
  {
    for (unsigned int k = 2; k <= records.size(); ++k)
      if (records[k - 1] && records[k - 1]->state_level < k &&
          !records[records[k - 1]->state_level - 1])
      {
        for (const auto &file : {record_file(k), closing_file(k)})
          remove_on_root(comm, file);
        remove_on_root(comm, level_directory(k) + "/closed");
        records[k - 1].reset();
      }
  }

  int PullSweepStudy::closing_progress() const
  {
    int           k = -1;
    std::ifstream in(output + "/closing_progress.txt");
    if (!(in >> k) || k < 0)
      k = -1;
    return k;
  }

  void PullSweepStudy::set_closing_progress(const unsigned int k) const
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      AtomicFile::write(output + "/closing_progress.txt",
                        std::to_string(k) + "\n");
  }

  bool PullSweepStudy::restart_closing_below(
      const unsigned int                             m,
      const std::vector<std::optional<FeGripLevel>> &records) const
  {
    const std::string closing = output + "/fe_closing";
    for (const char *name : {"checkpoint",
                             "checkpoint.old",
                             "checkpoint.new",
                             "checkpoint.damaged"})
      remove_on_root(comm, closing + "/" + name);
    for (unsigned int j = m - 1; j >= 1; --j)
      if (records[j - 1] && records[j - 1]->reached &&
          records[j - 1]->state_level == j &&
          std::filesystem::exists(level_directory(j) + "/closed/checkpoint") &&
          (records[j - 1]->closed_state.empty() ||
           records[j - 1]->closed_state == closed_state_of(j)))
      {
        copy_checkpoint(comm, level_directory(j) + "/closed", closing);
        set_closing_progress(j);
        return true;
      }
    set_closing_progress(0);
    return false;
  }

  std::vector<FeGripLevel>
  PullSweepStudy::close_to_levels(const KinematicsData      &kinematics,
                                  const std::string         &grip_link,
                                  const std::vector<double> &forces,
                                  std::ostream              &log,
                                  const double               step)
  {
    auto records = read_records(forces, &log);
    drop_shared(records);
    const auto missing = std::find_if(
        records.begin(), records.end(), [](const auto &r) { return !r; });
    if (missing == records.end())
    {
      std::vector<FeGripLevel> levels;
      for (auto &r : records)
        levels.push_back(std::move(*r));
      return levels;
    }
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
    const auto grip = IndentationStudy::link_index(
        inputs.bodies, grip_link, "Grasp-and-pull sweep/Grip link");

    // A killed sweep goes on from the closing's latest checkpoint, unless
    // that may lie beyond the first level without a record (its record was
    // deleted, a later level has one, or the progress file that says how
    // far the closing went is gone): then from a state below it.
    const unsigned int m     = missing - records.begin() + 1;
    const bool         later = std::any_of(
        missing, records.end(), [](const auto &r) { return r.has_value(); });
    const int progress = closing_progress();
    bool      started  = false;
    if (later || progress < 0 || progress >= static_cast<int>(m))
      started = restart_closing_below(m, records);
    else
    {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        started =
            std::filesystem::exists(output + "/fe_closing/checkpoint") ||
            std::filesystem::exists(output + "/fe_closing/checkpoint.old");
      started = Utilities::MPI::broadcast(comm, started, 0);
    }
    std::vector<FeGripLevel> levels;
    for (unsigned int k = 0; k < forces.size(); ++k)
      levels.push_back(
          records[k] ? std::move(*records[k])
                     : close_one(inputs, grip, levels, forces, k, started));
    return levels;
  }

  FeGripLevel
  PullSweepStudy::close_one(SolverInputs<3>                             &inputs,
                            const std::pair<unsigned int, unsigned int> &grip,
                            const std::vector<FeGripLevel>              &levels,
                            const std::vector<double>                   &forces,
                            const unsigned int                           k,
                            bool &started) const
  {
    FeGripLevel level;
    level.target_force = forces[k];
    level.settings     = settings;
    level.state_level  = k + 1;
    if (k > 0 &&
        (!levels[k - 1].reached || levels[k - 1].reached_force >= forces[k]))
    { // the state of the level below: it reaches this one too, or the
      // closure ended below both
      level.reached_force = levels[k - 1].reached_force;
      level.time          = levels[k - 1].time;
      level.reached       = levels[k - 1].reached;
      level.state_level   = levels[k - 1].state_level;
      if (level.reached)
      {
        copy_checkpoint(comm,
                        level_directory(level.state_level) + "/closed",
                        level_directory(k + 1) + "/closed");
        level.closed_state = closed_state_of(k + 1);
      }
    }
    else
    {
      inputs.solver.checkpoint.resume = started;
      auto solver                     = Simulation<3>::create(comm, inputs);
      solver->set_stop_criterion(
          [&solver, b = grip.first, g = grip.second, target = forces[k]]()
          {
            const auto &latest = solver->contact_force_history().back();
            return latest.forces[b][g].normal_force() >= target;
          });
      solver->run();
      started = true;
      set_closing_progress(k + 1);
      const auto &latest = solver->contact_force_history().back();
      level.reached_force =
          latest.forces[grip.first][grip.second].normal_force();
      level.time    = latest.time;
      level.reached = solver->stopped_by_criterion();
      if (level.reached)
      {
        copy_checkpoint(comm,
                        inputs.solver.output.directory,
                        level_directory(k + 1) + "/closed");
        level.closed_state = closed_state_of(k + 1);
      }
    }
    record(level, k + 1);
    return level;
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
    // A pull not begun (or finished and its record deleted, to try again)
    // starts from the level's closed state; a killed one goes on.
    bool begun = false;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      begun = std::filesystem::exists(level_directory(k) + "/checkpoint") ||
              std::filesystem::exists(level_directory(k) + "/checkpoint.old");
    if (!Utilities::MPI::broadcast(comm, begun, 0))
      copy_checkpoint(comm, level_directory(k) + "/closed", level_directory(k));
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
    for (const char *name : {"checkpoint",
                             "checkpoint.old",
                             "checkpoint.new",
                             "checkpoint.damaged"})
      remove_on_root(comm, level_directory(k) + "/" + name);
  }

  void write_grip_level(const FeGripLevel &level, const std::string &filename)
  {
    Hdf5Record::write(
        filename,
        [&](Hdf5Record::Group &file)
        {
          file.attribute("schema", std::string("softgrasp grip level"));
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
          file.attribute("state_level", int(level.state_level));
          file.attribute("closed_state", "state: " + level.closed_state);
          file.attribute("links", int(level.links.size()));
          for (std::size_t i = 0; i < level.links.size(); ++i)
          {
            const auto &link  = level.links[i];
            auto        group = file.group("link_" + std::to_string(i));
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
        "delete it (or its level's directory) to compute the level again: a "
        "level without level.h5 is pulled again from its closed state, one "
        "without closing.h5 closed again from the level below",
        [&](const Hdf5Record::Reader &file)
        {
          // every number of a record is finite and none is negative
          const auto number = [&](const std::string &name)
          {
            const double value = file.number_attribute("", name);
            if (!(value >= 0) || !std::isfinite(value))
              throw std::runtime_error("its attribute '" + name + "' is " +
                                       std::to_string(value));
            return value;
          };
          if (file.string_attribute("", "schema") != "softgrasp grip level")
            throw std::runtime_error("it is not a grip level record");
          level.settings            = file.string_attribute("", "settings");
          level.target_force        = number("target_force");
          level.reached_force       = number("reached_force");
          level.time                = number("time");
          level.reached             = number("reached") != 0;
          level.pulled              = number("pulled") != 0;
          const std::string failure = file.string_attribute("", "failure");
          if (failure.rfind("failure: ", 0) != 0)
            throw std::runtime_error("its attribute 'failure' is damaged");
          level.failure     = failure.substr(9);
          level.balance     = number("balance");
          level.penetration = number("penetration");
          level.state_level = file.has_attribute("/", "state_level")
                                  ? static_cast<unsigned int>(
                                        std::max(0.0, number("state_level")))
                                  : 0;
          if (file.has_attribute("/", "closed_state"))
          {
            const std::string state = file.string_attribute("", "closed_state");
            if (state.rfind("state: ", 0) != 0)
              throw std::runtime_error(
                  "its attribute 'closed_state' is damaged");
            level.closed_state = state.substr(7);
          }
          const int n = static_cast<int>(number("links"));
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
              *values = file.table(group + "/" + name, m, 1);
            for (const double f : force)
              if (!std::isfinite(f))
                throw std::runtime_error("link " + link.link +
                                         " has a force of NaN or inf");
            for (std::size_t j = 0; j < m; ++j)
              link.force.emplace_back(
                  force[3 * j], force[3 * j + 1], force[3 * j + 2]);
            level.links.push_back(link);
          }
        });
    return level;
  }
} // namespace softgrasp

namespace
{
  // A file with this subsection given to another program names its program.
  [[maybe_unused]] const bool softgrasp_program_section =
      softgrasp::ParameterReader::register_program_section(
          "Grasp-and-pull sweep", "grasp_pull_sweep");
} // namespace
