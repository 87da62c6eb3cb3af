#ifndef softgrasp_io_checkpoint_h
#define softgrasp_io_checkpoint_h

#include <deal.II/distributed/tria.h>
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

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &time &step_size &step &n_outputs &history_columns &history_rows
          &output_records &contact_columns &contact_rows &n_extra_fields
              &integrator_state;
    }
  };

  /**
   * Checkpoints of a run: the distributed mesh, the displacement and any
   * further fields (the velocity of an explicit run)
   * (p4est and deal.II's SolutionTransfer, so a run may restart on a
   * different number of ranks) and the RunState (Boost serialization).
   *
   * A checkpoint is written into "<directory>/checkpoint.new" and then
   * renamed to "<directory>/checkpoint", keeping the previous one as
   * "checkpoint.old" until the rename is done: a run killed at any moment
   * leaves at least one complete checkpoint.
   */
  template <int dim> class Checkpoint
  {
  public:
    explicit Checkpoint(std::string directory);

    void save(const dealii::parallel::distributed::Triangulation<dim> &tria,
              const SolidSystem<dim>                                  &system,
              RunState                                                 state,
              const std::vector<const dealii::TrilinosWrappers::MPI::Vector *>
                  &extra = {}) const;

    /// True if a complete checkpoint exists.
    bool exists() const;

    /**
     * Load into @p tria (which holds the same coarse mesh as the saved run)
     * and @p system (set up here); returns the saved RunState. The fields
     * saved besides the displacement go into @p extra (owned entries).
     */
    RunState
    load(dealii::parallel::distributed::Triangulation<dim>  &tria,
         SolidSystem<dim>                                   &system,
         std::vector<dealii::TrilinosWrappers::MPI::Vector> &extra) const;

  private:
    std::string complete_directory() const;
    std::string directory;
  };
} // namespace softgrasp

#endif
