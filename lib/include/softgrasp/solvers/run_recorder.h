#ifndef softgrasp_solvers_run_recorder_h
#define softgrasp_solvers_run_recorder_h

#include <deal.II/distributed/tria.h>
#include <memory>
#include <softgrasp/base/progress_reporter.h>
#include <softgrasp/base/run_directory.h>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/io/checkpoint.h>
#include <softgrasp/io/field_output.h>
#include <softgrasp/io/history_writer.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /// Named scalars of one recorded step, (column name, value), in the
  /// order of the history's columns.
  using HistoryValues = std::vector<std::pair<std::string, double>>;

  /**
   * Everything a run writes, and the run's progress: the output directory
   * (lock, earlier results, manifest), the history table (CSV) and the
   * contact history (CSV, HDF5, typed records), the field output (VTU,
   * PVD) and the checkpoints. A history row is a named record: a fresh
   * run takes its columns from the first row, and every later row (and a
   * resumed run's first) must have the same names, so that a value never
   * lands in another quantity's column.
   */
  template <int dim> class RunRecorder
  {
  public:
    RunRecorder(const OutputParameters            &output,
                typename Checkpoint<dim>::Settings settings);

    /// Lock the output directory; a new run (@p resume false) clears an
    /// earlier run's results as 'Output/Existing results' says.
    void claim_directory(MPI_Comm comm, bool resume);
    /// Give up the output directory (before a new claim).
    void release_directory();

    /// Forget the tables of an earlier run() of the same object.
    void start_fresh();

    /// Append a history row; throws if its names differ from the columns.
    void add_history_row(const HistoryValues &row);
    /// Append a contact row and its typed record.
    void add_contact_row(ContactForceRecord record, const HistoryValues &row);
    /// Write the tables (rank 0 only).
    void write_tables() const;

    /// Whether the fields of step @p step have been written.
    bool fields_written_at(const unsigned int step) const;
    /// VTU of @p system at @p time, once per step @p state.step.
    void write_fields(const SolidSystem<dim>                       &system,
                      const MaterialLibrary                        &materials,
                      const double                                  time,
                      RunState                                     &state,
                      const typename FieldOutput<dim>::ExtraFields &extra);

    /// Checkpoint of @p system with @p state (which gets the tables).
    void write_checkpoint(
        const dealii::parallel::distributed::Triangulation<dim> &tria,
        const SolidSystem<dim>                                  &system,
        RunState                                                &state,
        const std::vector<const dealii::TrilinosWrappers::MPI::Vector *> &extra)
        const;

    /// Load the newest usable checkpoint into @p tria and @p system, with
    /// @p n_fields fields besides the displacement; the tables continue
    /// from it. Returns its RunState.
    RunState
    load_checkpoint(dealii::parallel::distributed::Triangulation<dim>  &tria,
                    SolidSystem<dim>                                   &system,
                    std::vector<dealii::TrilinosWrappers::MPI::Vector> &fields,
                    unsigned int  n_fields,
                    std::ostream &log);

    const HistoryWriter                   &history() const;
    const HistoryWriter                   &contact_history() const;
    const std::vector<ContactForceRecord> &contact_forces() const;
    ProgressReporter                      &progress();

  private:
    OutputParameters                output;
    FieldOutput<dim>                field_output;
    HistoryWriter                   history_table;
    HistoryWriter                   contact_table;
    std::vector<ContactForceRecord> contact_records;
    Checkpoint<dim>                 checkpoint;
    std::unique_ptr<RunDirectory>   run_directory;
    ProgressReporter                progress_reporter;
    /// The step whose fields were written last (none: -1).
    unsigned int last_output_step = static_cast<unsigned int>(-1);
  };
} // namespace softgrasp

#endif
