#ifndef softgrasp_mujoco_grasp_study_program_h
#define softgrasp_mujoco_grasp_study_program_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace softgrasp
{
  class IndentationStudy;

  /**
   * The main() of a grasp study (studies/sphere_squeeze, ...):
   *
   *   program [--print-parameters] [--dry-run] [file.prm]
   *
   * reads the .prm ("Rigid environment", "Indentation study" and everything
   * a Simulation<3> reads), then
   *  1. if "Indentation study/Rigid stage" is "run": MuJoCo closes the hand
   *     to the equilibrium grasp and records the indentation phase
   *     (GraspSimulation, on rank 0) into the kinematics file;
   *  2. reads the kinematics file and runs the finite element indentation
   *     (IndentationStudy) on all ranks.
   * Errors become a message on stderr and exit code 1. @p report, if set,
   * is called after a successful run (all ranks).
   *
   * MPI must be initialised by the caller.
   */
  struct GraspStudyProgram
  {
    std::string default_parameter_file;
    /// The program's name (ParameterReader::set_program()) and the other
    /// programs whose files it reads (mujoco_grasp: sphere_squeeze's).
    std::string              name;
    std::vector<std::string> reads_files_of;
    /// Run the rigid stage only (write the kinematics file and stop).
    bool                                          rigid_only = false;
    std::function<void(const IndentationStudy &)> report;
    /// Declare the study's entries (default: IndentationStudy's).
    std::function<void(dealii::ParameterHandler &)> declare_study_parameters;
    /// Build the study from the parsed .prm (default: an IndentationStudy;
    /// e.g. an ArmGraspStudy).
    std::function<std::unique_ptr<IndentationStudy>(MPI_Comm,
                                                    dealii::ParameterHandler &)>
        make_study;

    int run(int argc, char **argv) const;
  };
} // namespace softgrasp

#endif
