#ifndef softgrasp_solvers_solver_program_h
#define softgrasp_solvers_solver_program_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The main() of a solver program, shared by the examples:
   *
   *   program [--print-parameters] [--dry-run] [file.prm]
   *
   * reads "Dimension" (2: plane strain, 3) and then the whole file with
   * every declaration pass, runs the Simulation<dim> that
   * 'Time/Integrator' names (quasi-static or explicit), and turns input
   * errors and solver failures into a message on stderr and exit code 1.
   * @p after_run, if given, is called on rank 0 and all ranks after a
   * successful run with the solver (as Simulation<2> or <3>) to
   * report results; use the overloads below.
   *
   * MPI must be initialised by the caller (Utilities::MPI::MPI_InitFinalize).
   */
  template <int dim> class Simulation;

  struct SolverProgram
  {
    std::string default_parameter_file;
    /// The program's name (ParameterReader::set_program()) and the other
    /// programs whose files it runs.
    std::string                                name;
    std::vector<std::string>                   reads_files_of;
    std::function<void(const Simulation<2> &)> report_2d;
    std::function<void(const Simulation<3> &)> report_3d;

    int run(int argc, char **argv) const;

    /// Read @p filename's "Dimension" entry (2 or 3).
    static unsigned int read_dimension(const std::string &filename);

    /// Declare and read everything a Simulation<dim> needs.
    template <int dim>
    static void read_parameters(dealii::ParameterHandler &prm,
                                const std::string        &filename);
  };
} // namespace softgrasp

#endif
