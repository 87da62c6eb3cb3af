#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/distributed/solution_transfer.h>
#include <filesystem>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/io/checkpoint.h>

namespace softgrasp
{
  using namespace dealii;
  namespace fs = std::filesystem;

  template <int dim>
  Checkpoint<dim>::Checkpoint(std::string directory)
      : directory(std::move(directory))
  {
  }

  template <int dim>
  void Checkpoint<dim>::save(
      const parallel::distributed::Triangulation<dim>          &tria,
      const SolidSystem<dim>                                   &system,
      RunState                                                  state,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &extra) const
  {
    state.n_extra_fields       = extra.size();
    const MPI_Comm    comm     = system.communicator();
    const bool        root     = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string target   = directory + "/checkpoint";
    const std::string partial  = directory + "/checkpoint.new";
    const std::string previous = directory + "/checkpoint.old";
    if (root)
    {
      fs::remove_all(partial);
      fs::create_directories(partial);
    }
    MPI_Barrier(comm);

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
        transfer(system.dof_handler());
    std::vector<const TrilinosWrappers::MPI::Vector *> fields = {
        &system.ghosted_solution()};
    fields.insert(fields.end(), extra.begin(), extra.end());
    transfer.prepare_for_serialization(fields);
    // save() is const on the mesh data but not declared so.
    const_cast<parallel::distributed::Triangulation<dim> &>(tria).save(partial +
                                                                       "/mesh");

    if (root)
    {
      {
        std::ofstream                 out(partial + "/state.txt");
        boost::archive::text_oarchive archive(out);
        archive << state;
      }
      fs::remove_all(previous);
      if (fs::exists(target))
        fs::rename(target, previous);
      fs::rename(partial, target);
      fs::remove_all(previous);
    }
    MPI_Barrier(comm);
  }

  template <int dim> std::string Checkpoint<dim>::complete_directory() const
  {
    for (const std::string name : {"/checkpoint", "/checkpoint.old"})
      if (fs::exists(directory + name + "/state.txt"))
        return directory + name;
    return "";
  }

  template <int dim> bool Checkpoint<dim>::exists() const
  {
    return !complete_directory().empty();
  }

  template <int dim>
  RunState
  Checkpoint<dim>::load(parallel::distributed::Triangulation<dim>  &tria,
                        SolidSystem<dim>                           &system,
                        std::vector<TrilinosWrappers::MPI::Vector> &extra) const
  {
    const std::string source = complete_directory();
    if (source.empty())
      throw InputError("'Checkpoint/Resume' is true but there is no "
                       "checkpoint in '" +
                       directory +
                       "'. Fix: set 'Resume = false' to start from the "
                       "beginning, or point 'Output/Directory' at the "
                       "directory of the run to continue.");
    RunState state;
    {
      std::ifstream                 in(source + "/state.txt");
      boost::archive::text_iarchive archive(in);
      archive >> state;
    }
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
