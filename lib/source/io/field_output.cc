#include <cstdio>
#include <deal.II/numerics/data_out.h>
#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/io/field_output.h>
#include <softgrasp/postprocess/strain_postprocessor.h>
#include <softgrasp/postprocess/stress_postprocessor.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// DataOut whose patches are moved by a displacement field in its rows.
    template <int dim> class DeformedDataOut : public DataOut<dim>
    {
    public:
      /// Add the dim rows starting at @p first_row to the point coordinates.
      void deform(const unsigned int first_row)
      {
        for (auto &patch : this->patches)
        {
          const unsigned int n_rows = patch.data.n_rows();
          const unsigned int n      = patch.n_subdivisions + 1;
          for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
               ++v)
          {
            unsigned int index = 0, stride = 1;
            for (unsigned int d = 0; d < dim; ++d, stride *= n)
              index += ((v >> d) & 1) * (n - 1) * stride;
            for (unsigned int d = 0; d < dim; ++d)
              patch.vertices[v][d] += patch.data(first_row + d, index);
          }
          // Interior points are stored only for curved/high-order patches;
          // otherwise the vertices alone define the geometry.
          if (!patch.points_are_available)
            continue;
          for (unsigned int p = 0; p < patch.data.n_cols(); ++p)
            for (unsigned int d = 0; d < dim; ++d)
              patch.data(n_rows - dim + d, p) += patch.data(first_row + d, p);
        }
      }
    };

  } // namespace

  template <int dim>
  FieldOutput<dim>::FieldOutput(std::string directory, std::string base_name)
      : directory(std::move(directory))
      , base_name(std::move(base_name))
  {
  }

  template <int dim>
  void FieldOutput<dim>::write(const SolidSystem<dim> &system,
                               const MaterialLibrary  &materials,
                               const double            time,
                               const unsigned int      index,
                               const ExtraFields      &extra)
  {
    const auto    &dofs = system.dof_handler();
    const auto    &u    = system.ghosted_solution();
    const MPI_Comm comm = system.communicator();

    DeformedDataOut<dim> data_out;
    data_out.attach_dof_handler(dofs);
    data_out.add_data_vector(
        u,
        std::vector<std::string>(dim, "displacement"),
        DataOut<dim>::type_dof_data,
        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            dim, DataComponentInterpretation::component_is_part_of_vector));
    const StrainPostprocessor<dim> strains(0);
    const StressPostprocessor<dim> stresses(materials, 0);
    data_out.add_data_vector(u, strains);
    data_out.add_data_vector(u, stresses);

    const auto   &tria = dofs.get_triangulation();
    Vector<float> material_id(tria.n_active_cells());
    Vector<float> rank(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        material_id[cell->active_cell_index()] = cell->material_id();
        rank[cell->active_cell_index()] =
            Utilities::MPI::this_mpi_process(comm);
      }
    Vector<float> e_max_cell(tria.n_active_cells());
    Vector<float> e_min_cell(tria.n_active_cells());
    cell_strain_extremes(system, e_max_cell, e_min_cell);
    data_out.add_data_vector(e_max_cell, "e_max_cell");
    data_out.add_data_vector(e_min_cell, "e_min_cell");
    data_out.add_data_vector(material_id, "material_id");
    data_out.add_data_vector(rank, "mpi_rank");
    if (extra)
      extra(data_out);

    const unsigned int degree = system.fe().degree;
    data_out.build_patches(
        system.mapping(), degree, DataOut<dim>::curved_inner_cells);
    data_out.deform(0);

    write_files(data_out, comm, time, index);
  }

  template <int dim>
  void FieldOutput<dim>::write_files(const DataOut<dim> &data_out,
                                     const MPI_Comm      comm,
                                     const double        time,
                                     const unsigned int  index)
  {
    std::ostringstream name;
    name << base_name << "_" << std::setw(5) << std::setfill('0') << index
         << ".vtu";
    const std::string file    = directory + "/" + name.str();
    const std::string partial = AtomicFile::temporary_name(file);
    std::string       problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
      { // listed before any rank creates it
        RunManifest::note(file);
      }
      catch (const std::exception &e)
      {
        problem = e.what();
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw std::runtime_error(problem);
    data_out.write_vtu_in_parallel(partial, comm);
    // MPI-IO reports a failed write only on stderr: check the file whole
    // before it gets its name, on rank 0, and fail on all ranks.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      problem = AtomicFile::check_written(partial, "</VTKFile>\n", true);
      try
      {
        if (!problem.empty())
          throw std::runtime_error(AtomicFile::write_error(file, problem));
        AtomicFile::commit(partial, file);
        auto with_this = records;
        with_this.emplace_back(time, name.str());
        std::ostringstream pvd;
        DataOutBase::write_pvd_record(pvd, with_this);
        AtomicFile::write(directory + "/" + base_name + ".pvd", pvd.str());
      }
      catch (const std::exception &e)
      {
        problem = e.what();
        std::remove(partial.c_str());
      }
    }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw std::runtime_error(problem);
    records.emplace_back(time, name.str());
  }

  template class FieldOutput<2>;
  template class FieldOutput<3>;
} // namespace softgrasp
