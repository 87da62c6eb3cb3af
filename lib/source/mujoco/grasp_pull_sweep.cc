#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_pull_sweep.h>
#include <softgrasp/mujoco/grasp_simulation.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  // Longer than 80 lines on purpose: one declare_entry after another, in
  // the order of the .prm and its documentation, reads as a table.
  void SweepParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Grasp-and-pull sweep");
    prm.declare_entry("Grip link",
                      "thumb_proximal/thumb_proximal_link",
                      Patterns::Anything(),
                      "The link (body/geom) whose normal force defines a "
                      "grip level, in MuJoCo and in the finite element "
                      "run (the paper takes the thumb's proximal link).");
    prm.declare_entry("Levels",
                      "13",
                      Patterns::Integer(1, 100),
                      "Number of grip levels, evenly spaced from 'Lowest "
                      "grip force' to 'Highest grip force'.");
    prm.declare_entry("Lowest grip force",
                      "0",
                      Patterns::Double(0),
                      "Normal force on the grip link at the loosest level; "
                      "0: MuJoCo's force at the equilibrium state (as in "
                      "the paper). Unit: N.");
    prm.declare_entry("Highest grip force",
                      "40",
                      Patterns::Double(0),
                      "Normal force on the grip link at the tightest level "
                      "(the paper's indented state: about 40 N). Unit: N.");
    prm.declare_entry("Pull distance",
                      "0.02",
                      Patterns::Double(0),
                      "How far the hand base moves along 'Rigid "
                      "environment/Pull/Axis' at every level (the paper: "
                      "2 cm towards the wrist). Unit: m.");
    prm.declare_entry("Pull speed",
                      "0.02",
                      Patterns::Double(0),
                      "Speed of MuJoCo's slide actuator target during the "
                      "pull. Unit: m/s.");
    prm.declare_entry("Pull servo stiffness",
                      "1e5",
                      Patterns::Double(0),
                      "Gain of MuJoCo's slide servo during the pulls (its "
                      "joint then critically damped for the hand's mass): "
                      "a robot arm carrying the hand holds its path; the "
                      "scene's own, softer servo would lag behind by the "
                      "drag over its gain. Unit: N/m.");
    prm.declare_entry("Pull friction coefficient",
                      "-1",
                      Patterns::Double(-1),
                      "Coulomb's friction coefficient of the finite element "
                      "pulls (each a branch from its level's closed state); "
                      "-1: 'Contact/Friction coefficient', as in the "
                      "closing. 0 leaves the drag of the tissue's pressure "
                      "on the links alone (on a straight limb none: "
                      "translation invariance). MuJoCo's pulls keep their "
                      "geoms' friction. Unit: 1.");
    prm.declare_entry("Closing time step",
                      "0",
                      Patterns::Double(0),
                      "Load step of the finite element closing (explicit: "
                      "its record interval), where each level stops at the "
                      "first step whose grip force is at or above the "
                      "level's; 0: 'Time/Time step'. Levels closer than the "
                      "force the closure adds in one step share a state "
                      "(and a pull); a smaller step makes them distinct at "
                      "the cost of more steps, and of one more pull per "
                      "level that becomes distinct. Unit: s.");
    prm.declare_entry("Pull samples",
                      "40",
                      Patterns::Integer(2, 10000),
                      "Records over one pull in MuJoCo.");
    prm.declare_entry("Settle time",
                      "2",
                      Patterns::Double(0),
                      "MuJoCo time simulated for each closure tried while "
                      "searching a level's grip force. Unit: s.");
    prm.declare_entry("Force tolerance",
                      "0.01",
                      Patterns::Double(0, 1),
                      "Relative miss of a level's grip force that MuJoCo's "
                      "search accepts. Unit: 1.");
    prm.declare_entry("Maximum closure",
                      "0.6",
                      Patterns::Double(0),
                      "Largest angle added to every finger joint's target "
                      "beyond the equilibrium state while searching a "
                      "level. Unit: rad.");
    prm.declare_entry("Slide fraction",
                      "0.1",
                      Patterns::Double(0, 1),
                      "A link slides when its contact points move relative "
                      "to the object, tangentially, at more than this "
                      "fraction of the pull speed (mean over the second "
                      "half of the pull). Unit: 1.");
    prm.leave_subsection();
  }

  void SweepParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Grasp-and-pull sweep");
    const CheckedSection section(prm, "Grasp-and-pull sweep");
    grip_label       = Utilities::trim(prm.get("Grip link"));
    const auto slash = grip_label.find('/');
    if (slash == std::string::npos || slash == 0 ||
        slash + 1 == grip_label.size())
      throw InputError("'Grasp-and-pull sweep/Grip link' = '" + grip_label +
                       "' is not body/geom. Fix: name the link as body/geom, "
                       "e.g. thumb_proximal/thumb_proximal_link.");
    rigid.grip_link      = grip_label.substr(slash + 1);
    rigid.levels         = prm.get_integer("Levels");
    rigid.lowest_force   = section.get_positive("Lowest grip force", "N", true);
    rigid.highest_force  = section.get_positive("Highest grip force", "N");
    rigid.pull_distance  = section.get_positive("Pull distance", "m");
    rigid.pull_speed     = section.get_positive("Pull speed", "m/s");
    rigid.samples        = prm.get_integer("Pull samples");
    rigid.pull_stiffness = section.get_positive("Pull servo stiffness", "N/m");
    rigid.settle_time    = section.get_positive("Settle time", "s");
    rigid.force_tolerance = section.get_positive("Force tolerance", "1");
    rigid.maximum_closure = section.get_positive("Maximum closure", "rad");
    rigid.slide_fraction  = section.get_positive("Slide fraction", "1");
    pull_friction         = prm.get_double("Pull friction coefficient");
    closing_step = section.get_positive("Closing time step", "s", true);
    prm.leave_subsection();
    if (rigid.lowest_force >= rigid.highest_force)
      throw InputError("'Grasp-and-pull sweep/Lowest grip force' (" +
                       std::to_string(rigid.lowest_force) +
                       " N) is not below 'Highest grip force' (" +
                       std::to_string(rigid.highest_force) +
                       " N). Fix: lower it, or set 0 to start at the "
                       "equilibrium state.");
  }

  void GraspPullSweep::declare_parameters(ParameterHandler &prm)
  {
    GraspParameters::declare_parameters(prm);
    ArmGraspStudy::declare_parameters(prm);
    SweepParameters::declare_parameters(prm);
  }

  namespace
  {
    /// The text of @p file ("" if it cannot be read: the rigid stage then
    /// reports the missing scene).
    std::string text_of(const std::string &file)
    {
      std::ifstream in(file);
      return std::string(std::istreambuf_iterator<char>(in), {});
    }
  } // namespace

  GraspPullSweep::GraspPullSweep(MPI_Comm           comm,
                                 ParameterHandler  &prm,
                                 const std::string &prm_file,
                                 PullSweepStudy    &study)
      : comm(comm)
      , study(study)
  {
    grasp.parse_parameters(
        prm, std::filesystem::path(prm_file).parent_path().string());
    sweep.parse_parameters(prm);
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    prm.leave_subsection();
    // The recorded pull phase is the sweep's pull: the finite element
    // pulls replay its motion.
    grasp.pull.distance = sweep.rigid.pull_distance;
    grasp.pull.duration = sweep.rigid.pull_distance / sweep.rigid.pull_speed;
    // The rigid stage's inputs: every setting but the output's (a finite
    // element setting changed between runs costs only a repeated rigid
    // stage of a few seconds), and the hand's scene file.
    settings = study.settings_text() + "hand:\n" + text_of(grasp.scene_file);
  }

  void GraspPullSweep::run_rigid(std::ostream &log)
  {
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      try
      {
        std::error_code code;
        if (!std::filesystem::create_directories(directory, code) && code)
          throw InputError("Cannot create the output directory '" + directory +
                           "' (" + code.message() +
                           "). Fix: choose an 'Output/Directory' in a "
                           "writable place.");
        const std::string file = directory + "/sweep_rigid.h5";
        if (std::filesystem::exists(file) &&
            std::filesystem::exists(study.arm().kinematics_file(directory)))
          record = read_rigid_record(file);
        if (record.settings == settings)
          log << "Rigid stage: the results in " << file
              << " are of these settings; not run again\n";
        else
        {
          GraspParameters parameters = grasp;
          parameters.scene_file =
              study.arm().rigid_scene(parameters.scene_file, directory);
          const auto      start = std::chrono::steady_clock::now();
          GraspSimulation simulation(parameters, log);
          const auto      data = simulation.run();
          write_kinematics_file(data, study.arm().kinematics_file(directory));
          rigid = simulation.grip_levels(sweep.rigid);
          log << "Rigid stage (MuJoCo): "
              << std::chrono::duration<double>(
                     std::chrono::steady_clock::now() - start)
                     .count()
              << " s wall time\n";
          write_rigid_levels(rigid,
                             directory + "/sweep_rigid_levels.csv",
                             directory + "/sweep_rigid_pulls.csv");
          record          = RigidSweepRecord();
          record.settings = settings;
          for (const auto &level : rigid)
            record.targets.push_back(level.target_force);
          record.friction = rigid.empty() ? 0 : rigid.front().friction;
          record.points   = grip_link_points(rigid, sweep.rigid.grip_link);
          write_rigid_record(record, file);
          figure({}, log);
        }
      }
      catch (const std::exception &e)
      {
        error = e.what();
      }
    }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    record.targets  = Utilities::MPI::broadcast(comm, record.targets, 0);
    record.friction = Utilities::MPI::broadcast(comm, record.friction, 0);
  }

  void GraspPullSweep::close(std::ostream &log, const unsigned int up_to)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    const auto kinematics =
        read_kinematics_file(study.arm().kinematics_file(directory));
    std::vector<double> forces = record.targets;
    if (up_to > 0 && up_to < forces.size())
      forces.resize(up_to);
    const auto start = std::chrono::steady_clock::now();
    fe               = study.close_to_levels(
        kinematics, sweep.grip_label, forces, log, sweep.closing_step);
    if (!root)
      return;
    for (std::size_t k = 0; k < fe.size(); ++k)
      if (fe[k].reached)
        log << "Level " << k + 1 << " (" << fe[k].target_force
            << " N): reached " << fe[k].reached_force
            << " N at t = " << fe[k].time << " s of the closure\n";
      else
        log << "Level " << k + 1 << " (" << fe[k].target_force
            << " N): not reached; the finite element closure ended at "
            << fe[k].reached_force
            << " N. Fix: raise 'Rigid environment/Indentation/Extra "
               "joint angle'.\n";
    log << "Finite element closing: "
        << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
               .count()
        << " s wall time\n";
  }

  void GraspPullSweep::pull(const unsigned int k, std::ostream &log)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    if (k < 1 || k > fe.size())
      throw InputError("Level " + std::to_string(k) +
                       " has not been closed to. Fix: run the closing "
                       "(grasp_pull_sweep --close) first.");
    FeGripLevel &level = fe[k - 1];
    if (level.finished())
    {
      if (root)
        log << "Level " << k << ": finished ("
            << (level.pulled     ? "pulled"
                : !level.reached ? "not reached"
                                 : "failed: " + level.failure)
            << ", " << study.record_file(k) << "); not run again\n";
      return;
    }
    if (k > 1 && fe[k - 2].pulled && fe[k - 2].time == level.time)
    { // the closing reached both levels in one state: the same pull
      const FeGripLevel &below = fe[k - 2];
      level.pulled             = true;
      level.balance            = below.balance;
      level.penetration        = below.penetration;
      level.links              = below.links;
      study.record(level, k);
      if (root)
        log << "Level " << k << ": the state of level " << k - 1
            << ", whose pull it shares\n";
      return;
    }
    if (root)
      log << "Level " << k << ": " << level.reached_force
          << " N at t = " << level.time << " s of the closure; pulling\n";
    const auto start = std::chrono::steady_clock::now();
    study.pull(read_kinematics_file(study.arm().kinematics_file(directory)),
               k,
               level,
               sweep.pull_friction);
    if (root)
      log << "Level " << k << ": "
          << (level.pulled ? "pulled" : "the pull stopped: " + level.failure)
          << " ("
          << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
                 .count()
          << " s wall time)\n";
  }

  void GraspPullSweep::collect(std::ostream &log)
  {
    fe = study.recorded_levels(record.targets);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    for (std::size_t k = 0; k < record.targets.size(); ++k)
      if (k >= fe.size())
        log << "Level " << k + 1
            << ": not closed to yet. Fix: grasp_pull_sweep --level " << k + 1
            << "\n";
      else if (!fe[k].finished())
        log << "Level " << k + 1
            << ": closed to, not pulled yet. Fix: grasp_pull_sweep --level "
            << k + 1 << "\n";
      else if (!fe[k].pulled && fe[k].reached)
        log << "Level " << k + 1 << ": the pull stopped: " << fe[k].failure
            << "\n";
    write_fe_levels(fe,
                    directory + "/sweep_fe_levels.csv",
                    directory + "/sweep_fe_pulls.csv");
    figure(fe, log);
  }

  void GraspPullSweep::run_fe(std::ostream &log)
  {
    const auto start = std::chrono::steady_clock::now();
    close(log);
    for (unsigned int k = 1; k <= fe.size(); ++k)
      pull(k, log);
    collect(log);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      log << "Finite element stage: "
          << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
                 .count()
          << " s wall time\n";
  }

  void GraspPullSweep::figure(const std::vector<FeGripLevel> &levels,
                              std::ostream                   &log) const
  {
    write_sweep_figure(record.points,
                       grip_link_points(levels, sweep.grip_label),
                       record.friction,
                       sweep.grip_label,
                       directory,
                       "sweep",
                       log);
  }
} // namespace softgrasp
