#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/program_arguments.h>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mechanics/solver_program.h>
#include <softgrasp/mujoco/grasp_pull_sweep.h>
#include <softgrasp/mujoco/grasp_simulation.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

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
  }

  int GraspPullSweep::main(int argc, char **argv)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    const auto     arguments =
        ProgramArguments::parse(argc, argv, "grasp_pull_sweep.prm");
    const int exit_code = arguments.handle(
        argv[0],
        "The grasp-and-pull sweep: MuJoCo's grasp and pull at every grip "
        "level, then the finite element closing and pulls "
        "(doc/studies.md).",
        root);
    if (exit_code >= 0)
      return exit_code;
    const bool              print    = arguments.print_parameters;
    const std::string      &filename = arguments.parameter_file;
    const ErrorCommunicator error_comm(comm);
    try
    {
      ParameterHandler prm;
      declare_parameters(prm);
      SolverProgram::read_parameters<3>(prm, filename);
      if (print)
      {
        if (root)
          prm.print_parameters(std::cout, ParameterHandler::PRM);
        return 0;
      }
      PullSweepStudy study(comm, prm);
      GraspPullSweep sweep(comm, prm, filename, study);
      sweep.run_rigid(std::cout);
      sweep.run_fe(std::cout);
    }
    catch (const std::exception &e)
    {
      return fatal_error(e, error_comm);
    }
    return 0;
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
        GraspParameters parameters = grasp;
        parameters.scene_file =
            study.rigid_scene(parameters.scene_file, directory);
        const auto      start = std::chrono::steady_clock::now();
        GraspSimulation simulation(parameters, log);
        const auto      data = simulation.run();
        write_kinematics_file(data, study.kinematics_file(directory));
        rigid = simulation.grip_levels(sweep.rigid);
        log << "Rigid stage (MuJoCo): "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
                   .count()
            << " s wall time\n";
        write_rigid_levels(rigid,
                           directory + "/sweep_rigid_levels.csv",
                           directory + "/sweep_rigid_pulls.csv");
        for (const auto &level : rigid)
          targets.push_back(level.target_force);
        friction = rigid.empty() ? 0 : rigid.front().friction;
        write_sweep_figure(grip_link_points(rigid, sweep.rigid.grip_link),
                           {},
                           friction,
                           sweep.grip_label,
                           directory,
                           "sweep",
                           log);
      }
      catch (const std::exception &e)
      {
        error = e.what();
      }
    }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    targets  = Utilities::MPI::broadcast(comm, targets, 0);
    friction = Utilities::MPI::broadcast(comm, friction, 0);
  }

  void GraspPullSweep::run_fe(std::ostream &log)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    const auto kinematics =
        read_kinematics_file(study.kinematics_file(directory));
    const auto start = std::chrono::steady_clock::now();
    fe = study.close_to_levels(kinematics, sweep.grip_label, targets);
    for (std::size_t k = 0; k < fe.size(); ++k)
    {
      if (!fe[k].reached)
      {
        if (root)
          log << "Level " << k + 1 << " (" << fe[k].target_force
              << " N): not reached; the finite element closure ended at "
              << fe[k].reached_force
              << " N. Fix: raise 'Rigid environment/Indentation/Extra "
                 "joint angle'.\n";
        continue;
      }
      if (root)
        log << "Level " << k + 1 << ": " << fe[k].reached_force
            << " N at t = " << fe[k].time << " s of the closure; pulling\n";
      study.pull(kinematics, k + 1, fe[k]);
      if (root && !fe[k].pulled)
        log << "Level " << k + 1 << ": the pull stopped: " << fe[k].failure
            << "\n";
    }
    if (!root)
      return;
    log << "Finite element stage: "
        << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
               .count()
        << " s wall time\n";
    write_fe_levels(fe,
                    directory + "/sweep_fe_levels.csv",
                    directory + "/sweep_fe_pulls.csv");
    write_sweep_figure(grip_link_points(rigid, sweep.rigid.grip_link),
                       grip_link_points(fe, sweep.grip_label),
                       friction,
                       sweep.grip_label,
                       directory,
                       "sweep",
                       log);
  }

  namespace
  {
    double max_of(const std::vector<double> &v)
    {
      return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
    }

    /// Mean of @p v over the records from half the last time on.
    double second_half_mean(const std::vector<double> &time,
                            const std::vector<double> &v)
    {
      double sum = 0;
      int    n   = 0;
      for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= 0.5 * time.back())
          sum += v[i], ++n;
      return n > 0 ? sum / n : 0;
    }
  } // namespace

  void write_rigid_levels(const std::vector<RigidGripLevel> &levels,
                          const std::string                 &summary_file,
                          const std::string                 &pulls_file)
  {
    std::ostringstream summary;
    summary << std::setprecision(8)
            << "level,link,target_force,reached_force,closure,matched,"
               "normal_end,normal_mean,lateral_end,lateral_mean,lateral_max,"
               "drag_end,drag_mean,drag_max,slip_speed_mean,slides\n";
    std::ostringstream pulls;
    pulls << std::setprecision(8) << "level,time,slide";
    if (!levels.empty())
      for (const auto &link : levels.front().links)
        for (const char *part : {"normal", "lateral", "drag", "slip_speed"})
          pulls << ',' << link.body << '/' << link.geom << ':' << part;
    pulls << '\n';
    for (std::size_t k = 0; k < levels.size(); ++k)
    {
      const auto &level = levels[k];
      for (const auto &link : level.links)
        summary << k + 1 << ',' << link.body << '/' << link.geom << ','
                << level.target_force << ',' << level.reached_force << ','
                << level.closure << ',' << level.matched << ','
                << link.normal.back() << ',' << link.normal_mean << ','
                << link.lateral.back() << ',' << link.lateral_mean << ','
                << max_of(link.lateral) << ',' << link.drag.back() << ','
                << link.drag_mean << ',' << max_of(link.drag) << ','
                << link.slip_mean << ',' << link.slides << '\n';
      for (std::size_t i = 0; i < level.time.size(); ++i)
      {
        pulls << k + 1 << ',' << level.time[i] << ',' << level.slide[i];
        for (const auto &link : level.links)
          pulls << ',' << link.normal[i] << ',' << link.lateral[i] << ','
                << link.drag[i] << ',' << link.slip_speed[i];
        pulls << '\n';
      }
    }
    AtomicFile::write(summary_file, summary.str());
    AtomicFile::write(pulls_file, pulls.str());
  }

  std::vector<SweepPoint>
  grip_link_points(const std::vector<RigidGripLevel> &levels,
                   const std::string                 &grip_geom)
  {
    std::vector<SweepPoint> points;
    for (std::size_t k = 0; k < levels.size(); ++k)
      for (const auto &link : levels[k].links)
        if (link.geom == grip_geom)
        {
          SweepPoint p;
          p.level        = k + 1;
          p.grip_force   = levels[k].reached_force;
          p.normal_mean  = link.normal_mean;
          p.lateral_mean = link.lateral_mean;
          p.lateral_max  = max_of(link.lateral);
          points.push_back(p);
        }
    return points;
  }

  std::vector<SweepPoint> grip_link_points(const std::vector<FeGripLevel> &fe,
                                           const std::string &grip_label)
  {
    std::vector<SweepPoint> points;
    for (std::size_t k = 0; k < fe.size(); ++k)
      for (const auto &link : fe[k].links)
        if (fe[k].pulled && link.link == grip_label && !link.time.empty())
        {
          SweepPoint p;
          p.level         = k + 1;
          p.grip_force    = fe[k].reached_force;
          p.normal_mean   = second_half_mean(link.time, link.normal);
          p.lateral_mean  = second_half_mean(link.time, link.lateral);
          p.lateral_max   = max_of(link.lateral);
          p.friction_mean = second_half_mean(link.time, link.friction);
          points.push_back(p);
        }
    return points;
  }

  void write_fe_levels(const std::vector<FeGripLevel> &levels,
                       const std::string              &summary_file,
                       const std::string              &pulls_file)
  {
    std::ostringstream summary, pulls;
    summary << std::setprecision(8)
            << "level,link,target_force,reached_force,closure_time,pulled,"
               "normal_end,normal_mean,lateral_end,lateral_mean,"
               "friction_end,friction_mean\n";
    pulls << std::setprecision(8)
          << "level,link,time,normal,lateral,friction\n";
    for (std::size_t k = 0; k < levels.size(); ++k)
    {
      const auto &level = levels[k];
      for (const auto &link : level.links)
      {
        if (link.time.empty())
          continue;
        summary << k + 1 << ',' << link.link << ',' << level.target_force << ','
                << level.reached_force << ',' << level.time << ','
                << level.pulled << ',' << link.normal.back() << ','
                << second_half_mean(link.time, link.normal) << ','
                << link.lateral.back() << ','
                << second_half_mean(link.time, link.lateral) << ','
                << link.friction.back() << ','
                << second_half_mean(link.time, link.friction) << '\n';
        for (std::size_t i = 0; i < link.time.size(); ++i)
          pulls << k + 1 << ',' << link.link << ',' << link.time[i] << ','
                << link.normal[i] << ',' << link.lateral[i] << ','
                << link.friction[i] << '\n';
      }
    }
    AtomicFile::write(summary_file, summary.str());
    AtomicFile::write(pulls_file, pulls.str());
  }

  void write_sweep_figure(const std::vector<SweepPoint> &rigid,
                          const std::vector<SweepPoint> &fe,
                          const double                   friction,
                          const std::string             &grip_link,
                          const std::string             &directory,
                          const std::string             &base,
                          std::ostream                  &log)
  {
    double       top    = 1;
    unsigned int levels = 2;
    {
      std::ofstream out(directory + "/" + base + "_figure.dat");
      out << "# grip link " << grip_link
          << ": level, grip force at the level, then over the second half "
             "of the pull the mean normal and lateral force and the third "
             "value (rigid: the largest lateral force over the pull; finite "
             "elements: the mean friction-only force), all in N\n"
          << "# rigid simulator (MuJoCo)\n";
      for (const auto &p : rigid)
      {
        out << p.level << ' ' << p.grip_force << ' ' << p.normal_mean << ' '
            << p.lateral_mean << ' ' << p.lateral_max << '\n';
        top    = std::max({top, p.normal_mean, p.lateral_mean});
        levels = std::max(levels, p.level);
      }
      out << "\n\n# finite elements\n";
      for (const auto &p : fe)
      {
        out << p.level << ' ' << p.grip_force << ' ' << p.normal_mean << ' '
            << p.lateral_mean << ' ' << p.friction_mean << '\n';
        top    = std::max({top, p.normal_mean, p.lateral_mean});
        levels = std::max(levels, p.level);
      }
      if (fe.empty())
        out << "-1 0 0 0 0\n"; // an empty block would stop gnuplot
    }
    const std::string data = "'" + base + "_figure.dat'";
    {
      std::ofstream gp(directory + "/" + base + "_figure.gnuplot");
      gp << "set terminal pngcairo size 1500,700 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_figure.png")
         << "'\n"
         << "set multiplot layout 1,2 title 'Grasp-and-pull sweep: forces "
            "on "
         << grip_link << " during the pull (means over its second half)'\n"
         << "set grid\nset key bottom right\n"
         << "set palette defined (0 'blue', 1 'red')\n"
         << "set cblabel 'grip level'\nset cbrange [1:" << levels
         << "]\nset cbtics 1\n"
         << "set title 'lateral against normal force'\n"
         << "set xlabel 'normal force (N)'\nset ylabel 'lateral force (N)'\n"
         << "set xrange [0:" << 1.1 * top << "]\nset yrange [0:" << 1.1 * top
         << "]\n"
         << "plot " << friction << " * x with lines dt 2 lc rgb 'gray40' "
         << "title 'mu N (mu = " << friction << ")', " << data
         << " index 0 using 3:4 with lines lw 2 lc rgb '#1f77b4' title "
            "'MuJoCo (rigid)', "
         << data << " index 1 using ($1 > 0 ? $3 : NaN):4 with lines lw 2 "
         << "lc rgb '#ff7f0e' title 'finite elements', " << data
         << " index 0 using 3:4:1 with points pt 7 ps 1.5 lc palette "
            "notitle, "
         << data
         << " index 1 using ($1 > 0 ? $3 : NaN):4:1 with points pt 5 ps 1.5 "
            "lc palette notitle\n"
         << "set title 'finite elements: lateral force = friction + tissue "
            "pressure'\n"
         << "set xlabel 'grip level'\nset ylabel 'force (N)'\n"
         << "set xrange [0.5:" << levels + 0.5
         << "]\nset yrange [0:*]\nset key top left\n"
         << "set style fill solid 0.8\nset boxwidth 0.35\nset xtics 1\n";
      if (fe.empty())
        gp << "set label 1 'no finite element level pulled yet' at graph "
              "0.5, 0.5 center\nplot NaN notitle\n";
      else
        gp << "plot " << data
           << " index 1 using ($1 - 0.18):4 with boxes lc rgb "
           << "'#ff7f0e' title 'lateral (all)', " << data
           << " index 1 using ($1 + 0.18):5 with boxes lc rgb '#2ca02c' title "
              "'friction-only part', "
           << data << " index 1 using 1:3 with linespoints pt 7 lc rgb "
           << "'black' title 'normal'\n";
      gp << "unset multiplot\n";
    }
    run_gnuplot(
        directory, base + "_figure.gnuplot", {base + "_figure.png"}, log);
  }
} // namespace softgrasp
