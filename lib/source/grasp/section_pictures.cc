#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/grasp/section_pictures.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  std::vector<std::vector<Point<3>>>
  SectionView::geom_outlines(const RigidBodySet &bodies,
                             const double        time,
                             const Point<3>     &origin,
                             const Tensor<1, 3> &normal,
                             const Tensor<1, 3> &e1,
                             const Tensor<1, 3> &e2)
  {
    std::vector<std::vector<Point<3>>> outlines;
    const auto                         eigen = [](const Point<3> &p)
    { return Eigen::Vector3d(p[0], p[1], p[2]); };
    for (const auto &body : bodies.bodies())
      for (unsigned int g = 0; g < body.geoms().size(); ++g)
      {
        const auto &shape  = *body.geoms()[g].shape;
        const Pose  pose   = body.geom_pose(g, time);
        const auto  inside = [&](const Point<3> &p)
        { return shape.query(pose.to_local(eigen(p))).distance < 0; };
        // Seed: the geom's origin projected onto the plane.
        const Eigen::Vector3d o = pose.position;
        const Point<3>        c =
            Point<3>(o[0], o[1], o[2]) -
            ((Point<3>(o[0], o[1], o[2]) - origin) * normal) * normal;
        if (!inside(c) || !std::isfinite(shape.bounding_radius()))
          continue;
        std::vector<Point<3>> outline;
        for (unsigned int k = 0; k <= 72; ++k)
        {
          const double       a   = 2 * M_PI * k / 72;
          const Tensor<1, 3> dir = std::cos(a) * e1 + std::sin(a) * e2;
          double             lo = 0, hi = 2 * shape.bounding_radius();
          for (unsigned int it = 0; it < 40; ++it)
          {
            const double mid                  = 0.5 * (lo + hi);
            (inside(c + mid * dir) ? lo : hi) = mid;
          }
          outline.push_back(c + lo * dir);
        }
        outlines.push_back(outline);
      }
    return outlines;
  }

  namespace
  {
    /// The e_max palette of the pictures: blue, cyan, green, yellow, red.
    const std::vector<std::pair<double, std::array<int, 3>>> stops = {
        {0.0, {{48, 18, 200}}},
        {0.25, {{20, 170, 230}}},
        {0.5, {{60, 200, 80}}},
        {0.75, {{250, 220, 40}}},
        {1.0, {{220, 30, 30}}}};

    std::string colour(const double value)
    {
      const double v = std::clamp(value, 0.0, 1.0);
      std::size_t  k = 0;
      while (k + 2 < stops.size() && v > stops[k + 1].first)
        ++k;
      const double w =
          (v - stops[k].first) / (stops[k + 1].first - stops[k].first);
      std::ostringstream out;
      out << '#' << std::hex << std::setfill('0');
      for (unsigned int c = 0; c < 3; ++c)
        out << std::setw(2)
            << static_cast<int>(std::lround((1 - w) * stops[k].second[c] +
                                            w * stops[k + 1].second[c]));
      return out.str();
    }

    /// @p text inside a single-quoted gnuplot string (' doubled).
    std::string quoted(const std::string &text)
    {
      std::string out;
      for (const char c : text)
        out += c == '\'' ? std::string("''") : std::string(1, c);
      return out;
    }

    /// Colours of the tissues, by position in the sorted list of ids.
    const std::vector<std::string> tissue_colours = {
        "#e8b49a", "#f3dc7a", "#b0b0d8", "#c0504d", "#f0f0e8", "#7fb3d5"};

    /// Polygons as gnuplot objects (mm) in one panel.
    void draw_polygons(
        std::ostream                                               &gp,
        const SectionView                                          &view,
        const bool                                                  deformed,
        const std::function<std::string(const Section::Polygon &)> &fill,
        unsigned int                                               &object)
    {
      for (const auto &p : view.section.polygons)
      {
        const auto &corners = deformed ? p.deformed : p.reference;
        gp << "set object " << ++object << " polygon from ";
        for (std::size_t k = 0; k <= corners.size(); ++k)
        {
          const auto  &x = corners[k % corners.size()];
          const double u = 1000 * ((x - view.section.origin) * view.e1);
          const double v = 1000 * ((x - view.section.origin) * view.e2);
          gp << (k == 0 ? "" : " to ") << u << "," << v;
        }
        gp << " fc rgb '" << fill(p)
           << "' fs solid 1.0 border lc rgb '#404040' lw 0.3 front\n";
      }
    }

    void write_links(const std::string                        &file,
                     const SectionView                        &view,
                     const std::vector<std::vector<Point<3>>> &links)
    {
      std::ostringstream out;
      out << "# link cross-sections: u v (mm)\n";
      for (const auto &outline : links)
      {
        for (const auto &x : outline)
          out << 1000 * ((x - view.section.origin) * view.e1) << ' '
              << 1000 * ((x - view.section.origin) * view.e2) << '\n';
        out << "\n\n";
      }
      AtomicFile::write(file, out.str());
    }
  } // namespace

  namespace
  {
    /// (u, v) of @p x in the plane of @p view (m).
    std::pair<double, double> in_plane(const SectionView &view,
                                       const Point<3>    &x)
    {
      return {(x - view.section.origin) * view.e1,
              (x - view.section.origin) * view.e2};
    }

    /// Writes every number of the section (polygons, skin outline, link
    /// outlines) as CSV and gnuplot data; returns the largest e_max.
    double write_section_data(const SectionView &view,
                              const std::string &directory,
                              const std::string &stem)
    {
      const auto        &s     = view.section;
      double             e_top = 1e-6;
      std::ostringstream csv;
      csv << std::setprecision(9)
          << "polygon,corner,material_id,e_max,X,Y,Z,x,y,z\n";
      for (std::size_t p = 0; p < s.polygons.size(); ++p)
      {
        const auto &poly = s.polygons[p];
        e_top            = std::max(e_top, poly.e_max);
        for (std::size_t k = 0; k < poly.reference.size(); ++k)
        {
          const auto &X = poly.reference[k], &x = poly.deformed[k];
          csv << p << ',' << k << ',' << int(poly.material) << ',' << poly.e_max
              << ',' << X[0] << ',' << X[1] << ',' << X[2] << ',' << x[0] << ','
              << x[1] << ',' << x[2] << '\n';
        }
      }
      AtomicFile::write(directory + "/" + stem + "_section.csv", csv.str());
      std::ostringstream skin, dat;
      skin << std::setprecision(9)
           << "segment,point,u_before,v_before,u_after,v_after\n";
      dat << "# skin outline: u v before, u v after (mm)\n";
      for (std::size_t i = 0; i < s.outline.size(); ++i)
        for (unsigned int k = 0; k < 2; ++k)
        {
          const auto [ub, vb] = in_plane(view, s.outline[i].reference[k]);
          const auto [ua, va] = in_plane(view, s.outline[i].deformed[k]);
          skin << i << ',' << k << ',' << ub << ',' << vb << ',' << ua << ','
               << va << '\n';
          dat << 1000 * ub << ' ' << 1000 * vb << ' ' << 1000 * ua << ' '
              << 1000 * va << (k == 1 ? "\n\n" : "\n");
        }
      AtomicFile::write(directory + "/" + stem + "_skin.csv", skin.str());
      AtomicFile::write(directory + "/" + stem + "_skin.dat", dat.str());
      write_links(directory + "/" + stem + "_links_equilibrium.dat",
                  view,
                  view.links_equilibrium);
      write_links(directory + "/" + stem + "_links_indented.dat",
                  view,
                  view.links_indented);
      return e_top;
    }

    /// gnuplot's x and y ranges (mm) around the section, before and after.
    std::string drawing_range(const SectionView &view)
    {
      double lo_u = 1e300, hi_u = -1e300, lo_v = 1e300, hi_v = -1e300;
      for (const auto &p : view.section.polygons)
        for (const auto *corners : {&p.reference, &p.deformed})
          for (const auto &x : *corners)
          {
            const auto [u, v] = in_plane(view, x);
            lo_u = std::min(lo_u, 1000 * u), hi_u = std::max(hi_u, 1000 * u);
            lo_v = std::min(lo_v, 1000 * v), hi_v = std::max(hi_v, 1000 * v);
          }
      if (view.section.polygons.empty())
        lo_u = lo_v = -1, hi_u = hi_v = 1;
      const double       pad = 0.05 * std::max(hi_u - lo_u, hi_v - lo_v) + 5;
      std::ostringstream range;
      range << "set xrange [" << lo_u - pad << ":" << hi_u + pad << "]\n"
            << "set yrange [" << lo_v - pad << ":" << hi_v + pad << "]\n";
      return range.str();
    }

    /// The tissues in a section: their colours and legend names.
    struct TissueLegend
    {
      TissueLegend(const SectionView                               &view,
                   const std::map<types::material_id, std::string> &names)
          : names(names)
      {
        for (const auto &p : view.section.polygons)
          if (std::find(ids.begin(), ids.end(), p.material) == ids.end())
            ids.push_back(p.material);
        std::sort(ids.begin(), ids.end());
      }

      std::string colour(const types::material_id id) const
      {
        const auto i = std::find(ids.begin(), ids.end(), id) - ids.begin();
        return tissue_colours[i % tissue_colours.size()];
      }

      std::string name(const types::material_id id) const
      {
        const auto it = names.find(id);
        return it == names.end() ? "material " + std::to_string(id)
                                 : it->second;
      }

      std::vector<types::material_id>                  ids;
      const std::map<types::material_id, std::string> &names;
    };

    /// The three panels: tissues before and after, e_max after.
    void write_section_script(const SectionView  &view,
                              const TissueLegend &legend,
                              const double        e_top,
                              const std::string  &directory,
                              const std::string  &stem)
    {
      AtomicFile::TextFile gp(directory + "/" + stem + "_section.gnuplot");
      gp << "set terminal pngcairo size 1800,640 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(stem + "_section.png")
         << "'\n"
         << "set multiplot layout 1,3 title '" << quoted(view.title) << "'\n"
         << "set size ratio -1\n"
         << drawing_range(view) << "set xlabel 'in-plane u (mm)'\n"
         << "set ylabel 'in-plane v (mm)'\nset key outside bottom center\n";
      const std::string links_eq = stem + "_links_equilibrium.dat";
      const std::string links_in = stem + "_links_indented.dat";
      unsigned int      object   = 0;
      for (const bool deformed : {false, true})
      {
        gp << "unset object\nunset colorbox\n";
        draw_polygons(
            gp,
            view,
            deformed,
            [&](const Section::Polygon &p)
            { return legend.colour(p.material); },
            object);
        gp << "set title '"
           << (deformed ? "indented state: tissues"
                        : "equilibrium state: tissues")
           << "'\nplot ";
        for (const auto id : legend.ids)
          gp << "NaN with boxes fs solid fc rgb '" << legend.colour(id)
             << "' title '" << quoted(legend.name(id)) << "', ";
        gp << "'" << (deformed ? links_in : links_eq)
           << "' using 1:2 with filledcurves closed fc rgb '#303030' "
              "title 'finger links'\n";
      }
      gp << "unset object\n";
      draw_polygons(
          gp,
          view,
          true,
          [&](const Section::Polygon &p) { return colour(p.e_max / e_top); },
          object);
      gp << "set title 'indented state: e_max (largest principal strain)'\n"
         << "set palette defined (";
      for (std::size_t k = 0; k < stops.size(); ++k)
        gp << (k ? ", " : "") << stops[k].first << " '"
           << colour(stops[k].first) << "'";
      gp << ")\nset cbrange [0:" << e_top << "]\nset cblabel 'e_max'\n"
         << "set colorbox\nplot '" << links_in
         << "' using 1:2 with filledcurves closed fc rgb '#303030' "
            "title 'finger links', '' using 1:2:(0) with points pt -1 lc "
            "palette notitle\nunset multiplot\n";
      gp.commit();
    }

    /// The skin outline before and after, with the indented links.
    void write_skin_script(const SectionView &view,
                           const std::string &directory,
                           const std::string &stem)
    {
      AtomicFile::TextFile skin(directory + "/" + stem + "_skin.gnuplot");
      skin << "set terminal pngcairo size 900,800 noenhanced\n"
           << "set output '" << AtomicFile::temporary_name(stem + "_skin.png")
           << "'\nset title 'Skin outline before and after the "
              "indentation; "
           << quoted(view.title) << "' font ',10'\n"
           << "set size ratio -1\n"
           << drawing_range(view) << "set xlabel 'in-plane u (mm)'\n"
           << "set ylabel 'in-plane v (mm)'\nset key bottom right\n"
           << "plot '" << stem
           << "_skin.dat' using 1:2 with lines lw 2 lc rgb '#1f77b4' title "
              "'equilibrium state', '' using 3:4 with lines lw 2 lc rgb "
              "'#d62728' title 'indented state', '"
           << stem << "_links_indented.dat"
           << "' using 1:2 with lines lc rgb '#303030' title 'finger links "
              "(indented)'\n";
      skin.commit();
    }
  } // namespace

  void write_section_pictures(
      const SectionView                               &view,
      const std::map<types::material_id, std::string> &tissue_names,
      const std::string                               &directory,
      const std::string                               &base,
      std::ostream                                    &log)
  {
    const std::string stem  = base + "_" + view.name;
    const double      e_top = write_section_data(view, directory, stem);
    write_section_script(
        view, TissueLegend(view, tissue_names), e_top, directory, stem);
    write_skin_script(view, directory, stem);
    if (run_gnuplot(directory,
                    stem + "_section.gnuplot",
                    {stem + "_section.png"},
                    log) &&
        run_gnuplot(
            directory, stem + "_skin.gnuplot", {stem + "_skin.png"}, log))
      log << "Sliced views: " << directory << "/" << stem << "_section.png, "
          << stem << "_skin.png\n";
  }
} // namespace softgrasp
