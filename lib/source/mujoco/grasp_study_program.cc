#include <chrono>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iostream>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/program_arguments.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/mujoco/grasp_simulation.h>
#include <softgrasp/mujoco/grasp_study_program.h>
#include <softgrasp/solvers/solver_program.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    void read_study_parameters(
        ParameterHandler                              &prm,
        const std::string                             &filename,
        const std::function<void(ParameterHandler &)> &declare_study)
    {
      GraspParameters::declare_parameters(prm);
      if (declare_study)
        declare_study(prm);
      else
        IndentationStudy::declare_parameters(prm);
      SolverProgram::read_parameters<3>(prm, filename);
    }

    /// The rigid stage on rank 0; its error (if any) reaches every rank.
    void run_rigid_stage(MPI_Comm                comm,
                         ParameterHandler       &prm,
                         const std::string      &prm_file,
                         const IndentationStudy &study,
                         const std::string      &kinematics_file)
    {
      std::string error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        try
        {
          // The directory first: a bad one must not cost a MuJoCo run.
          const auto directory =
              std::filesystem::path(kinematics_file).parent_path();
          std::error_code code;
          if (!directory.empty() &&
              !std::filesystem::create_directories(directory, code) && code)
            throw InputError("Cannot create the directory '" +
                             directory.string() + "' of the kinematics file (" +
                             code.message() +
                             "). Fix: choose an 'Output/Directory' (and "
                             "'Indentation study/Kinematics file') in a "
                             "writable place.");
          GraspParameters parameters;
          parameters.parse_parameters(
              prm, std::filesystem::path(prm_file).parent_path().string());
          parameters.scene_file =
              study.rigid_scene(parameters.scene_file, directory.string());
          const auto      start = std::chrono::steady_clock::now();
          GraspSimulation simulation(parameters, std::cout);
          const auto      data = simulation.run();
          std::cout << "Rigid stage (MuJoCo): "
                    << std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count()
                    << " s wall time\n";
          write_kinematics_file(data, kinematics_file);
          std::cout << "Kinematics file: " << kinematics_file << "\n\n";
        }
        catch (const std::exception &e)
        {
          error = e.what();
        }
      }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw InputError(error);
    }
  } // namespace

  int GraspStudyProgram::run(int argc, char **argv) const
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    ParameterReader::set_program(name, reads_files_of);
    const auto arguments =
        ProgramArguments::parse(argc, argv, default_parameter_file);
    const int exit_code = arguments.handle(
        argv[0],
        "Runs MuJoCo to the equilibrium grasp (unless 'Indentation "
        "study/Rigid stage' is 'read'), then the finite element indentation.",
        root);
    if (exit_code >= 0)
      return exit_code;
    const bool              print    = arguments.print_parameters;
    const std::string      &filename = arguments.parameter_file;
    const ErrorCommunicator error_comm(comm);
    try
    {
      ParameterHandler prm;
      read_study_parameters(prm, filename, declare_study_parameters);
      if (print)
      {
        if (root)
          prm.print_parameters(std::cout, ParameterHandler::PRM);
        return 0;
      }
      if (arguments.dry_run)
      {
        ProgramArguments::report_dry_run(name, filename, root);
        return 0;
      }
      const std::unique_ptr<IndentationStudy> study_pointer =
          make_study ? make_study(comm, prm)
                     : std::make_unique<IndentationStudy>(comm, prm);
      IndentationStudy &study = *study_pointer;
      prm.enter_subsection("Output");
      const std::string directory = prm.get("Directory");
      prm.leave_subsection();
      const std::string kinematics_file = study.kinematics_file(directory);
      if (study.rigid_stage_requested() || rigid_only)
        run_rigid_stage(comm, prm, filename, study, kinematics_file);
      if (rigid_only)
        return 0;
      study.run(read_kinematics_file(kinematics_file));
      if (report)
        report(study);
    }
    catch (const std::exception &e)
    {
      return fatal_error(e, error_comm);
    }
    return 0;
  }
} // namespace softgrasp
