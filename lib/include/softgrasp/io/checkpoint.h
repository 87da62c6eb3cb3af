#ifndef softgrasp_io_checkpoint_h
#define softgrasp_io_checkpoint_h

#include <deal.II/distributed/tria.h>
#include <ostream>
#include <softgrasp/mechanics/solid_system.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
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

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &time &step_size &step &n_outputs &history_columns &history_rows
          &output_records &contact_columns &contact_rows &n_extra_fields
              &integrator_state &contact_force_records;
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
     * saved besides the displacement go into @p extra (owned entries).
     * Warnings (a damaged newest checkpoint) go to @p log on rank 0.
     */
    RunState load(dealii::parallel::distributed::Triangulation<dim>  &tria,
                  SolidSystem<dim>                                   &system,
                  std::vector<dealii::TrilinosWrappers::MPI::Vector> &extra,
                  std::ostream &log) const;

    /// The manifest's format version (3: with the typed contact force
    /// history in the state; 4: with each geom's nodal normal force).
    static constexpr unsigned int format_version = 4;

  private:
    /// The checkpoint to resume from, validated on rank 0, on all ranks.
    std::string select(MPI_Comm comm, std::ostream &log) const;
    /// Why @p path cannot be used ("" if it can); settings are not compared.
    std::string damage(const std::string &path) const;
    /// The settings that differ from @p path's manifest ("" if none).
    std::string changed_settings(const std::string &path) const;
    void        write_manifest(const std::string &path) const;

    std::string directory;
    Settings    settings;
  };
} // namespace softgrasp

#endif
