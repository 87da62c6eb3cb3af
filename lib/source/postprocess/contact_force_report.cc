#include <fstream>
#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/postprocess/contact_force_report.h>
#include <sstream>

namespace softgrasp
{
  namespace
  {
    /// "(x, y, z)" with @p n components in scientific notation.
    std::string vector_text(const Eigen::Vector3d &v, const unsigned int n)
    {
      std::ostringstream s;
      s << std::scientific << std::setprecision(4) << '(';
      for (unsigned int i = 0; i < n; ++i)
        s << (i ? ", " : "") << v[i];
      s << ')';
      return s.str();
    }

    /// The lateral force, its friction-only part and the rest.
    struct LateralSplit
    {
      double lateral, friction, pressure;
    };

    LateralSplit lateral_split(const GeomContactForce &f)
    {
      const double lateral  = f.lateral_part.norm();
      const double friction = f.friction.norm();
      return {lateral, friction, lateral - friction};
    }
  } // namespace

  ContactForceReport::ContactForceReport(
      const RigidBodySet                    &bodies,
      const std::vector<ContactForceRecord> &records,
      const unsigned int                     dim)
      : bodies(bodies)
      , records(records)
      , dim(dim)
  {
  }

  bool ContactForceReport::empty() const
  {
    return records.empty() || bodies.empty();
  }

  std::string ContactForceReport::force_unit() const
  {
    return dim == 2 ? "N/m" : "N";
  }

  std::vector<std::string> ContactForceReport::geom_labels() const
  {
    std::vector<std::string> labels;
    for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
        labels.push_back(bodies.geom_label(b, g));
    return labels;
  }

  void ContactForceReport::print(std::ostream &out) const
  {
    if (empty())
      return;
    const ContactForceRecord &last   = records.back();
    const std::string         unit   = force_unit();
    const std::string         m_unit = dim == 2 ? "N m/m" : "N m";
    out << "\nContact forces at t = " << last.time << " s (step " << last.step
        << "), exerted by the tissue on each rigid body and geom, in " << unit
        << (dim == 2 ? " (per metre of thickness)" : "") << ":\n";
    const auto &list = bodies.bodies();
    for (unsigned int b = 0; b < list.size() && b < last.forces.size(); ++b)
    {
      const auto [total, torque] =
          body_resultant(list[b], last.forces[b], last.time);
      out << "  body " << list[b].name() << ": F = " << vector_text(total, 3)
          << ' ' << unit << ", M = " << vector_text(torque, 3) << ' ' << m_unit
          << " about the body origin\n";
      for (unsigned int g = 0; g < last.forces[b].size(); ++g)
      {
        const auto        &f = last.forces[b][g];
        const LateralSplit s = lateral_split(f);
        const double       N = f.normal_force();
        out << "    geom " << bodies.geom_label(b, g) << " ("
            << list[b].geoms()[g].shape->type() << ")\n"
            << "      F = " << vector_text(f.force, 3) << ' ' << unit
            << ", M = " << vector_text(f.moment, 3) << ' ' << m_unit
            << " about the geom origin\n"
            << "      reference normal n = " << vector_text(f.normal, 3)
            << ": normal force " << N << ' ' << unit << ", lateral "
            << s.lateral << ' ' << unit;
        if (N > 0)
          out << " (" << std::setprecision(3) << s.lateral / N
              << std::setprecision(6) << " of normal)";
        out << "\n      lateral = friction alone " << s.friction
            << " + pressure on the tissue " << s.pressure << ' ' << unit
            << "; contact area " << f.area << (dim == 2 ? " m" : " m^2") << ", "
            << f.active << " nodes closed, " << f.slipping << " slipping\n";
      }
    }
    out << std::flush;
  }

  bool ContactForceReport::write_table_and_picture(const std::string &directory,
                                                   const std::string &base,
                                                   std::ostream      &log) const
  {
    if (empty())
      return false;
    const std::string unit   = force_unit();
    const auto        labels = geom_labels();
    {
      std::ostringstream out;
      out << "# time (s), then per geom: normal, lateral, friction-only and "
             "pressure part of the lateral force ("
          << unit << "), and lateral / normal (1; 0 without a normal force)"
          << "\n# geoms:";
      for (const auto &label : labels)
        out << ' ' << label;
      out << '\n' << std::setprecision(10);
      for (const auto &record : records)
      {
        out << record.time;
        for (const auto &body_forces : record.forces)
          for (const auto &f : body_forces)
          {
            const LateralSplit s = lateral_split(f);
            const double       N = f.normal_force();
            out << ' ' << N << ' ' << s.lateral << ' ' << s.friction << ' '
                << s.pressure << ' ' << (N > 0 ? s.lateral / N : 0.);
          }
        out << '\n';
      }
      AtomicFile::write(directory + "/" + base + ".dat", out.str());
    }
    const std::string picture = base + ".png";
    {
      std::ostringstream gp;
      gp << "set terminal pngcairo size 1000,650 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(picture) << "'\n"
         << "set title 'Contact forces on the rigid geoms: normal (solid), "
            "lateral (dashed), friction alone (dotted); lateral / normal "
            "(thin, right axis)'\n"
         << "set xlabel 'time t (s)'\nset ylabel 'force (" << unit
         << ")'\nset y2label 'lateral / normal (1)'\nset ytics nomirror\n"
         << "set y2tics\nset key left top\nset grid\nplot ";
      for (unsigned int g = 0; g < labels.size(); ++g)
      {
        const unsigned int c = 2 + 5 * g;
        gp << (g ? ", " : "") << "'" << base << ".dat' using 1:" << c
           << " with lines lw 2 lc " << g + 1 << " title '" << labels[g]
           << ": normal', '' using 1:" << c + 1 << " with lines dt 2 lw 2 lc "
           << g + 1 << " title '" << labels[g]
           << ": lateral', '' using 1:" << c + 2 << " with lines dt 3 lw 2 lc "
           << g + 1 << " title '" << labels[g]
           << ": friction alone', '' using 1:" << c + 4
           << " axes x1y2 with lines dt 4 lw 1 lc " << g + 1 << " title '"
           << labels[g] << ": lateral / normal'";
      }
      gp << '\n';
      AtomicFile::write(directory + "/" + base + ".gnuplot", gp.str());
    }
    return run_gnuplot(directory, base + ".gnuplot", {picture}, log);
  }

  void report_contact_forces(MPI_Comm                               comm,
                             const RigidBodySet                    &bodies,
                             const std::vector<ContactForceRecord> &records,
                             const unsigned int                     dim,
                             const std::string                     &directory,
                             const std::string                     &base,
                             std::ostream                          &out)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const ContactForceReport report(bodies, records, dim);
    if (report.empty())
      return;
    report.print(out);
    if (report.write_table_and_picture(directory, base, out))
      out << "Picture: " << directory << "/" << base << ".png (table " << base
          << ".dat)" << std::endl;
  }
} // namespace softgrasp
