#include <algorithm>
#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <softgrasp/base/file_checksum.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/io/checkpoint.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;
  namespace fs = std::filesystem;

  namespace
  {
    const char *const manifest_name = "manifest.txt";

    /// What a manifest records.
    struct Manifest
    {
      unsigned int                       version = 0;
      unsigned int                       dim     = 0;
      std::map<std::string, std::string> files; // name -> "size checksum"
      std::vector<std::pair<std::string, std::string>> settings;
      bool                                             complete = false;
    };

    Manifest read_manifest(const fs::path &file)
    {
      Manifest      m;
      std::ifstream in(file);
      std::string   line;
      if (!std::getline(in, line) ||
          line.rfind("softgrasp checkpoint ", 0) != 0)
        return m;
      m.version = std::atoi(line.c_str() + 21);
      while (std::getline(in, line))
      {
        std::istringstream words(line);
        std::string        key;
        words >> key;
        if (key == "dimension")
          words >> m.dim;
        else if (key == "file")
        {
          std::string name, size, sum;
          words >> name >> size >> sum;
          m.files[name] = size + " " + sum;
        }
        else if (key == "setting")
        {
          const auto equal = line.find(" = ");
          if (equal != std::string::npos)
            m.settings.emplace_back(line.substr(8, equal - 8),
                                    line.substr(equal + 3));
        }
        else if (key == "end")
          m.complete = true;
      }
      return m;
    }
    /// The layout of @p n_fields fields of @p system on @p tria.
    template <int dim>
    CheckpointLayout
    layout_of(const parallel::distributed::Triangulation<dim> &tria,
              const SolidSystem<dim>                          &system,
              const unsigned int                               n_fields)
    {
      CheckpointLayout layout;
      layout.dim            = dim;
      layout.n_coarse_cells = tria.n_cells(0);
      layout.n_cells        = tria.n_global_active_cells();
      layout.degree         = system.fe().degree;
      layout.dofs_per_cell  = system.fe().n_dofs_per_cell();
      layout.n_dofs         = system.n_dofs();
      layout.n_fields       = n_fields;
      return layout;
    }

    /// The files of the checkpoint folder @p path that p4est and the
    /// solution transfer wrote, each with "<size> <checksum>".
    std::vector<std::pair<std::string, std::string>>
    data_files_in(const std::string &path)
    {
      std::vector<std::pair<std::string, std::string>> files;
      for (const auto &entry : fs::directory_iterator(path))
      {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name != manifest_name &&
            name != "state.txt")
          files.emplace_back(name, entry_fingerprint(entry.path()));
      }
      std::sort(files.begin(), files.end());
      return files;
    }

    /**
     * Why the data files in @p path are not the ones written with @p state
     * (a file copied from another checkpoint or run, with its manifest
     * line); "" if they are, or if @p state predates the record.
     */
    std::string foreign_data(const std::string &path, const RunState &state)
    {
      const CheckpointLayout &l = state.layout;
      for (const auto &[name, proof] : state.data_files)
        if (const auto found = entry_fingerprint(fs::path(path) / name);
            found != proof)
          return "its data file '" + name + "' is not the one written with " +
                 "its run state (a " + std::to_string(l.dim) + "D mesh of " +
                 std::to_string(l.n_cells) + " cells, degree " +
                 std::to_string(l.degree) + " elements, " +
                 std::to_string(l.n_dofs) + " dofs, " +
                 std::to_string(l.n_fields) + " field(s)): its size and " +
                 "checksum are '" + (found.empty() ? "missing" : found) +
                 "', the state records '" + proof +
                 "' (a file copied from another checkpoint or run)";
      return "";
    }

    /// Why data of layout @p saved cannot be read into a run of layout
    /// @p run; "" if they can. @p compare_cells: after the mesh was loaded.
    std::string mismatch(const CheckpointLayout &saved,
                         const CheckpointLayout &run,
                         const bool              compare_cells)
    {
      std::ostringstream why;
      if (saved.dim != run.dim)
        why << "its data are of a " << saved.dim << "D run, this run is "
            << run.dim << "D";
      else if (saved.n_coarse_cells != run.n_coarse_cells)
        why << "its mesh has " << saved.n_coarse_cells
            << " coarse cells, this run's " << run.n_coarse_cells
            << " (another 'Mesh')";
      else if (compare_cells && saved.n_cells != run.n_cells)
        why << "its state belongs to a mesh of " << saved.n_cells
            << " cells, its mesh file has " << run.n_cells
            << " (files of two checkpoints)";
      else if (compare_cells && (saved.degree != run.degree ||
                                 saved.dofs_per_cell != run.dofs_per_cell ||
                                 saved.n_dofs != run.n_dofs))
        why << "its data are of degree " << saved.degree << " elements ("
            << saved.dofs_per_cell << " dofs per cell, " << saved.n_dofs
            << " dofs), this run's of degree " << run.degree << " ("
            << run.dofs_per_cell << " dofs per cell, " << run.n_dofs
            << " dofs)";
      else if (saved.n_fields != run.n_fields)
        why << "it holds " << saved.n_fields - 1
            << " field(s) besides the displacement, this run needs "
            << run.n_fields - 1
            << ": it was written by another time integrator (or, for the "
               "explicit one, with 'Explicit dynamics/Stiffness damping' "
               "switched on or off)";
      return why.str();
    }
  } // namespace

  template <int dim>
  Checkpoint<dim>::Checkpoint(std::string directory, Settings settings)
      : directory(std::move(directory))
      , settings(std::move(settings))
  {
  }

  template <int dim>
  void Checkpoint<dim>::write_manifest(
      const std::string                                      &path,
      const std::vector<std::pair<std::string, std::string>> &data_files) const
  {
    // the data files' proofs as the run state lists them (hashed once),
    // and the state itself
    auto files = data_files;
    files.emplace_back("state.txt",
                       entry_fingerprint(fs::path(path) / "state.txt"));
    std::sort(files.begin(), files.end());
    std::ostringstream out;
    out << "softgrasp checkpoint " << format_version << "\ndimension " << dim
        << "\n";
    for (const auto &[name, proof] : files)
      out << "file " << name << " " << proof << "\n";
    for (const auto &[name, value] : settings)
      out << "setting " << name << " = " << value << "\n";
    out << "end\n";
    std::ofstream file(fs::path(path) / manifest_name);
    file << out.str();
    file.close();
    if (!file)
      throw InputError("Cannot write the checkpoint manifest in '" + path +
                       "'. Fix: check that the disk is not full and the "
                       "directory is writable.");
  }

  template <int dim>
  void Checkpoint<dim>::save(
      const parallel::distributed::Triangulation<dim>          &tria,
      const SolidSystem<dim>                                   &system,
      RunState                                                  state,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &extra) const
  {
    state.n_extra_fields      = extra.size();
    state.layout              = layout_of(tria, system, 1 + extra.size());
    const MPI_Comm    comm    = system.communicator();
    const bool        root    = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string partial = directory + "/checkpoint.new";
    // p4est aborts the job on a failed write: check the free space first
    // (twice the last checkpoint, or an estimate from the fields).
    std::string error =
        root ? prepare_folder((1 + extra.size()) * 12 * system.n_dofs() +
                              200 * tria.n_global_active_cells())
             : "";
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
        transfer(system.dof_handler());
    std::vector<const TrilinosWrappers::MPI::Vector *> fields = {
        &system.ghosted_solution()};
    fields.insert(fields.end(), extra.begin(), extra.end());
    transfer.prepare_for_serialization(fields);
    // save() is const on the mesh data but not declared so.
    const_cast<parallel::distributed::Triangulation<dim> &>(tria).save(partial +
                                                                       "/mesh");
    MPI_Barrier(comm);

    if (root)
      error = complete(state);
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  template <int dim>
  std::string
  Checkpoint<dim>::prepare_folder(const std::uintmax_t estimate) const
  {
    const std::string target   = directory + "/checkpoint";
    const std::string partial  = directory + "/checkpoint.new";
    const std::string previous = directory + "/checkpoint.old";
    std::error_code   ignored;
    std::uintmax_t    needed = 0;
    if (fs::is_directory(target))
      for (const auto &entry : fs::directory_iterator(target))
        needed += entry.file_size(ignored);
    else
      needed = estimate;
    const auto space = fs::space(directory, ignored);
    if (!ignored && space.available < 2 * needed + (1u << 16))
      return "Not enough free disk space for a checkpoint in '" + directory +
             "' (" + std::to_string(space.available >> 20) +
             " MiB free, about " + std::to_string((2 * needed) >> 20) +
             " MiB needed). The previous checkpoint is kept. Fix: free "
             "disk space, or set 'Checkpoint/Interval = 0'.";
    try
    {
      for (const auto &entry : {partial, target, previous})
        RunManifest::note(entry);
      fs::remove_all(partial, ignored);
      if (!fs::create_directories(partial, ignored) && ignored)
        return "Cannot create '" + partial + "': " + ignored.message();
    }
    catch (const std::exception &e)
    {
      return e.what();
    }
    return "";
  }

  template <int dim> std::string Checkpoint<dim>::complete(RunState state) const
  {
    const std::string target   = directory + "/checkpoint";
    const std::string partial  = directory + "/checkpoint.new";
    const std::string previous = directory + "/checkpoint.old";
    try
    {
      state.data_files = data_files_in(partial);
      {
        std::ofstream                 out(partial + "/state.txt");
        boost::archive::text_oarchive archive(out);
        archive << state;
        out.flush();
        if (!out)
          throw InputError("Cannot write '" + partial + "/state.txt'.");
      }
      write_manifest(partial, state.data_files);
      // Keep the last good checkpoint until the new one is in place.
      if (fs::exists(target))
      {
        fs::remove_all(previous);
        fs::rename(target, previous);
        RunManifest::record(previous);
      }
      fs::rename(partial, target);
      RunManifest::record(target);
    }
    catch (const std::exception &e)
    {
      return std::string("Writing the checkpoint in '") + directory +
             "' failed: " + e.what() +
             " The previous checkpoint is kept. Fix: check that the disk "
             "is not full and the directory is writable.";
    }
    return "";
  }

  template <int dim>
  std::string Checkpoint<dim>::damage(const std::string &path) const
  {
    if (!fs::is_directory(path))
      return "it does not exist";
    const fs::path manifest_file = fs::path(path) / manifest_name;
    if (!fs::exists(manifest_file))
      return "it has no manifest (written by softgrasp before checkpoint "
             "format " +
             std::to_string(format_version) +
             ", or its writing was interrupted)";
    const Manifest m = read_manifest(manifest_file);
    if (m.version != format_version || !m.complete)
      return "its manifest is damaged or of another format version (" +
             std::to_string(m.version) + ", this softgrasp reads " +
             std::to_string(format_version) + ")";
    if (m.dim != dim)
      return "it was written by a " + std::to_string(m.dim) +
             "D run, this run is " + std::to_string(dim) + "D";
    if (m.files.count("state.txt") == 0 || m.files.count("mesh") == 0)
      return "its manifest lists no mesh or state file";
    for (const auto &[name, recorded] : m.files)
    {
      const fs::path file = fs::path(path) / name;
      if (!fs::exists(file))
        return "the file '" + name + "' is missing";
      const std::string actual =
          std::to_string(fs::file_size(file)) + " " + file_checksum(file);
      if (actual != recorded)
        return "the file '" + name + "' is damaged (its size or checksum " +
               "differs from the manifest)";
    }
    return "";
  }

  template <int dim>
  std::string Checkpoint<dim>::changed_settings(const std::string &path) const
  {
    const Manifest m = read_manifest(fs::path(path) / manifest_name);
    std::map<std::string, std::string> saved(m.settings.begin(),
                                             m.settings.end());
    std::ostringstream                 differences;
    for (const auto &[name, value] : settings)
    {
      const auto it = saved.find(name);
      if (it == saved.end())
        differences << "\n  '" << name << "' = '" << value
                    << "' is new (not in the checkpoint)";
      else if (it->second != value)
        differences << "\n  '" << name << "' = '" << value
                    << "', the checkpoint was written with '" << it->second
                    << "'";
      if (it != saved.end())
        saved.erase(it);
    }
    for (const auto &[name, value] : saved)
      differences << "\n  '" << name << "' = '" << value
                  << "' in the checkpoint is not set in this run";
    return differences.str();
  }

  template <int dim>
  std::string Checkpoint<dim>::select(MPI_Comm comm, std::ostream &log) const
  {
    std::string chosen, error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::string reasons;
      for (const std::string name : {"checkpoint", "checkpoint.old"})
      {
        const std::string path    = directory + "/" + name;
        const std::string problem = damage(path);
        if (problem.empty())
        {
          const std::string changed = changed_settings(path);
          if (!changed.empty())
            error = "The run cannot resume from '" + path +
                    "': these settings differ from the run that wrote "
                    "it:" +
                    changed +
                    "\nFix: resume with the settings of that run (the "
                    "checkpoint's manifest.txt lists them), or set "
                    "'Checkpoint/Resume = false' to start over.";
          else
            chosen = path;
          break;
        }
        reasons += "\n  '" + path + "': " + problem;
      }
      if (chosen.empty() && error.empty())
        error = "'Checkpoint/Resume' is true but there is no usable "
                "checkpoint in '" +
                directory + "':" + reasons +
                "\nFix: set 'Checkpoint/Resume = false' to start from the "
                "beginning, or point 'Output/Directory' at the directory of "
                "the run to continue.";
      else if (!chosen.empty() && !reasons.empty())
      {
        // Keep the damaged one aside, so the next checkpoint does not
        // replace the good one by it.
        const std::string newest = directory + "/checkpoint";
        std::error_code   ignored;
        try
        { // best effort, as the rename below
          RunManifest::note(newest + ".damaged");
        }
        catch (const std::exception &)
        {
        }
        fs::remove_all(newest + ".damaged", ignored);
        fs::rename(newest, newest + ".damaged", ignored);
        log << "Warning: the newest checkpoint cannot be used:" << reasons
            << "\nResuming from the previous one, '" << chosen
            << "' (the damaged one is kept as 'checkpoint.damaged')."
            << std::endl;
      }
    }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    return Utilities::MPI::broadcast(comm, chosen, 0);
  }

  template <int dim>
  RunState
  Checkpoint<dim>::load(parallel::distributed::Triangulation<dim>  &tria,
                        SolidSystem<dim>                           &system,
                        std::vector<TrilinosWrappers::MPI::Vector> &extra,
                        const unsigned int                          n_extra,
                        std::ostream                               &log) const
  {
    const std::string source = select(system.communicator(), log);
    RunState          state;
    try // intact (checksum), but perhaps of another Boost archive version
    {
      std::ifstream                 in(source + "/state.txt");
      boost::archive::text_iarchive archive(in);
      archive >> state;
    }
    catch (const std::exception &e)
    {
      throw InputError("The state file of the checkpoint in '" + source +
                       "' cannot be read (" + e.what() +
                       "): it was written by a softgrasp built with another "
                       "Boost version. Fix: resume with that build, or set "
                       "'Checkpoint/Resume = false'.");
    }
    // The data against the run, before p4est or the solution transfer
    // read them (an edited or foreign manifest must not reach them).
    const auto refuse = [&](const std::string &why)
    {
      throw InputError("The run cannot resume from the checkpoint in '" +
                       source + "': " + why +
                       ". Its manifest does not describe its data (edited, "
                       "or of another run). Fix: resume with the settings "
                       "of the run that wrote the data, or set "
                       "'Checkpoint/Resume = false'.");
    };
    const bool root =
        Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0;
    if (const auto why = Utilities::MPI::broadcast(
            tria.get_communicator(),
            root ? foreign_data(source, state) : std::string(),
            0);
        !why.empty())
      refuse(why);
    const bool       recorded = state.layout.dim > 0; // not before format 4.1
    CheckpointLayout run;
    run.dim                = dim;
    run.n_coarse_cells     = tria.n_cells(0);
    run.n_fields           = 1 + n_extra;
    CheckpointLayout saved = state.layout;
    if (!recorded) // only the field count is known
    {
      saved          = run;
      saved.n_fields = 1 + state.n_extra_fields;
    }
    if (const auto why = mismatch(saved, run, false); !why.empty())
      refuse(why);
    try
    {
      tria.load(source + "/mesh");
    }
    catch (const ExceptionBase &e)
    {
      throw InputError("The checkpoint in '" + source +
                       "' does not fit this run's coarse mesh. Fix: resume "
                       "with the same 'Mesh' and 'Finite element' settings "
                       "as the run that wrote it.");
    }
    system.setup();
    if (recorded)
      if (const auto why = mismatch(
              state.layout, layout_of(tria, system, 1 + n_extra), true);
          !why.empty())
        refuse(why);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
        transfer(system.dof_handler());
    extra.resize(state.n_extra_fields);
    std::vector<TrilinosWrappers::MPI::Vector *> fields = {&system.solution()};
    for (auto &field : extra)
    {
      field.reinit(system.locally_owned_dofs(), system.communicator());
      fields.push_back(&field);
    }
    transfer.deserialize(fields);
    system.update_ghosts();
    return state;
  }

  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace softgrasp
