#ifndef softgrasp_mujoco_grasp_pull_sweep_h
#define softgrasp_mujoco_grasp_pull_sweep_h

#include <deal.II/base/parameter_handler.h>
#include <mpi.h>
#include <ostream>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grip_levels.h>
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

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The grasp-and-pull sweep (the source paper's second case study): at
   * grip levels from the equilibrium grip to the indented-state grip (a
   * normal force on the grip link), the hand pulls along the arm, in the
   * rigid simulator and on the finite element arm. See doc/studies.md.
   *
   * run_rigid(): MuJoCo closes the hand to the equilibrium state on the
   * study's scene and records the closing, indentation and pull phases
   * (the kinematics file), then runs every level's grasp-and-pull
   * (GraspSimulation::grip_levels()) and writes sweep_rigid_levels.csv,
   * sweep_rigid_pulls.csv and the figure into the output directory.
   *
   * run_fe(): the finite element arm closes to the same grip forces
   * (PullSweepStudy::close_to_levels()) and pulls at every level it
   * reaches; writes sweep_fe_levels.csv, sweep_fe_pulls.csv and the figure
   * with both lines.
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

    /**
     * The program: grasp_pull_sweep [--print-parameters] [file.prm]
     * (default sweep file grasp_pull_sweep.prm). Errors become a message
     * on stderr and exit code 1. MPI must be initialised by the caller.
     */
    static int main(int argc, char **argv);

    /// The rigid stage (rank 0 works; errors reach every rank).
    void run_rigid(std::ostream &log);

    /// The finite element stage (all ranks), after run_rigid().
    void run_fe(std::ostream &log);

    /// The finite element levels of the last run_fe().
    const std::vector<FeGripLevel> &fe_levels() const
    {
      return fe;
    }

    /// The rigid simulator's levels of the last run_rigid() (rank 0).
    const std::vector<RigidGripLevel> &rigid_levels() const
    {
      return rigid;
    }

    const SweepParameters &parameters() const
    {
      return sweep;
    }

  private:
    MPI_Comm                    comm;
    PullSweepStudy             &study;
    GraspParameters             grasp;
    SweepParameters             sweep;
    std::string                 directory; ///< 'Output/Directory'
    std::vector<RigidGripLevel> rigid;
    std::vector<double>         targets;      ///< N, every level (all ranks)
    double                      friction = 0; ///< MuJoCo's, for the figure
    std::vector<FeGripLevel>    fe;
  };

  /**
   * The rigid simulator's grip levels as tables:
   *  - @p summary_file: one row per level and link: the target and reached
   *    grip force and the closure of the level, then the link's normal,
   *    lateral and drag force at the end of the pull, their means over the
   *    second half of it and their maxima over it, its slip speed at the
   *    end and whether it slides;
   *  - @p pulls_file: every sample of every pull (level, time, slide, then
   *    per link normal, lateral, drag and slip speed).
   * Both written whole or not at all (AtomicFile). Units: N, m, s, rad.
   */
  void write_rigid_levels(const std::vector<RigidGripLevel> &levels,
                          const std::string                 &summary_file,
                          const std::string                 &pulls_file);

  /// One grip level's point of the sweep's figure (N): the grip force the
  /// level reached, and the grip link's normal and lateral force averaged
  /// over the second half of the pull (steady sliding or sticking) and the
  /// largest lateral force over the pull.
  struct SweepPoint
  {
    unsigned int level = 0;
    double grip_force = 0, normal_mean = 0, lateral_mean = 0, lateral_max = 0;
    double friction_mean = 0; ///< finite elements: friction-only part
  };

  /// The grip link's points of @p levels (one per level).
  std::vector<SweepPoint>
  grip_link_points(const std::vector<RigidGripLevel> &levels,
                   const std::string                 &grip_geom);

  /// The grip link's points of the finite element levels that were pulled
  /// (means over the second half of the pull).
  std::vector<SweepPoint> grip_link_points(const std::vector<FeGripLevel> &fe,
                                           const std::string &grip_label);

  /**
   * The finite element levels as tables: @p summary_file, one row per level
   * and link (target and reached grip force, closure time, whether pulled,
   * the link's normal, lateral and friction-only force at the end of the
   * pull and their means over its second half); @p pulls_file, every
   * record of every pull. Units: N, s.
   */
  void write_fe_levels(const std::vector<FeGripLevel> &levels,
                       const std::string              &summary_file,
                       const std::string              &pulls_file);

  /**
   * The sweep's figure (PNG, as the paper's fig. 10) in @p directory:
   * lateral against normal force on the grip link, the rigid simulator's
   * levels as one line and the finite element levels as another, points
   * coloured by level, with the line mu N; a second panel splits the
   * finite element lateral force into its friction-only part and the rest
   * (pressure of the tissue against the link) per level. Data in
   * <base>_figure.dat, the script <base>_figure.gnuplot.
   */
  void write_sweep_figure(const std::vector<SweepPoint> &rigid,
                          const std::vector<SweepPoint> &fe,
                          const double                   friction,
                          const std::string             &grip_link,
                          const std::string             &directory,
                          const std::string             &base,
                          std::ostream                  &log);
} // namespace softgrasp

#endif
