#include <deal.II/base/mpi.h>
#include <fstream>
#include <iostream>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/program_arguments.h>
#include <softgrasp/solvers/simulation.h>
#include <softgrasp/solvers/solver_program.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// 'Dimension' with the default @p dim (the dimension a program that
    /// reads it runs in).
    void declare_dimension(ParameterHandler &prm, const unsigned int dim = 2)
    {
      prm.declare_entry("Dimension",
                        std::to_string(dim),
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain; forces per metre "
                        "of thickness) or 3. Unit: 1.");
    }
  } // namespace

  unsigned int SolverProgram::read_dimension(const std::string &filename)
  {
    const std::string text = ParameterReader::file_text(filename);
    ParameterHandler  prm;
    declare_dimension(prm);
    ParameterReader reader;
    try
    {
      prm.parse_input_from_string(text, "", true);
    }
    catch (const ExceptionBase &)
    {
      // reported with line numbers by the full read
      reader.read_string(prm, text, filename);
    }
    return prm.get_integer("Dimension");
  }

  template <int dim>
  void SolverProgram::read_parameters(ParameterHandler  &prm,
                                      const std::string &filename)
  {
    declare_dimension(prm, dim);
    Simulation<dim>::declare_parameters(prm);
    ParameterReader reader;
    Simulation<dim>::add_passes(reader);
    reader.read_file(prm, filename);
    if (prm.get_integer("Dimension") != dim)
      throw InputError("'Dimension' = " + prm.get("Dimension") + " in '" +
                       filename + "', but this program runs in " +
                       std::to_string(dim) + "D only. Fix: set 'Dimension = " +
                       std::to_string(dim) + "' or remove the entry.");
  }

  namespace
  {
    /// Every entry on rank 0 (@p root): with a file, including the
    /// subsections the file creates (per material id, boundary id, rigid
    /// body and geom), with the file's values; without, the entries every
    /// run has.
    void print_all_parameters(const std::string &filename,
                              const bool         file_given,
                              const bool         root)
    {
      ParameterHandler prm;
      if (file_given)
      {
        if (SolverProgram::read_dimension(filename) == 2)
          SolverProgram::read_parameters<2>(prm, filename);
        else
          SolverProgram::read_parameters<3>(prm, filename);
      }
      else
      {
        ParameterReader::declare_program_entry(prm);
        declare_dimension(prm);
        Simulation<2>::declare_parameters(prm);
      }
      if (root)
        prm.print_parameters(std::cout, ParameterHandler::PRM);
    }

    /// Read @p filename, run its simulation and @p report it.
    template <int dim>
    void run_file(MPI_Comm                                            comm,
                  const std::string                                  &filename,
                  const std::function<void(const Simulation<dim> &)> &report)
    {
      ParameterHandler prm;
      SolverProgram::read_parameters<dim>(prm, filename);
      const auto simulation = Simulation<dim>::create(comm, prm);
      simulation->run();
      if (report)
        report(*simulation);
    }
  } // namespace

  int SolverProgram::run(int argc, char **argv) const
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    ParameterReader::set_program(name, reads_files_of);
    bool        print_parameters = false;
    bool        dry_run          = false;
    bool        file_given       = false;
    std::string filename         = default_parameter_file;
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--print-parameters")
        print_parameters = true;
      else if (arg == "--dry-run")
        dry_run = true;
      else if (arg == "--help" || arg == "-h")
      {
        if (root)
          std::cout << "Usage: " << argv[0]
                    << " [--print-parameters] [--dry-run] [file.prm]\n"
                       "--print-parameters prints every parameter with its "
                       "documentation (with a file: including the file's "
                       "subsections and values).\n"
                       "--dry-run reads and checks the file, then stops "
                       "(nothing is run or written).\n"
                    << (default_parameter_file.empty()
                            ? "A parameter file must be given."
                            : "Default parameter file: " +
                                  default_parameter_file)
                    << std::endl;
        return 0;
      }
      else if (!arg.empty() && arg[0] == '-')
      {
        if (root)
          std::cerr << "Error: unknown option '" << arg
                    << "'. Fix: use --print-parameters, --dry-run, --help or "
                       "the name of a .prm file."
                    << std::endl;
        return 1;
      }
      else
      {
        filename   = arg;
        file_given = true;
      }
    }
    if (filename.empty() && !print_parameters)
    {
      if (root)
        std::cerr << "Error: no parameter file given.\nFix: run " << argv[0]
                  << " file.prm (see " << argv[0]
                  << " --print-parameters for every entry)." << std::endl;
      return 1;
    }
    const ErrorCommunicator error_comm(comm);
    try
    {
      if (print_parameters)
        print_all_parameters(filename, file_given, root);
      else if (dry_run)
      {
        ParameterHandler prm;
        if (read_dimension(filename) == 2)
          read_parameters<2>(prm, filename);
        else
          read_parameters<3>(prm, filename);
        ProgramArguments::report_dry_run(
            name.empty() ? "softgrasp" : name, filename, root);
      }
      else if (read_dimension(filename) == 2)
        run_file<2>(comm, filename, report_2d);
      else
        run_file<3>(comm, filename, report_3d);
    }
    catch (const std::exception &e)
    {
      return fatal_error(e, error_comm);
    }
    return 0;
  }

  template void SolverProgram::read_parameters<2>(ParameterHandler &,
                                                  const std::string &);
  template void SolverProgram::read_parameters<3>(ParameterHandler &,
                                                  const std::string &);
} // namespace softgrasp
