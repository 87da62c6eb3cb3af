#ifndef softgrasp_mujoco_grasp_pull_sweep_h
#define softgrasp_mujoco_grasp_pull_sweep_h

#include <deal.II/base/parameter_handler.h>
#include <mpi.h>
#include <ostream>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grip_levels.h>
#include <softgrasp/mujoco/sweep_output.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /// The "Grasp-and-pull sweep" subsection, parsed once. SI units.
  struct SweepParameters
  {
    GripLevelSettings rigid; ///< levels, pull and MuJoCo's search settings
    /// The grip link as body/geom (the finite element label of the link).
    std::string grip_label;
    /// Coulomb's mu of the finite element pulls (1); < 0: the contact's.
    double pull_friction = -1;
    /// Load step (explicit: record interval) of the finite element
    /// closing (s); 0: 'Time/Time step'.
    double closing_step = 0;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The grasp-and-pull sweep (the source paper's second case study): at
   * grip levels from the equilibrium grip to the indented-state grip (a
   * normal force on the grip link), the hand pulls along the arm, in the
   * rigid simulator and on the finite element arm. See doc/studies.md.
   *
   * Its stages leave records in the output directory, so that a killed
   * sweep resumes where it stopped and the levels can run as separate jobs:
   *  - run_rigid(): MuJoCo closes the hand to the equilibrium state on the
   *    study's scene and records the closing, indentation and pull phases
   *    (the kinematics file), runs every level's grasp-and-pull
   *    (GraspSimulation::grip_levels()) and writes sweep_rigid_levels.csv,
   *    sweep_rigid_pulls.csv, the figure and sweep_rigid.h5; skipped when
   *    sweep_rigid.h5 holds the results of the same settings;
   *  - close(): the finite element arm closes to the levels' grip forces
   *    (PullSweepStudy::close_to_levels(), one record per level);
   *  - pull(k): level k's pull, unless its record says it is finished;
   *  - collect(): every level's record into sweep_fe_levels.csv,
   *    sweep_fe_pulls.csv and the figure with both lines.
   * The program studies/grasp_pull_sweep chooses the stages from its
   * command line.
   */
  class GraspPullSweep
  {
  public:
    /// Every entry the sweep reads: the rigid environment, the study's
    /// (@p declare_study) and the sweep's own subsection.
    static void declare_parameters(dealii::ParameterHandler &prm);

    /// @p study supplies the scene and the tissue; @p prm_file's directory
    /// resolves relative file names.
    GraspPullSweep(MPI_Comm                  comm,
                   dealii::ParameterHandler &prm,
                   const std::string        &prm_file,
                   PullSweepStudy           &study);

    /// The rigid stage (rank 0 works; errors reach every rank).
    void run_rigid(std::ostream &log);

    /// The finite element closing to levels 1 to @p up_to (0: all), after
    /// run_rigid(). Levels with a record are not closed again.
    void close(std::ostream &log, const unsigned int up_to = 0);

    /// Level @p k's pull (1-based), after close() reached it; a level
    /// already finished (pulled, failed or not reached) is left as it is,
    /// and one that the closing reached in the state of level k - 1 (the
    /// force rose past both between two records) takes that level's pull.
    void pull(const unsigned int k, std::ostream &log);

    /// Every level's record into the tables and the figure (rank 0
    /// writes); the levels without one are listed in @p log.
    void collect(std::ostream &log);

    /// close(), every level's pull(), collect().
    void run_fe(std::ostream &log);

    /// The finite element levels: those of the last close() and pull(),
    /// all of them after collect().
    const std::vector<FeGripLevel> &fe_levels() const
    {
      return fe;
    }

    /// The rigid simulator's levels of the last run_rigid() that ran
    /// MuJoCo (rank 0; empty if its record was reused).
    const std::vector<RigidGripLevel> &rigid_levels() const
    {
      return rigid;
    }

    const SweepParameters &parameters() const
    {
      return sweep;
    }

    /// The grip forces of the levels (N; all ranks, after run_rigid()).
    const std::vector<double> &grip_forces() const
    {
      return record.targets;
    }

  private:
    /// The figure with the rigid points and @p fe's (rank 0).
    void figure(const std::vector<FeGripLevel> &fe, std::ostream &log) const;

    MPI_Comm                    comm;
    PullSweepStudy             &study;
    GraspParameters             grasp;
    SweepParameters             sweep;
    std::string                 directory; ///< 'Output/Directory'
    std::string                 settings;  ///< what the rigid stage reads
    std::vector<RigidGripLevel> rigid;
    RigidSweepRecord            record; ///< of the rigid stage, all ranks
    std::vector<FeGripLevel>    fe;
  };

} // namespace softgrasp

#endif
