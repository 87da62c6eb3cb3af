/* ---------------------------------------------------------------------------
 * Study: the grasp-and-pull sweep (the source paper's second case study).
 * At grip levels from the equilibrium grip to the indented-state grip (a
 * normal force on the thumb's proximal link), the three-finger hand pulls
 * 2 cm along the upper arm; the lateral force it meets, against the grip,
 * in the rigid simulator (MuJoCo) and on the finite element arm.
 *
 * Run:   ./grasp_pull_sweep [--close | --level k | --collect]
 *                           [--print-parameters] [grasp_pull_sweep.prm]
 * See doc/studies.md.
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <iostream>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/program_arguments.h>
#include <softgrasp/mujoco/grasp_pull_sweep.h>
#include <softgrasp/solvers/solver_program.h>

namespace
{
  /// The level of "--level @p value": a number from 1 to @p levels, or an
  /// InputError with the fix.
  unsigned int level_number(const std::string &value, const unsigned int levels)
  {
    unsigned int level = 0;
    if (!value.empty() &&
        value.find_first_not_of("0123456789") == std::string::npos &&
        value.size() < 4)
      level = std::stoul(value);
    if (level < 1 || level > levels)
      throw softgrasp::InputError("--level " + value +
                                  " is not a level of this sweep. Fix: give a "
                                  "number from 1 to " +
                                  std::to_string(levels) +
                                  " ('Grasp-and-pull sweep/Levels').");
    return level;
  }

  /// The stages the command line asks for, on the sweep of the .prm.
  void run_stages(const softgrasp::ProgramArguments &arguments,
                  softgrasp::GraspPullSweep         &sweep)
  {
    const unsigned int level =
        arguments.has("--level") ? level_number(arguments.options.at("--level"),
                                                sweep.parameters().rigid.levels)
                                 : 0;
    sweep.run_rigid(std::cout);
    if (arguments.has("--collect"))
      sweep.collect(std::cout);
    else if (arguments.has("--close"))
      sweep.close(std::cout);
    else if (level > 0)
    {
      sweep.close(std::cout, level);
      sweep.pull(level, std::cout);
    }
    else
      sweep.run_fe(std::cout);
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace softgrasp;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  ParameterReader::set_program("grasp_pull_sweep", {});
  const auto arguments = ProgramArguments::parse(
      argc,
      argv,
      "grasp_pull_sweep.prm",
      {{"--close",
        "",
        "only the rigid stage and the finite element closing to every level "
        "(a cluster run's first job)"},
       {"--level",
        "k",
        "only level k: what it needs of the rigid stage and the closing, "
        "then its pull (a job array's task)"},
       {"--collect",
        "",
        "only merge the levels' records into the tables and the figure"}});
  const int exit_code = arguments.handle(
      argv[0],
      "The grasp-and-pull sweep: MuJoCo's grasp and pull at every grip level, "
      "then the finite element closing and pulls (doc/studies.md). A killed "
      "sweep resumes where it stopped.",
      root);
  if (exit_code >= 0)
    return exit_code;
  const ErrorCommunicator error_comm(comm);
  try
  {
    if (arguments.options.size() > 1)
      throw InputError("--close, --level and --collect exclude each other. "
                       "Fix: give one of them, or none for the whole sweep.");
    dealii::ParameterHandler prm;
    GraspPullSweep::declare_parameters(prm);
    SolverProgram::read_parameters<3>(prm, arguments.parameter_file);
    if (arguments.print_parameters)
    {
      if (root)
        prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
    if (arguments.dry_run)
    {
      ProgramArguments::report_dry_run(
          "grasp_pull_sweep", arguments.parameter_file, root);
      return 0;
    }
    PullSweepStudy study(comm, prm);
    GraspPullSweep sweep(comm, prm, arguments.parameter_file, study);
    run_stages(arguments, sweep);
  }
  catch (const std::exception &e)
  {
    return fatal_error(e, error_comm);
  }
  return 0;
}
