#ifndef softgrasp_io_checkpoint_h
#define softgrasp_io_checkpoint_h

#include <boost/serialization/version.hpp>
#include <cstdint>
#include <deal.II/distributed/tria.h>
#include <ostream>
#include <softgrasp/mechanics/solid_system.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /**
   * What the data files of a checkpoint hold, recorded with them: a resume
   * checks it against its own mesh and element before it hands the data
   * to the solution transfer, whatever the manifest says.
   */
  struct CheckpointLayout
  {
    unsigned int       dim            = 0; ///< 0: not recorded (format 4)
    unsigned int       n_coarse_cells = 0;
    unsigned long long n_cells        = 0; ///< active cells, all ranks
    unsigned int       degree         = 0; ///< of the displacement element
    unsigned int       dofs_per_cell  = 0;
    unsigned long long n_dofs         = 0;
    unsigned int       n_fields       = 0; ///< displacement and the others

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &dim &n_coarse_cells &n_cells &degree &dofs_per_cell &n_dofs
          &n_fields;
    }
  };

  /// The scalar state of a run that a restart needs besides the fields.
  struct RunState
  {
    double                                      time      = 0; ///< s
    double                                      step_size = 0; ///< s
    unsigned int                                step      = 0;
    unsigned int                                n_outputs = 0;
    std::vector<std::string>                    history_columns;
    std::vector<std::vector<double>>            history_rows;
    std::vector<std::pair<double, std::string>> output_records;
    std::vector<std::string>                    contact_columns;
    std::vector<std::vector<double>>            contact_rows;
    /// Number of fields saved besides the displacement (e.g. velocity).
    unsigned int n_extra_fields = 0;
    /// The time integrator's own scalars (e.g. energy accumulators).
    std::vector<double> integrator_state;
    /// The typed contact force history, one packed record per step.
    std::vector<std::vector<double>> contact_force_records;

    /// What the data files hold (recorded since class version 1).
    CheckpointLayout layout;

    /**
     * The data files written with this state (the p4est mesh and the
     * fields), each with "<size> <checksum>" (since class version 2): the
     * state binds them to its layout, so a data file of another checkpoint
     * or run is refused by name on resume, whatever the manifest says.
     */
    std::vector<std::pair<std::string, std::string>> data_files;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int version)
    {
      archive &time &step_size &step &n_outputs &history_columns &history_rows
          &output_records &contact_columns &contact_rows &n_extra_fields
              &integrator_state &contact_force_records;
      if (version >= 1)
        archive &layout;
      if (version >= 2)
        archive &data_files;
    }
  };

  /**
   * Checkpoints of a run: the distributed mesh, the displacement and any
   * further fields (the velocity of an explicit run)
   * (p4est and deal.II's SolutionTransfer, so a run may restart on a
   * different number of ranks) and the RunState (Boost serialization).
   *
   * A checkpoint is written into "<directory>/checkpoint.new", completed by
   * a manifest (format version, size and checksum of every file, the
   * settings that must not change across a resume) and then renamed to
   * "<directory>/checkpoint"; the one before is kept as "checkpoint.old".
   * A resume validates the manifest, every file and the settings before it
   * touches p4est; a damaged newest checkpoint falls back to the previous
   * one; anything else stops with an InputError that names the cause. See
   * doc/reliability.md.
   */
  template <int dim> class Checkpoint
  {
  public:
    /// Entries (full .prm path, value) that a resume must not change.
    using Settings = std::vector<std::pair<std::string, std::string>>;

    Checkpoint(std::string directory, Settings settings);

    void save(const dealii::parallel::distributed::Triangulation<dim> &tria,
              const SolidSystem<dim>                                  &system,
              RunState                                                 state,
              const std::vector<const dealii::TrilinosWrappers::MPI::Vector *>
                  &extra = {}) const;

    /**
     * Load into @p tria (which holds the same coarse mesh as the saved run)
     * and @p system (set up here); returns the saved RunState. The fields
     * saved besides the displacement, @p n_extra of them, go into @p extra
     * (owned entries). The data are checked against the run's mesh,
     * element and fields before they are read: a mismatch is an
     * InputError naming both. Warnings (a damaged newest checkpoint) go
     * to @p log on rank 0.
     */
    RunState load(dealii::parallel::distributed::Triangulation<dim>  &tria,
                  SolidSystem<dim>                                   &system,
                  std::vector<dealii::TrilinosWrappers::MPI::Vector> &extra,
                  unsigned int                                        n_extra,
                  std::ostream &log) const;

    /// The manifest's format version (3: with the typed contact force
    /// history in the state; 4: with each geom's nodal normal force).
    static constexpr unsigned int format_version = 4;

  private:
    /// Rank 0: check the free space (twice the last checkpoint, or
    /// @p estimate bytes) and create the empty "checkpoint.new"; "" or the
    /// error.
    std::string prepare_folder(std::uintmax_t estimate) const;
    /// Rank 0: write @p state (with the data files' proofs) and the
    /// manifest into "checkpoint.new" and rename it into place, keeping the
    /// previous one; "" or the error.
    std::string complete(RunState state) const;
    /// The checkpoint to resume from, validated on rank 0, on all ranks.
    std::string select(MPI_Comm comm, std::ostream &log) const;
    /// Why @p path cannot be used ("" if it can); settings are not compared.
    std::string damage(const std::string &path) const;
    /// The settings that differ from @p path's manifest ("" if none).
    std::string changed_settings(const std::string &path) const;
    /// The manifest of the folder @p path: @p data_files (the run state's
    /// list, "<size> <checksum>" each) and state.txt.
    void write_manifest(const std::string &path,
                        const std::vector<std::pair<std::string, std::string>>
                            &data_files) const;

    std::string directory;
    Settings    settings;
  };
} // namespace softgrasp

BOOST_CLASS_VERSION(softgrasp::RunState, 2)

#endif
