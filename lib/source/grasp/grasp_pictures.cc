#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <fstream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/grasp/grasp_pictures.h>
#include <softgrasp/postprocess/principal_strains.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// Wire frame of a capsule, cylinder or sphere (rings and meridians).
    void write_geom(std::ostream         &out,
                    const std::string    &type,
                    const Eigen::Vector3d size,
                    const Pose           &pose)
    {
      const double r = size[0];
      const double h = (type == "sphere") ? 0 : size[1];
      // the profile (z, radius) along the local z axis
      std::vector<std::pair<double, double>> profile;
      const auto cap = [&](const double z0, const int first, const int last)
      {
        for (int k = first; k <= last; ++k)
        {
          const double phi = M_PI / 2 * k / 8.0;
          profile.emplace_back(z0 + r * std::sin(phi), r * std::cos(phi));
        }
      };
      if (type == "sphere")
        cap(0, -8, 8);
      else
      {
        if (type == "capsule")
          cap(-h, -8, -1);
        for (int k = 0; k <= 4; ++k)
          profile.emplace_back(-h + 2 * h * k / 4.0, r);
        if (type == "capsule")
          cap(h, 1, 8);
      }
      const auto point =
          [&](const double angle, const std::pair<double, double> &zr)
      {
        const Eigen::Vector3d x =
            pose.to_world(Eigen::Vector3d(zr.second * std::cos(angle),
                                          zr.second * std::sin(angle),
                                          zr.first));
        out << 1e3 * x[0] << ' ' << 1e3 * x[1] << ' ' << 1e3 * x[2] << '\n';
      };
      for (const auto &zr : profile) // rings
      {
        for (unsigned int i = 0; i <= 24; ++i)
          point(2 * M_PI * i / 24, zr);
        out << "\n\n";
      }
      for (unsigned int i = 0; i < 8; ++i) // meridians
      {
        for (const auto &zr : profile)
          point(2 * M_PI * i / 8, zr);
        out << "\n\n";
      }
    }

    void
    write_box(std::ostream &out, const Eigen::Vector3d size, const Pose &pose)
    {
      for (unsigned int axis = 0; axis < 3; ++axis)
        for (int a = -1; a <= 1; a += 2)
          for (int b = -1; b <= 1; b += 2)
          {
            for (int c = -1; c <= 1; c += 2)
            {
              Eigen::Vector3d local;
              local[axis]             = c * size[axis];
              local[(axis + 1) % 3]   = a * size[(axis + 1) % 3];
              local[(axis + 2) % 3]   = b * size[(axis + 2) % 3];
              const Eigen::Vector3d x = pose.to_world(local);
              out << 1e3 * x[0] << ' ' << 1e3 * x[1] << ' ' << 1e3 * x[2]
                  << '\n';
            }
            out << "\n\n";
          }
    }
  } // namespace

  void write_grasp_picture(const SolidSystem<3>            &system,
                           const KinematicsData            &kinematics,
                           const double                     time,
                           const std::vector<unsigned int> &hidden_boundaries,
                           const std::string               &directory,
                           const std::string               &base,
                           std::ostream                    &log)
  {
    // The 8 vertices of the unit cell as quadrature points.
    std::vector<Point<3>> vertices;
    for (const unsigned int v : GeometryInfo<3>::vertex_indices())
      vertices.push_back(GeometryInfo<3>::unit_cell_vertex(v));
    const Quadrature<3>              at_vertices(vertices);
    FEValues<3>                      fe_values(system.mapping(),
                          system.fe(),
                          at_vertices,
                          update_values | update_gradients |
                              update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 3>>        u(8);
    std::vector<Tensor<2, 3>>        grad_u(8);
    std::vector<double>              quads; // 4 x (x, y, z, e_max)
    for (const auto &cell : system.dof_handler().active_cell_iterators())
    {
      if (!cell->is_locally_owned() || !cell->at_boundary())
        continue;
      bool reinitialised = false;
      for (const unsigned int f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        const unsigned int id = cell->face(f)->boundary_id();
        if (std::find(hidden_boundaries.begin(), hidden_boundaries.end(), id) !=
            hidden_boundaries.end())
          continue;
        if (!reinitialised)
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(system.ghosted_solution(),
                                                      u);
          fe_values[displacement].get_function_gradients(
              system.ghosted_solution(), grad_u);
          reinitialised = true;
        }
        for (unsigned int v = 0; v < 4; ++v)
        {
          const unsigned int q = GeometryInfo<3>::face_to_cell_vertices(f, v);
          const Point<3>     x = fe_values.quadrature_point(q) + u[q];
          const auto         e =
              PrincipalStrains::compute(unit_symmetric_tensor<3>() + grad_u[q]);
          quads.insert(quads.end(),
                       {1e3 * x[0], 1e3 * x[1], 1e3 * x[2], e.e_max()});
        }
      }
    }
    const auto all = Utilities::MPI::gather(system.communicator(), quads, 0);
    if (Utilities::MPI::this_mpi_process(system.communicator()) != 0)
      return;

    double e_top = 0;
    {
      std::ofstream out(directory + "/" + base + "_surface.dat");
      out << "# deformed surface: x y z (mm) e_max (1); one quad per block\n";
      for (const auto &part : all)
        for (std::size_t i = 0; i + 16 <= part.size(); i += 16)
        {
          for (unsigned int v = 0; v < 4; ++v)
          {
            out << part[i + 4 * v] << ' ' << part[i + 4 * v + 1] << ' '
                << part[i + 4 * v + 2] << ' ' << part[i + 4 * v + 3] << '\n';
            e_top = std::max(e_top, part[i + 4 * v + 3]);
            if (v == 1)
              out << '\n';
          }
          out << "\n\n";
        }
    }
    {
      std::ofstream out(directory + "/" + base + "_geoms.dat");
      out << "# link geoms at t = " << time << " s: x y z (mm)\n";
      // the pose at the time: interpolate the recorded samples
      for (const auto &body : kinematics.bodies)
      {
        if (body.geoms.empty())
          continue;
        const PoseTrajectory trajectory(kinematics.time, body.poses, body.name);
        const Pose           pose = trajectory.pose(time);
        for (const auto &geom : body.geoms)
        {
          if (geom.type == "box")
            write_box(out, geom.size, pose * geom.local_pose);
          else if (geom.type == "capsule" || geom.type == "cylinder" ||
                   geom.type == "sphere")
            write_geom(out, geom.type, geom.size, pose * geom.local_pose);
        }
      }
    }
    {
      std::ofstream gp(directory + "/" + base + "_picture.gnuplot");
      gp << "set terminal pngcairo size 1100,900 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_picture.png")
         << "'\n"
         << "set title 'Indented body coloured by e_max (largest principal "
            "Green-Lagrange strain), finger links at t = "
         << time << " s'\n"
         << "set view 70, 30\nset view equal xyz\nset xyplane 0\n"
         << "set xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset zlabel 'z (mm)'\n"
         << "set pm3d depthorder\nset palette rgb 33,13,10\n"
         << "set cblabel 'e_max'\nset cbrange [0:" << std::max(e_top, 1e-6)
         << "]\n"
         << "splot '" << base
         << "_surface.dat' using 1:2:3:4 with pm3d notitle, '" << base
         << "_geoms.dat' using 1:2:3 with lines lc rgb '#202020' notitle\n";
    }
    if (run_gnuplot(
            directory, base + "_picture.gnuplot", {base + "_picture.png"}, log))
      log << "Picture: " << directory << "/" << base << "_picture.png\n";
  }

  namespace
  {
    /// "geom" of "body/geom".
    std::string short_name(const std::string &link)
    {
      return link.substr(link.find('/') + 1);
    }
  } // namespace

  void write_force_plot(const std::string              &csv_name,
                        const std::vector<std::string> &links,
                        const std::string              &directory,
                        const std::string              &base,
                        std::ostream                   &log)
  {
    {
      std::ofstream gp(directory + "/" + base + "_forces.gnuplot");
      gp << "set terminal pngcairo size 1400,650 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_forces.png")
         << "'\n"
         << "set datafile separator ','\nset key top left font ',8'\n"
         << "set grid\nset multiplot layout 1,2 title 'Link forces against "
            "closure: finite elements (solid, points) and MuJoCo (dashed)'\n";
      for (const std::string part : {"normal", "lateral"})
      {
        gp << "set xlabel 'closure beyond the equilibrium (rad)'\n"
           << "set ylabel '" << part << " force (N)'\nplot ";
        for (std::size_t l = 0; l < links.size(); ++l)
          gp << (l ? ", " : "") << "'" << csv_name
             << "' using (column('closure')):(column('" << links[l] << ":FE_"
             << part << "')) with linespoints lt " << l + 1 << " dt 1 title '"
             << short_name(links[l]) << " FE', '" << csv_name
             << "' using (column('closure')):(column('" << links[l] << ":MJ_"
             << part << "')) with lines lt " << l + 1 << " dt 2 title '"
             << short_name(links[l]) << " MuJoCo'";
        gp << "\n";
      }
      gp << "unset multiplot\n";
    }
    if (run_gnuplot(
            directory, base + "_forces.gnuplot", {base + "_forces.png"}, log))
      log << "Plot: " << directory << "/" << base << "_forces.png\n";
  }
} // namespace softgrasp
