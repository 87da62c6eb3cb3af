#ifndef softgrasp_io_field_output_h
#define softgrasp_io_field_output_h

#include <deal.II/numerics/data_out.h>
#include <functional>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/solid_system.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /**
   * VTU/PVD output of a solid on its deformed configuration: the
   * displacement (m), the principal strains e_max, e_mid, e_min and J
   * (StrainPostprocessor), the Cauchy and von Mises stress and pressure (Pa,
   * StressPostprocessor), the material id and the MPI rank. Fields are
   * computed on the reference mesh (so gradients are reference gradients)
   * and the output points are then moved by the displacement.
   *
   * One .vtu per output step (written in parallel through MPI I/O) and a
   * .pvd collection; each is written to a temporary name and renamed, so
   * no reader sees a partial file.
   */
  template <int dim> class FieldOutput
  {
  public:
    FieldOutput(std::string directory, std::string base_name);

    /// Adds further fields (e.g. contact) to the DataOut before patches
    /// are built; the data it adds must live until write() returns.
    using ExtraFields = std::function<void(dealii::DataOut<dim> &)>;

    /// Write the fields of @p system at @p time (s) as output @p index.
    void write(const SolidSystem<dim> &system,
               const MaterialLibrary  &materials,
               const double            time,
               const unsigned int      index,
               const ExtraFields      &extra = ExtraFields());

    /// (time, file) of every .vtu written so far, for the .pvd and restarts.
    std::vector<std::pair<double, std::string>> records;

  private:
    /// Write @p data_out as output @p index at @p time: the VTU in
    /// parallel under a temporary name, checked, renamed, and the PVD.
    void write_files(const dealii::DataOut<dim> &data_out,
                     MPI_Comm                    comm,
                     double                      time,
                     unsigned int                index);

    std::string directory;
    std::string base_name;
  };
} // namespace softgrasp

#endif
