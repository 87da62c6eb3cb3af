#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/postprocess/tissue_injury.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  void InjuryThresholds::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Injury assessment");
    prm.declare_entry(
        "Compressive strain thresholds",
        "0.40, 0.65",
        Patterns::List(Patterns::Double(0, 1), 0),
        "Engineering compressive strains 1 - lambda_min (= -e_min) beyond "
        "which the tissue volume is reported, per tissue. Defaults: cell "
        "death of skeletal muscle cells under sustained compression, about "
        "0.65 within an hour and 0.40 after several hours (Gefen et al., "
        "J. Biomech. 41, 2008; doc/studies.md). Unit: 1.");
    prm.declare_entry(
        "Tensile strain thresholds",
        "0.54",
        Patterns::List(Patterns::Double(0), 0),
        "Principal strains e_max = lambda_max - 1 beyond which the tissue "
        "volume is reported, per tissue. Default: the mean failure strain "
        "of excised human skin in uniaxial tension (Ni Annaidh et al., J. "
        "Mech. Behav. Biomed. Mater. 5, 2012). Unit: 1.");
    prm.declare_entry(
        "Pressure thresholds",
        "4.3e3, 1.9e6",
        Patterns::List(Patterns::Double(0), 0),
        "Contact pressures beyond which the (deformed) skin area is "
        "reported. Defaults: 4.3 kPa, the capillary closing pressure of 32 "
        "mmHg (Landis, Heart 15, 1930), relevant to a sustained grip; 1.9 "
        "MPa, the onset of pain on the deltoid muscle under quasi-static "
        "contact (ISO/TS 15066:2016, Table A.2). Unit: Pa.");
    prm.leave_subsection();
  }

  void InjuryThresholds::parse_parameters(ParameterHandler  &prm,
                                          const std::string &parent)
  {
    prm.enter_subsection("Injury assessment");
    const CheckedSection section(prm, parent + "/Injury assessment");
    const auto           list = [&](const std::string &name)
    {
      return section.is_set(name) ? section.get_number_list(name)
                                  : std::vector<double>{};
    };
    compressive_strains = list("Compressive strain thresholds");
    tensile_strains     = list("Tensile strain thresholds");
    pressures           = list("Pressure thresholds");
    prm.leave_subsection();
    for (const double t : compressive_strains)
      if (!(t > 0 && t < 1))
        throw InputError("'" +
                         section.path_of("Compressive strain "
                                         "thresholds") +
                         "' has " + std::to_string(t) +
                         ", but a compressive strain 1 - lambda_min lies "
                         "in (0, 1). Fix: give strains such as 0.4.");
  }

  namespace
  {
    Eigen::Vector3d eigen(const Point<3> &p)
    {
      return {p[0], p[1], p[2]};
    }

    /// Pack a candidate extreme for the all-gather: value, X, x.
    void pack(std::vector<double> &data, const InjuryLocation &l)
    {
      data.push_back(l.value);
      data.insert(data.end(), l.reference.data(), l.reference.data() + 3);
      data.insert(data.end(), l.current.data(), l.current.data() + 3);
    }

    InjuryLocation unpack(const std::vector<double> &data, std::size_t i)
    {
      InjuryLocation l;
      l.value = data[i];
      for (unsigned int d = 0; d < 3; ++d)
      {
        l.reference[d] = data[i + 1 + d];
        l.current[d]   = data[i + 4 + d];
      }
      return l;
    }

    /// The element-wise sum of @p values over all ranks.
    std::vector<double> sum_over_ranks(const std::vector<double> &values,
                                       MPI_Comm                   comm)
    {
      std::vector<double> sum(values.size());
      Utilities::MPI::sum(make_array_view(values), comm, make_array_view(sum));
      return sum;
    }

    /// The largest (@p sign = 1) or smallest (-1) candidate of all ranks.
    InjuryLocation
    extreme_over_ranks(const InjuryLocation &local, double sign, MPI_Comm comm)
    {
      std::vector<double> data;
      pack(data, local);
      const auto     all  = Utilities::MPI::all_gather(comm, data);
      InjuryLocation best = unpack(all.front(), 0);
      for (const auto &candidate : all)
        if (sign * candidate[0] > sign * best.value)
          best = unpack(candidate, 0);
      return best;
    }

    /// Name the geom nearest to the current position of @p l.
    void
    locate(InjuryLocation &l, const RigidBodySet &bodies, const double time)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      {
        const auto q = bodies.bodies()[b].closest_geom(l.current, time);
        if (q.distance < nearest)
        {
          nearest         = q.distance;
          l.nearest_geom  = bodies.geom_label(b, q.geom);
          l.geom_distance = q.distance;
        }
      }
    }
  } // namespace

  template <int dim>
  void TissueInjury<dim>::compute(const SolidSystem<dim>    &system,
                                  const MaterialLibrary     &materials,
                                  const ContactSurface<dim> *contact,
                                  const ContactOutput<dim>  *output,
                                  const RigidBodySet        &bodies,
                                  const double               time,
                                  const InjuryThresholds    &thresholds)
  {
    compute_strains(system.dof_handler(),
                    system.mapping(),
                    system.ghosted_solution(),
                    materials,
                    thresholds);
    has_contact = contact != nullptr && output != nullptr;
    if (has_contact)
      compute_pressure(system, *contact, *output);
    for (auto &row : rows)
    {
      locate(row.e_max, bodies, time);
      locate(row.e_min, bodies, time);
    }
    if (has_contact)
      locate(pressure.maximum, bodies, time);
  }

  template <int dim>
  template <typename VectorType>
  void TissueInjury<dim>::compute_strains(const DoFHandler<dim>  &dof_handler,
                                          const Mapping<dim>     &mapping,
                                          const VectorType       &solution,
                                          const MaterialLibrary  &materials,
                                          const InjuryThresholds &thresholds)
  {
    limits            = thresholds;
    pressure          = SurfacePressure();
    has_contact       = false;
    const auto &fe    = dof_handler.get_fe();
    const auto  index = start_rows(materials);

    const QGauss<dim>                quadrature(fe.degree + 1);
    FEValues<dim>                    fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
    std::vector<Tensor<1, dim>>      u(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(solution, grad_u);
        fe_values[displacement].get_function_values(solution, u);
        Tissue &row = rows[index.at(cell->material_id())];
        for (const auto q : fe_values.quadrature_point_indices())
        {
          const auto       p  = PrincipalStrains::compute(PlaneStrain::to_3d(
              Tensor<2, dim>(unit_symmetric_tensor<dim>()) + grad_u[q]));
          const double     dV = fe_values.JxW(q);
          const Point<dim> X  = fe_values.quadrature_point(q);
          row.volume += dV;
          for (std::size_t t = 0; t < limits.compressive_strains.size(); ++t)
            if (-p.e_min() >= limits.compressive_strains[t])
              row.volume_compressed[t] += dV;
          for (std::size_t t = 0; t < limits.tensile_strains.size(); ++t)
            if (p.e_max() >= limits.tensile_strains[t])
              row.volume_stretched[t] += dV;
          const auto place = [&](InjuryLocation &l, const double value)
          {
            l.value     = value;
            l.reference = eigen(PlaneStrain::to_3d(X));
            l.current   = eigen(PlaneStrain::to_3d(Point<dim>(X + u[q])));
          };
          if (p.e_max() > row.e_max.value)
            place(row.e_max, p.e_max());
          if (p.e_min() < row.e_min.value)
            place(row.e_min, p.e_min());
        }
      }

    finish_rows(dof_handler.get_communicator());
  }

  template <int dim>
  std::map<types::material_id, unsigned int>
  TissueInjury<dim>::start_rows(const MaterialLibrary &materials)
  {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto       ids = materials.material_ids();
    rows.assign(ids.size(), Tissue());
    std::map<types::material_id, unsigned int> index;
    for (unsigned int k = 0; k < ids.size(); ++k)
    {
      index[ids[k]]       = k;
      rows[k].id          = ids[k];
      rows[k].name        = materials.get(ids[k]).name();
      rows[k].e_max.value = -inf;
      rows[k].e_min.value = inf;
      rows[k].volume_compressed.assign(limits.compressive_strains.size(), 0);
      rows[k].volume_stretched.assign(limits.tensile_strains.size(), 0);
    }
    return index;
  }

  template <int dim> void TissueInjury<dim>::finish_rows(const MPI_Comm comm)
  {
    for (auto &row : rows)
    {
      row.volume            = Utilities::MPI::sum(row.volume, comm);
      row.volume_compressed = sum_over_ranks(row.volume_compressed, comm);
      row.volume_stretched  = sum_over_ranks(row.volume_stretched, comm);
      row.e_max             = extreme_over_ranks(row.e_max, 1, comm);
      row.e_min             = extreme_over_ranks(row.e_min, -1, comm);
    }
    std::vector<Tissue> kept;
    for (auto &row : rows)
      if (row.volume > 0)
        kept.push_back(std::move(row));
    rows = std::move(kept);
  }

  template <int dim>
  void TissueInjury<dim>::compute_pressure(const SolidSystem<dim>    &system,
                                           const ContactSurface<dim> &contact,
                                           const ContactOutput<dim>  &output)
  {
    const auto  areas = output.current_areas(system);
    const auto &nodes = contact.nodes();
    const auto &u     = system.ghosted_solution();
    pressure.area_above.assign(limits.pressures.size(), 0);
    pressure.maximum.value = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
    {
      const auto &node = nodes[j];
      if (node.status == ContactStatus::inactive || !(areas[j] > 0))
        continue;
      const double p = contact_pressure(node, areas[j]);
      pressure.contact_area += areas[j];
      for (std::size_t t = 0; t < limits.pressures.size(); ++t)
        if (p >= limits.pressures[t])
          pressure.area_above[t] += areas[j];
      if (p > pressure.maximum.value)
      {
        pressure.maximum.value     = p;
        pressure.maximum.reference = node.reference_position;
        pressure.maximum.current   = node.reference_position;
        for (unsigned int c = 0; c < dim; ++c)
          pressure.maximum.current[c] += u[node.dofs[c]];
      }
    }
    const MPI_Comm comm   = system.communicator();
    pressure.contact_area = Utilities::MPI::sum(pressure.contact_area, comm);
    pressure.area_above   = sum_over_ranks(pressure.area_above, comm);
    pressure.maximum      = extreme_over_ranks(pressure.maximum, 1, comm);
  }

  namespace
  {
    std::string threshold_label(const double t)
    {
      std::ostringstream out;
      out << t;
      return out.str();
    }

    void write_location(std::ostream &out, const InjuryLocation &l)
    {
      out << ',' << l.value;
      for (const auto *v : {&l.reference, &l.current})
        for (unsigned int d = 0; d < 3; ++d)
          out << ',' << (*v)[d];
      out << ',' << l.nearest_geom << ',' << l.geom_distance;
    }

    std::string location_columns(const std::string &name)
    {
      std::string columns = "," + name;
      for (const char *frame : {"X", "x"})
        for (const char *d : {"1", "2", "3"})
          columns += "," + name + "_" + frame + d + "_m";
      return columns + "," + name + "_nearest_geom," + name +
             "_geom_distance_m";
    }
  } // namespace

  template <int dim>
  void TissueInjury<dim>::write_csv(const std::string &tissue_file,
                                    const std::string &surface_file) const
  {
    {
      AtomicFile::TextFile out(tissue_file);
      out << std::setprecision(8) << "material_id,tissue,volume_m3"
          << location_columns("e_max") << location_columns("e_min")
          << ",E_GL_max,E_GL_min,log_strain_max,log_strain_min";
      for (const double t : limits.compressive_strains)
        out << ",volume_compressed_beyond_" << threshold_label(t) << "_m3";
      for (const double t : limits.tensile_strains)
        out << ",volume_stretched_beyond_" << threshold_label(t) << "_m3";
      out << '\n';
      for (const auto &row : rows)
      {
        out << static_cast<unsigned int>(row.id) << ',' << row.name << ','
            << row.volume;
        write_location(out, row.e_max);
        write_location(out, row.e_min);
        out << ',' << green_lagrange_strain(row.e_max.value) << ','
            << green_lagrange_strain(row.e_min.value) << ','
            << logarithmic_strain(row.e_max.value) << ','
            << logarithmic_strain(row.e_min.value);
        for (const double v : row.volume_compressed)
          out << ',' << v;
        for (const double v : row.volume_stretched)
          out << ',' << v;
        out << '\n';
      }
      out.commit();
    }
    if (!has_contact)
      return;
    AtomicFile::TextFile out(surface_file);
    out << std::setprecision(8)
        << "pressure_threshold_Pa,area_above_m2,contact_area_m2"
        << location_columns("pressure_max_Pa") << '\n';
    for (std::size_t t = 0; t < limits.pressures.size(); ++t)
    {
      out << limits.pressures[t] << ',' << pressure.area_above[t] << ','
          << pressure.contact_area;
      write_location(out, pressure.maximum);
      out << '\n';
    }
    out.commit();
  }

  namespace
  {
    std::string where(const InjuryLocation &l)
    {
      std::ostringstream out;
      out << std::fixed << std::setprecision(1) << "at (" << 1e3 * l.current[0]
          << ", " << 1e3 * l.current[1] << ", " << 1e3 * l.current[2] << ") mm";
      if (!l.nearest_geom.empty())
        out << ", " << 1e3 * l.geom_distance << " mm from " << l.nearest_geom;
      return out.str();
    }
  } // namespace

  template <int dim> void TissueInjury<dim>::print(std::ostream &out) const
  {
    const auto flags     = out.flags();
    const auto precision = out.precision();
    out << "Injury assessment (principal strains e = lambda - 1; volumes in "
           "the reference configuration):\n";
    for (const auto &row : rows)
    {
      out << "  " << row.name << " (id " << static_cast<unsigned int>(row.id)
          << ", " << std::setprecision(4) << 1e6 * row.volume << " cm^3):\n"
          << "    e_max " << std::setprecision(3) << row.e_max.value << ' '
          << where(row.e_max) << "\n    e_min " << row.e_min.value << ' '
          << where(row.e_min) << "\n    Green-Lagrange "
          << green_lagrange_strain(row.e_max.value) << " / "
          << green_lagrange_strain(row.e_min.value) << ", logarithmic "
          << logarithmic_strain(row.e_max.value) << " / "
          << logarithmic_strain(row.e_min.value) << " (largest / smallest)\n";
      for (std::size_t t = 0; t < row.volume_compressed.size(); ++t)
        out << "    compressed beyond " << limits.compressive_strains[t] << ": "
            << std::setprecision(3) << 1e6 * row.volume_compressed[t]
            << " cm^3 (" << 100 * row.volume_compressed[t] / row.volume
            << " %)\n";
      for (std::size_t t = 0; t < row.volume_stretched.size(); ++t)
        out << "    stretched beyond " << limits.tensile_strains[t] << ": "
            << std::setprecision(3) << 1e6 * row.volume_stretched[t]
            << " cm^3 (" << 100 * row.volume_stretched[t] / row.volume
            << " %)\n";
    }
    if (has_contact)
    {
      out << "  contact surface: " << std::setprecision(3)
          << 1e4 * pressure.contact_area << " cm^2 in contact, largest "
          << "pressure " << 1e-3 * pressure.maximum.value << " kPa "
          << where(pressure.maximum) << '\n';
      for (std::size_t t = 0; t < limits.pressures.size(); ++t)
        out << "    above " << 1e-3 * limits.pressures[t]
            << " kPa: " << 1e4 * pressure.area_above[t] << " cm^2\n";
    }
    out.flags(flags);
    out.precision(precision);
  }

  template class TissueInjury<2>;
  template class TissueInjury<3>;

#define SOFTGRASP_INSTANTIATE(dim, VectorType)                                 \
  template void TissueInjury<dim>::compute_strains<VectorType>(                \
      const DoFHandler<dim> &,                                                 \
      const Mapping<dim> &,                                                    \
      const VectorType &,                                                      \
      const MaterialLibrary &,                                                 \
      const InjuryThresholds &);
  SOFTGRASP_INSTANTIATE(2, LinearAlgebra::distributed::Vector<double>)
  SOFTGRASP_INSTANTIATE(3, LinearAlgebra::distributed::Vector<double>)
  SOFTGRASP_INSTANTIATE(2, TrilinosWrappers::MPI::Vector)
  SOFTGRASP_INSTANTIATE(3, TrilinosWrappers::MPI::Vector)
#undef SOFTGRASP_INSTANTIATE
} // namespace softgrasp
