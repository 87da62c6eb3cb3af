#include <softgrasp/base/input_error.h>
#include <softgrasp/io/hdf5_history.h>
#include <softgrasp/solvers/run_recorder.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    std::vector<std::string> names_of(const HistoryValues &row)
    {
      std::vector<std::string> names;
      names.reserve(row.size());
      for (const auto &entry : row)
        names.push_back(entry.first);
      return names;
    }

    std::vector<double> values_of(const HistoryValues &row)
    {
      std::vector<double> values;
      values.reserve(row.size());
      for (const auto &entry : row)
        values.push_back(entry.second);
      return values;
    }

    /// Append @p row to @p table: its names become the columns of an
    /// empty table and must equal them otherwise.
    void append(HistoryWriter &table, const HistoryValues &row)
    {
      const auto names = names_of(row);
      if (table.columns.empty())
        table.set_columns(names);
      else if (names != table.columns)
        throw InputError(
            "The history table '" + table.filename + "' has " +
            std::to_string(table.columns.size()) +
            " columns, and this run records " + std::to_string(names.size()) +
            " other ones: it continues a run of another 'Time/Integrator' or "
            "other outputs (monitor points, boundary ids). Fix: resume with "
            "the settings of the run that wrote the checkpoint, or start "
            "afresh ('Checkpoint/Resume = false').");
      table.add_row(values_of(row));
    }
  } // namespace

  template <int dim>
  RunRecorder<dim>::RunRecorder(const OutputParameters            &output,
                                typename Checkpoint<dim>::Settings settings)
      : output(output)
      , field_output(output.directory, output.base_name)
      , history_table(output.directory + "/" + output.base_name +
                      "_history.csv")
      , contact_table(output.directory + "/" + output.base_name +
                      "_contact.csv")
      , checkpoint(output.directory, std::move(settings))
  {
  }

  template <int dim>
  void RunRecorder<dim>::claim_directory(MPI_Comm comm, const bool resume)
  {
    run_directory = std::make_unique<RunDirectory>(comm,
                                                   output.directory,
                                                   output.existing_results,
                                                   resume,
                                                   output.base_name,
                                                   std::cout);
  }

  template <int dim> void RunRecorder<dim>::release_directory()
  {
    run_directory.reset();
  }

  template <int dim> void RunRecorder<dim>::start_fresh()
  {
    history_table.columns.clear();
    history_table.rows.clear();
    contact_table.columns.clear();
    contact_table.rows.clear();
    contact_records.clear();
    field_output.records.clear();
    last_output_step = static_cast<unsigned int>(-1);
  }

  template <int dim>
  void RunRecorder<dim>::add_history_row(const HistoryValues &row)
  {
    append(history_table, row);
  }

  template <int dim>
  void RunRecorder<dim>::add_contact_row(ContactForceRecord   record,
                                         const HistoryValues &row)
  {
    append(contact_table, row);
    contact_records.push_back(std::move(record));
  }

  template <int dim> void RunRecorder<dim>::write_tables() const
  {
    history_table.write();
    if (contact_table.columns.empty())
      return;
    contact_table.write();
    write_history_hdf5(contact_table,
                       output.directory + "/" + output.base_name +
                           "_contact.h5",
                       "softgrasp contact history 1",
                       dim);
  }

  template <int dim>
  bool RunRecorder<dim>::fields_written_at(const unsigned int step) const
  {
    return last_output_step == step;
  }

  template <int dim>
  void RunRecorder<dim>::write_fields(
      const SolidSystem<dim>                       &system,
      const MaterialLibrary                        &materials,
      const double                                  time,
      RunState                                     &state,
      const typename FieldOutput<dim>::ExtraFields &extra)
  {
    if (fields_written_at(state.step))
      return;
    field_output.write(system, materials, time, state.n_outputs++, extra);
    last_output_step = state.step;
  }

  template <int dim>
  void RunRecorder<dim>::write_checkpoint(
      const parallel::distributed::Triangulation<dim>          &tria,
      const SolidSystem<dim>                                   &system,
      RunState                                                 &state,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &extra) const
  {
    state.history_columns = history_table.columns;
    state.history_rows    = history_table.rows;
    state.output_records  = field_output.records;
    state.contact_columns = contact_table.columns;
    state.contact_rows    = contact_table.rows;
    state.contact_force_records.clear();
    for (const auto &record : contact_records)
      state.contact_force_records.push_back(record.pack());
    checkpoint.save(tria, system, state, extra);
  }

  template <int dim>
  RunState RunRecorder<dim>::load_checkpoint(
      parallel::distributed::Triangulation<dim>  &tria,
      SolidSystem<dim>                           &system,
      std::vector<TrilinosWrappers::MPI::Vector> &fields,
      const unsigned int                          n_fields,
      std::ostream                               &log)
  {
    RunState state = checkpoint.load(tria, system, fields, n_fields, log);
    history_table.columns = state.history_columns;
    history_table.rows    = state.history_rows;
    contact_table.columns = state.contact_columns;
    contact_table.rows    = state.contact_rows;
    contact_records.clear();
    for (const auto &packed : state.contact_force_records)
      contact_records.push_back(ContactForceRecord::unpack(packed));
    field_output.records = state.output_records;
    last_output_step     = static_cast<unsigned int>(-1);
    return state;
  }

  template <int dim> const HistoryWriter &RunRecorder<dim>::history() const
  {
    return history_table;
  }

  template <int dim>
  const HistoryWriter &RunRecorder<dim>::contact_history() const
  {
    return contact_table;
  }

  template <int dim>
  const std::vector<ContactForceRecord> &
  RunRecorder<dim>::contact_forces() const
  {
    return contact_records;
  }

  template <int dim> ProgressReporter &RunRecorder<dim>::progress()
  {
    return progress_reporter;
  }

  template class RunRecorder<2>;
  template class RunRecorder<3>;
} // namespace softgrasp
