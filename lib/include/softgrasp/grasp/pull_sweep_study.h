#ifndef softgrasp_grasp_pull_sweep_study_h
#define softgrasp_grasp_pull_sweep_study_h

#include <optional>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/grasp/link_force_history.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /// One grip level of the finite element arm.
  struct FeGripLevel
  {
    double      target_force  = 0;     ///< N on the grip link
    double      reached_force = 0;     ///< N at the first record at or above it
    double      time          = 0;     ///< s of the indentation phase there
    bool        reached       = false; ///< false: the closure ended below it
    bool        pulled        = false; ///< the pull ran to its end
    std::string failure;               ///< why the pull stopped, if it did
    std::string settings; ///< PullSweepStudy::settings_text() of its run
    /// The level (1-based) whose closed state this one is: itself, or the
    /// level below when the closing reached both in one state (or neither);
    /// 0 in records of older sweeps (taken as its own).
    unsigned int state_level = 0;
    /// The checksum of the closed state's checkpoint manifest (which holds
    /// the checksum of every file of that state) when the level was closed:
    /// a pull starts only from the state its record was closed to. Empty if
    /// not reached, or in records of older sweeps (not checked).
    std::string closed_state;
    /// At the end of the pull: |sum F_links - R| / max |F_link| and the
    /// deepest penetration of a link (m).
    double balance = 0, penetration = 0;
    /// Every link's forces over the pull (time from the level's start).
    std::vector<LinkForceHistory> links;

    /// Nothing is left to compute: pulled, failed, or not reachable.
    bool finished() const
    {
      return pulled || !failure.empty() || !reached;
    }
  };

  /// Write @p level to @p filename (HDF5, whole or not at all; rank 0):
  /// the record a resumed or collecting sweep reads back.
  void write_grip_level(const FeGripLevel &level, const std::string &filename);

  /// The level written by write_grip_level(); an InputError naming the
  /// file and the fix if it is missing or damaged.
  FeGripLevel read_grip_level(const std::string &filename);

  /**
   * The finite element half of the grasp-and-pull sweep on the arm (the
   * source paper's second case study), on the arm grasp's tissue and
   * solver settings:
   *
   *  - close_to_levels(): one run along the recorded indentation phase
   *    (directory <output>/fe_closing) stops at the first record where the
   *    grip link's normal force reaches each level's force; its state there
   *    is kept in <output>/level_<k>/closed/checkpoint and the level's
   *    closing record in closing_file(k); the run goes on to the next level
   *    from it. A killed sweep goes on from the closing's latest
   *    checkpoint; a level whose closing record is gone (deleted, damaged)
   *    is closed again from the closed state of the nearest level below it
   *    (or from the start), never from a later state, together with the
   *    levels that share its state.
   *  - pull(k): from level k's closed state (directory <output>/level_<k>),
   *    every link moves on the recorded pull phase's motion, relative to
   *    where the pull started, applied to the link's pose at the level
   *    (the finger joints hold the level's closure; the base slides); the
   *    humerus stays fixed. A killed pull resumes from its own latest
   *    checkpoint; a finished one writes record_file(k) and removes its
   *    checkpoints, so that deleting the record pulls the level again from
   *    its closed state.
   *
   * It is composed of the arm grasp (arm()), whose tissue, solver settings
   * and rigid scene it uses; it does not extend it.
   */
  class PullSweepStudy
  {
  public:
    PullSweepStudy(MPI_Comm comm, dealii::ParameterHandler &prm);

    /// The arm grasp of the .prm: the tissue, the solver settings, the
    /// kinematics file and the rigid scene of the sweep.
    const ArmGraspStudy &arm() const
    {
      return arm_study;
    }

    /**
     * Close along the 'indentation' phase of @p kinematics until the
     * normal force on @p grip_link (body/geom) reaches each of @p forces
     * (N, increasing), with load steps (explicit: records) of @p step
     * (s; 0: 'Time/Time step'). Returns one FeGripLevel per force; levels
     * with a record are read, not closed again.
     */
    std::vector<FeGripLevel> close_to_levels(const KinematicsData &kinematics,
                                             const std::string    &grip_link,
                                             const std::vector<double> &forces,
                                             std::ostream              &log,
                                             const double step = 0);

    /// The pull of @p level (1-based number @p k), which close_to_levels()
    /// reached; fills its links, pulled and failure, and records it. A
    /// killed pull resumes from its latest checkpoint. @p friction >= 0
    /// replaces 'Contact/Friction coefficient' during the pull (a branch
    /// from the level's state: 0 leaves only the tissue's pressure).
    void pull(const KinematicsData &kinematics,
              const unsigned int    k,
              FeGripLevel          &level,
              const double          friction = -1);

    /// Every parameter but 'Output/...' and 'Checkpoint/...' as
    /// "path = value" lines: what the results of a sweep depend on.
    /// Records carry it; a record of other settings is refused, but for
    /// the time steps (numerical settings of what is still to compute).
    const std::string &settings_text() const
    {
      return settings;
    }

    /// <output>/level_<k> (k 1-based, two digits).
    std::string level_directory(const unsigned int k) const;

    /// The record of level @p k after its pull: <output>/level_<k>/level.h5.
    std::string record_file(const unsigned int k) const;

    /// The record of level @p k's closing: <output>/level_<k>/closing.h5.
    std::string closing_file(const unsigned int k) const;

    /// The records of the first levels of @p forces (N) that have one, in
    /// order up to the first without; an InputError if a record is damaged,
    /// of other settings, or was closed to another force.
    std::vector<FeGripLevel>
    recorded_levels(const std::vector<double> &forces) const;

    /// Write @p level as level @p k's record (rank 0; all ranks wait):
    /// its closing record, or, once pulled (or failed), its full record.
    void record(const FeGripLevel &level, const unsigned int k) const;

  private:
    /**
     * Every level's record (the full one, else the closing one), or none.
     * A level without its closing record has none (its other files are
     * removed: it is computed again). With @p log, a level still to pull
     * whose closed state is not the one its record was closed to (swapped,
     * copied from another level) loses its record too, and @p log says so.
     */
    std::vector<std::optional<FeGripLevel>>
    read_records(const std::vector<double> &forces,
                 std::ostream              *log = nullptr) const;
    /// Remove level @p k's records and closed state (rank 0; all wait).
    void forget_level(const unsigned int k) const;
    /// The checksum of level @p k's closed state's checkpoint manifest, ""
    /// if it has none (FeGripLevel::closed_state).
    std::string closed_state_of(const unsigned int k) const;
    /// Drop the records of the levels that share the state of a level
    /// without one (they are closed again together), with their files.
    void drop_shared(std::vector<std::optional<FeGripLevel>> &records) const;
    /// Point the closing at a state below level @p m's force: the closed
    /// state of the nearest level below that owns one, or the start;
    /// returns whether a state is there to resume from.
    bool restart_closing_below(
        const unsigned int                             m,
        const std::vector<std::optional<FeGripLevel>> &records) const;
    /// The highest level the closing's latest checkpoint may have passed
    /// (<output>/closing_progress.txt), -1 if that file is missing or
    /// damaged (then it may have passed any), and its update.
    int  closing_progress() const;
    void set_closing_progress(const unsigned int k) const;
    /// Close to level @p k (0-based) of @p forces from where the closing
    /// is; @p levels holds the levels below it.
    FeGripLevel close_one(SolverInputs<3>                             &inputs,
                          const std::pair<unsigned int, unsigned int> &grip,
                          const std::vector<FeGripLevel>              &levels,
                          const std::vector<double>                   &forces,
                          const unsigned int                           k,
                          bool &started) const;

    MPI_Comm      comm;
    ArmGraspStudy arm_study;
    std::string   output;   ///< the study's 'Output/Directory'
    std::string   settings; ///< settings_text()
  };

  /**
   * The kinematics of a pull from the state at time @p t (s, relative to
   * the start of @p closing): @p closing's samples up to @p t (and one at
   * @p t), then every body moved by its motion in @p pull relative to the
   * pull's first sample, applied to its pose at @p t. Both inputs are
   * slices (time from 0); so is the result, and it has the phases
   * "indentation" (0 to t) and "pull".
   */
  KinematicsData pull_from(const KinematicsData &closing,
                           const KinematicsData &pull,
                           const double          t);
} // namespace softgrasp

#endif
