#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/mechanics/mechanics_solver.h>
#include <softgrasp/rigid/pose_trajectory.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
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
      : ArmGraspStudy(comm, prm)
      , output(solver_inputs.solver.output.directory)
  {
  }

  std::string PullSweepStudy::level_directory(const unsigned int k) const
  {
    std::ostringstream name;
    name << output << "/level_" << std::setw(2) << std::setfill('0') << k;
    return name.str();
  }

  std::vector<FeGripLevel>
  PullSweepStudy::close_to_levels(const KinematicsData      &kinematics,
                                  const std::string         &grip_link,
                                  const std::vector<double> &forces)
  {
    const auto     &phase  = kinematics.phase("indentation");
    const auto      cut    = kinematics.slice(phase.start_time, phase.end_time);
    SolverInputs<3> inputs = inputs_for(cut);
    inputs.solver.time.end_time    = phase.end_time - phase.start_time;
    inputs.solver.output.directory = output + "/fe_closing";
    inputs.add_resume_setting("Study/Sweep", "grasp-and-pull");
    const auto [b, g] =
        link_index(inputs.bodies, grip_link, "Grasp-and-pull sweep/Grip link");

    std::vector<FeGripLevel> levels(forces.size());
    for (std::size_t k = 0; k < forces.size(); ++k)
      levels[k].target_force = forces[k];
    bool closing_started = false;
    for (std::size_t k = 0; k < forces.size(); ++k)
    {
      FeGripLevel &level = levels[k];
      if (k > 0 && levels[k - 1].reached_force >= forces[k])
      { // the state that reached the level below reaches this one too
        level.reached_force = levels[k - 1].reached_force;
        level.time          = levels[k - 1].time;
        level.reached       = true;
        copy_checkpoint(
            comm, inputs.solver.output.directory, level_directory(k + 1));
        continue;
      }
      inputs.solver.checkpoint.resume = closing_started;
      auto solver = MechanicsSolver<3>::create(comm, inputs);
      solver->set_stop_criterion(
          [&solver, b = b, g = g, target = forces[k]]()
          {
            const auto &latest = solver->contact_force_history().back();
            return latest.forces[b][g].normal_force() >= target;
          });
      solver->run();
      closing_started     = true;
      const auto &latest  = solver->contact_force_history().back();
      level.reached_force = latest.forces[b][g].normal_force();
      level.time          = latest.time;
      level.reached       = solver->stopped_by_criterion();
      if (!level.reached)
        break; // the closure ended below this level and all above it
      copy_checkpoint(
          comm, inputs.solver.output.directory, level_directory(k + 1));
    }
    return levels;
  }

  void PullSweepStudy::pull(const KinematicsData &kinematics,
                            const unsigned int    k,
                            FeGripLevel          &level)
  {
    const auto &indentation = kinematics.phase("indentation");
    const auto &pull_phase  = kinematics.phase("pull");
    const auto  closing =
        kinematics.slice(indentation.start_time, indentation.end_time);
    const auto motion =
        kinematics.slice(pull_phase.start_time, pull_phase.end_time);
    const KinematicsData path       = pull_from(closing, motion, level.time);
    SolverInputs<3>      inputs     = inputs_for(path);
    inputs.solver.output.directory  = level_directory(k);
    inputs.solver.checkpoint.resume = true;
    inputs.add_resume_setting("Study/Sweep", "grasp-and-pull");
    auto solver = MechanicsSolver<3>::create(comm, inputs);
    try
    {
      solver->run();
      level.pulled = true;
    }
    catch (const SolverFailure &e)
    {
      level.failure = e.what();
    }
    const auto check  = final_state_check(*solver);
    level.balance     = check.balance;
    level.penetration = check.penetration;
    level.links       = link_force_histories(solver->rigid_bodies(),
                                       solver->contact_force_history());
    // Keep the pull's records only (time from the level's start).
    for (auto &link : level.links)
    {
      LinkForceHistory kept;
      kept.link = link.link;
      for (std::size_t i = 0; i < link.time.size(); ++i)
        if (link.time[i] >= level.time - 1e-12)
        {
          kept.time.push_back(link.time[i] - level.time);
          kept.force.push_back(link.force[i]);
          kept.normal.push_back(link.normal[i]);
          kept.lateral.push_back(link.lateral[i]);
          kept.friction.push_back(link.friction[i]);
        }
      link = kept;
    }
  }
} // namespace softgrasp
