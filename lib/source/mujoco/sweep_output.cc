#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/io/hdf5_record.h>
#include <softgrasp/mujoco/sweep_output.h>
#include <sstream>
#include <stdexcept>

namespace softgrasp
{
  namespace
  {
    double max_of(const std::vector<double> &v)
    {
      return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
    }

    /// Mean of @p v over the records from half the last time on.
    double second_half_mean(const std::vector<double> &time,
                            const std::vector<double> &v)
    {
      double sum = 0;
      int    n   = 0;
      for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= 0.5 * time.back())
          sum += v[i], ++n;
      return n > 0 ? sum / n : 0;
    }
  } // namespace

  void write_rigid_levels(const std::vector<RigidGripLevel> &levels,
                          const std::string                 &summary_file,
                          const std::string                 &pulls_file)
  {
    std::ostringstream summary;
    summary << std::setprecision(8)
            << "level,link,target_force,reached_force,closure,matched,"
               "normal_end,normal_mean,lateral_end,lateral_mean,lateral_max,"
               "drag_end,drag_mean,drag_max,slip_speed_mean,slides\n";
    std::ostringstream pulls;
    pulls << std::setprecision(8) << "level,time,slide";
    if (!levels.empty())
      for (const auto &link : levels.front().links)
        for (const char *part : {"normal", "lateral", "drag", "slip_speed"})
          pulls << ',' << link.body << '/' << link.geom << ':' << part;
    pulls << '\n';
    for (std::size_t k = 0; k < levels.size(); ++k)
    {
      const auto &level = levels[k];
      for (const auto &link : level.links)
        summary << k + 1 << ',' << link.body << '/' << link.geom << ','
                << level.target_force << ',' << level.reached_force << ','
                << level.closure << ',' << level.matched << ','
                << link.normal.back() << ',' << link.normal_mean << ','
                << link.lateral.back() << ',' << link.lateral_mean << ','
                << max_of(link.lateral) << ',' << link.drag.back() << ','
                << link.drag_mean << ',' << max_of(link.drag) << ','
                << link.slip_mean << ',' << link.slides << '\n';
      for (std::size_t i = 0; i < level.time.size(); ++i)
      {
        pulls << k + 1 << ',' << level.time[i] << ',' << level.slide[i];
        for (const auto &link : level.links)
          pulls << ',' << link.normal[i] << ',' << link.lateral[i] << ','
                << link.drag[i] << ',' << link.slip_speed[i];
        pulls << '\n';
      }
    }
    AtomicFile::write(summary_file, summary.str());
    AtomicFile::write(pulls_file, pulls.str());
  }

  std::vector<SweepPoint>
  grip_link_points(const std::vector<RigidGripLevel> &levels,
                   const std::string                 &grip_geom)
  {
    std::vector<SweepPoint> points;
    for (std::size_t k = 0; k < levels.size(); ++k)
      for (const auto &link : levels[k].links)
        if (link.geom == grip_geom)
        {
          SweepPoint p;
          p.level        = k + 1;
          p.grip_force   = levels[k].reached_force;
          p.normal_mean  = link.normal_mean;
          p.lateral_mean = link.lateral_mean;
          p.lateral_max  = max_of(link.lateral);
          points.push_back(p);
        }
    return points;
  }

  std::vector<SweepPoint> grip_link_points(const std::vector<FeGripLevel> &fe,
                                           const std::string &grip_label)
  {
    std::vector<SweepPoint> points;
    for (std::size_t k = 0; k < fe.size(); ++k)
      for (const auto &link : fe[k].links)
        if (fe[k].pulled && link.link == grip_label && !link.time.empty())
        {
          SweepPoint p;
          p.level         = k + 1;
          p.grip_force    = fe[k].reached_force;
          p.normal_mean   = second_half_mean(link.time, link.normal);
          p.lateral_mean  = second_half_mean(link.time, link.lateral);
          p.lateral_max   = max_of(link.lateral);
          p.friction_mean = second_half_mean(link.time, link.friction);
          points.push_back(p);
        }
    return points;
  }

  namespace
  {
    /// The mean over the second half of @p link's pull of the fraction of
    /// its closed nodes that slide (0 if none is closed).
    double slip_fraction(const LinkForceHistory &link)
    {
      std::vector<double> fraction;
      for (std::size_t i = 0; i < link.time.size(); ++i)
        fraction.push_back(
            link.closed[i] > 0 ? link.slipping[i] / link.closed[i] : 0);
      return second_half_mean(link.time, fraction);
    }
  } // namespace

  void write_fe_levels(const std::vector<FeGripLevel> &levels,
                       const std::string              &summary_file,
                       const std::string              &pulls_file)
  {
    std::ostringstream summary, pulls;
    summary << std::setprecision(8)
            << "level,link,target_force,reached_force,closure_time,pulled,"
               "normal_end,normal_mean,lateral_end,lateral_mean,"
               "friction_end,friction_mean,nodal_normal_end,"
               "nodal_normal_mean,closed_nodes_end,slipping_nodes_end,"
               "slip_fraction_mean,slides\n";
    pulls << std::setprecision(8)
          << "level,link,time,normal,lateral,friction,nodal_normal,"
             "closed_nodes,slipping_nodes\n";
    for (std::size_t k = 0; k < levels.size(); ++k)
    {
      const auto &level = levels[k];
      for (const auto &link : level.links)
      {
        if (link.time.empty())
          continue;
        const auto both = [&](const std::vector<double> &v)
        {
          std::ostringstream out;
          out << std::setprecision(8) << v.back() << ','
              << second_half_mean(link.time, v);
          return out.str();
        };
        const double slip = slip_fraction(link);
        summary << k + 1 << ',' << link.link << ',' << level.target_force << ','
                << level.reached_force << ',' << level.time << ','
                << level.pulled << ',' << both(link.normal) << ','
                << both(link.lateral) << ',' << both(link.friction) << ','
                << both(link.nodal_normal) << ',' << link.closed.back() << ','
                << link.slipping.back() << ',' << slip << ',' << (slip > 0.5)
                << '\n';
        for (std::size_t i = 0; i < link.time.size(); ++i)
          pulls << k + 1 << ',' << link.link << ',' << link.time[i] << ','
                << link.normal[i] << ',' << link.lateral[i] << ','
                << link.friction[i] << ',' << link.nodal_normal[i] << ','
                << link.closed[i] << ',' << link.slipping[i] << '\n';
      }
    }
    AtomicFile::write(summary_file, summary.str());
    AtomicFile::write(pulls_file, pulls.str());
  }

  namespace
  {
    /// The sweep figure's data (gnuplot blocks: rigid, finite elements);
    /// returns the largest force (N, at least 1) and the highest level.
    std::pair<double, unsigned int>
    write_figure_data(const std::vector<SweepPoint> &rigid,
                      const std::vector<SweepPoint> &fe,
                      const std::string             &grip_link,
                      const std::string             &file)
    {
      double             top    = 1;
      unsigned int       levels = 2;
      std::ostringstream out;
      out << "# grip link " << grip_link
          << ": level, grip force at the level, then over the second half "
             "of the pull the mean normal and lateral force and the third "
             "value (rigid: the largest lateral force over the pull; finite "
             "elements: the mean friction-only force), all in N\n"
          << "# rigid simulator (MuJoCo)\n";
      for (const auto &p : rigid)
      {
        out << p.level << ' ' << p.grip_force << ' ' << p.normal_mean << ' '
            << p.lateral_mean << ' ' << p.lateral_max << '\n';
        top    = std::max({top, p.normal_mean, p.lateral_mean});
        levels = std::max(levels, p.level);
      }
      out << "\n\n# finite elements\n";
      for (const auto &p : fe)
      {
        out << p.level << ' ' << p.grip_force << ' ' << p.normal_mean << ' '
            << p.lateral_mean << ' ' << p.friction_mean << '\n';
        top    = std::max({top, p.normal_mean, p.lateral_mean});
        levels = std::max(levels, p.level);
      }
      if (fe.empty())
        out << "-1 0 0 0 0\n"; // an empty block would stop gnuplot
      AtomicFile::write(file, out.str());
      return {top, levels};
    }
  } // namespace

  void write_sweep_figure(const std::vector<SweepPoint> &rigid,
                          const std::vector<SweepPoint> &fe,
                          const double                   friction,
                          const std::string             &grip_link,
                          const std::string             &directory,
                          const std::string             &base,
                          std::ostream                  &log)
  {
    const auto [top, levels] = write_figure_data(
        rigid, fe, grip_link, directory + "/" + base + "_figure.dat");
    const std::string data = "'" + base + "_figure.dat'";
    {
      AtomicFile::TextFile gp(directory + "/" + base + "_figure.gnuplot");
      gp << "set terminal pngcairo size 1500,700 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_figure.png")
         << "'\n"
         << "set multiplot layout 1,2 title 'Grasp-and-pull sweep: forces "
            "on "
         << grip_link << " during the pull (means over its second half)'\n"
         << "set grid\nset key bottom right\n"
         << "set palette defined (0 'blue', 1 'red')\n"
         << "set cblabel 'grip level'\nset cbrange [1:" << levels
         << "]\nset cbtics 1\n"
         << "set title 'lateral against normal force'\n"
         << "set xlabel 'normal force (N)'\nset ylabel 'lateral force (N)'\n"
         << "set xrange [0:" << 1.1 * top << "]\nset yrange [0:" << 1.1 * top
         << "]\n"
         << "plot " << friction << " * x with lines dt 2 lc rgb 'gray40' "
         << "title 'mu N (mu = " << friction << ")', " << data
         << " index 0 using 3:4 with lines lw 2 lc rgb '#1f77b4' title "
            "'MuJoCo (rigid)', "
         << data << " index 1 using ($1 > 0 ? $3 : NaN):4 with lines lw 2 "
         << "lc rgb '#ff7f0e' title 'finite elements', " << data
         << " index 0 using 3:4:1 with points pt 7 ps 1.5 lc palette "
            "notitle, "
         << data
         << " index 1 using ($1 > 0 ? $3 : NaN):4:1 with points pt 5 ps 1.5 "
            "lc palette notitle\n"
         << "set title 'finite elements: lateral force = friction + tissue "
            "pressure'\n"
         << "set xlabel 'grip level'\nset ylabel 'force (N)'\n"
         << "set xrange [0.5:" << levels + 0.5
         << "]\nset yrange [0:*]\nset key top left\n"
         << "set style fill solid 0.8\nset boxwidth 0.35\nset xtics 1\n";
      if (fe.empty())
        // an empty panel with its label (a curve above the range: gnuplot
        // refuses to plot nothing)
        gp << "set label 1 'no finite element level pulled yet' at graph "
              "0.5, 0.5 center\nset yrange [0:1]\nplot 2 notitle\n";
      else
        gp << "plot " << data
           << " index 1 using ($1 - 0.18):4 with boxes lc rgb "
           << "'#ff7f0e' title 'lateral (all)', " << data
           << " index 1 using ($1 + 0.18):5 with boxes lc rgb '#2ca02c' title "
              "'friction-only part', "
           << data << " index 1 using 1:3 with linespoints pt 7 lc rgb "
           << "'black' title 'normal'\n";
      gp << "unset multiplot\n";
      gp.commit();
    }
    run_gnuplot(
        directory, base + "_figure.gnuplot", {base + "_figure.png"}, log);
  }

  void write_rigid_record(const RigidSweepRecord &record,
                          const std::string      &filename)
  {
    Hdf5Record::write(
        filename,
        [&](Hdf5Record::Group &file)
        {
          file.attribute("schema", std::string("softgrasp rigid sweep"));
          file.attribute("settings", record.settings);
          file.attribute("friction", record.friction);
          file.vector("targets", record.targets);
          std::vector<double> level, grip, normal, lateral, lateral_max;
          for (const auto &p : record.points)
          {
            level.push_back(p.level);
            grip.push_back(p.grip_force);
            normal.push_back(p.normal_mean);
            lateral.push_back(p.lateral_mean);
            lateral_max.push_back(p.lateral_max);
          }
          auto points = file.group("grip_link");
          points.vector("level", level);
          points.vector("grip_force", grip);
          points.vector("normal_mean", normal);
          points.vector("lateral_mean", lateral);
          points.vector("lateral_max", lateral_max);
        });
  }

  RigidSweepRecord read_rigid_record(const std::string &filename)
  {
    RigidSweepRecord record;
    Hdf5Record::read(
        filename,
        "delete it; the sweep then runs its rigid stage again",
        [&](const Hdf5Record::Reader &file)
        {
          if (file.string_attribute("", "schema") != "softgrasp rigid sweep")
            throw std::runtime_error("it is not a rigid sweep record");
          record.settings = file.string_attribute("", "settings");
          record.friction = file.number_attribute("", "friction");
          if (!(record.friction >= 0) || !std::isfinite(record.friction))
            throw std::runtime_error("its friction coefficient is " +
                                     std::to_string(record.friction));
          record.targets         = file.table("targets", 0, 1);
          const auto level       = file.table("grip_link/level", 0, 1);
          const auto grip        = file.table("grip_link/grip_force", 0, 1);
          const auto normal      = file.table("grip_link/normal_mean", 0, 1);
          const auto lateral     = file.table("grip_link/lateral_mean", 0, 1);
          const auto lateral_max = file.table("grip_link/lateral_max", 0, 1);
          const std::size_t n    = level.size();
          if (grip.size() != n || normal.size() != n || lateral.size() != n ||
              lateral_max.size() != n)
            throw std::runtime_error(
                "its grip link datasets have different lengths");
          for (std::size_t i = 0; i < n; ++i)
          {
            SweepPoint p;
            p.level        = static_cast<unsigned int>(level[i]);
            p.grip_force   = grip[i];
            p.normal_mean  = normal[i];
            p.lateral_mean = lateral[i];
            p.lateral_max  = lateral_max[i];
            record.points.push_back(p);
          }
        });
    return record;
  }
} // namespace softgrasp
