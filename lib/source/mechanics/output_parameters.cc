#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/mechanics/solver_parameters.h>

// The parameters of what a run writes: its output ('Output') and its
// checkpoints ('Checkpoint'); the rest of SolverParameters is in
// solver_parameters.cc.
namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// The .prm spelling of each ExistingResults choice.
    const std::vector<std::pair<std::string, ExistingResults>>
        existing_results_names = {{"move aside", ExistingResults::move_aside},
                                  {"replace", ExistingResults::replace},
                                  {"refuse", ExistingResults::refuse}};
  } // namespace

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::FileName(Patterns::FileName::output),
                      "Directory of all output files; created if missing.");
    prm.declare_entry("Base name",
                      "solution",
                      Patterns::FileName(Patterns::FileName::output),
                      "Prefix of the VTU, PVD and CSV files.");
    prm.declare_entry("VTU interval",
                      "1",
                      Patterns::Integer(0),
                      "Write the fields every n-th converged step (and "
                      "always the last one); 0 writes the last one only. "
                      "Unit: 1.");
    prm.declare_entry("Monitor points",
                      "",
                      Patterns::Anything(),
                      "Reference positions whose displacement is recorded "
                      "in the history CSV, separated by ';', coordinates "
                      "by ',', e.g. '0.048, 0.060; 0, 0'. Unit: m.");
    prm.declare_entry("Verbose",
                      "true",
                      Patterns::Bool(),
                      "Print every Newton iteration (residual, line search, "
                      "linear iterations) besides the per-step progress.");
    prm.declare_entry(
        "Existing results",
        "move aside",
        Patterns::Selection(choice_pattern(existing_results_names)),
        "What a new run (not a resume) does with the results of an earlier "
        "run in 'Directory', that is with the files and folders listed in "
        "that run's manifest 'softgrasp-run-files.txt' whose size and "
        "checksum match what it records: 'move aside' moves them into a "
        "subfolder 'previous-run-<n>', 'replace' deletes them, 'refuse' "
        "stops with an error. Nothing that a run cannot prove it wrote "
        "(inputs, notes, folders, edited results) is ever deleted or "
        "written over: a file in the way is moved into 'moved-aside-<n>' "
        "first, and the log says so (doc/reliability.md).");
    prm.leave_subsection();
  }

  namespace
  {
    /**
     * Refuses an 'Output/Base name' that is not an ordinary file name
     * prefix: empty, with '/' or a NUL, "." or ".." (hidden files such as
     * '..pvd'), or too long for the file system once the longest suffix a
     * run appends is added.
     */
    void check_base_name(const std::string &base_name)
    {
      // POSIX file systems allow 255 bytes per name; the longest suffix a
      // run appends is about 40 bytes ("_history.csv.partial", a VTU
      // file's step and rank numbers).
      constexpr std::size_t longest_name = 255 - 40;
      const std::string     entry =
          "Parameter 'Output/Base name' is '" + base_name + "'";
      const std::string named =
          " (the files are named '<Base name>_00001.vtu', '<Base name>.pvd', "
          "...). Fix: set a name such as 'solution', and choose the folder "
          "with 'Output/Directory'.";
      if (base_name.empty() || base_name.find('/') != std::string::npos ||
          base_name.find('\0') != std::string::npos)
        throw InputError(entry +
                         ": it must be a non-empty file name prefix without "
                         "'/'" +
                         named);
      if (base_name == "." || base_name == "..")
        throw InputError(entry +
                         ": it must be an ordinary file name prefix, not '.' "
                         "or '..' (the files would be hidden, e.g. '" +
                         base_name + ".pvd')" + named);
      if (base_name.size() > longest_name)
        throw InputError("Parameter 'Output/Base name' has " +
                         std::to_string(base_name.size()) +
                         " characters: a file name may have at most 255 "
                         "bytes, and the run appends up to 40 to it, so the "
                         "base name may have at most " +
                         std::to_string(longest_name) + "." + named);
    }
  } // namespace

  void OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    base_name = prm.get("Base name");
    check_base_name(base_name);
    vtu_interval = prm.get_integer("VTU interval");
    verbose      = prm.get_bool("Verbose");
    existing_results =
        lookup_choice(existing_results_names, prm.get("Existing results"));
    monitor_points.clear();
    for (const std::string &point :
         Utilities::split_string_list(prm.get("Monitor points"), ';'))
    {
      std::vector<double> coordinates;
      try
      {
        coordinates = Utilities::string_to_double(
            Utilities::split_string_list(point, ','));
      }
      catch (...)
      {
        coordinates.clear();
      }
      if (coordinates.empty())
        throw InputError("Parameter 'Output/Monitor points' has the entry '" +
                         point +
                         "', which is not a list of numbers. Fix: write "
                         "points as 'x, y[, z]' separated by ';' (m).");
      monitor_points.push_back(coordinates);
    }
    prm.leave_subsection();
  }

  void CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every n-th converged step into "
                      "<Output directory>/checkpoint; 0 = never. Unit: 1.");
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Restart from the last checkpoint in the output "
                      "directory instead of from the reference state.");
    prm.leave_subsection();
  }

  void CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    interval = prm.get_integer("Interval");
    resume   = prm.get_bool("Resume");
    prm.leave_subsection();
  }

} // namespace softgrasp
