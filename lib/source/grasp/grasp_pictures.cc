#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <fstream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/grasp/grasp_pictures.h>
#include <softgrasp/postprocess/principal_strains.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// The deformed surface of @p system but @p hidden_boundaries as quads
    /// of 4 x (x, y, z (mm), e_max), gathered on rank 0.
    std::vector<std::vector<double>>
    surface_quads(const SolidSystem<3>            &system,
                  const std::vector<unsigned int> &hidden_boundaries)
    {
      // The 8 vertices of the unit cell as quadrature points.
      std::vector<Point<3>> vertices;
      for (const unsigned int v : GeometryInfo<3>::vertex_indices())
        vertices.push_back(GeometryInfo<3>::unit_cell_vertex(v));
      FEValues<3>                      fe_values(system.mapping(),
                            system.fe(),
                            Quadrature<3>(vertices),
                            update_values | update_gradients |
                                update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      const auto                      &solution = system.ghosted_solution();
      std::vector<Tensor<1, 3>>        u(8);
      std::vector<Tensor<2, 3>>        grad_u(8);
      std::vector<double>              quads;
      const auto                       shown = [&](const auto &face)
      {
        return face->at_boundary() &&
               std::find(hidden_boundaries.begin(),
                         hidden_boundaries.end(),
                         face->boundary_id()) == hidden_boundaries.end();
      };
      for (const auto &cell : system.dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned() || !cell->at_boundary())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, u);
        fe_values[displacement].get_function_gradients(solution, grad_u);
        for (const unsigned int f : cell->face_indices())
          if (shown(cell->face(f)))
            for (unsigned int v = 0; v < 4; ++v)
            {
              const unsigned int q =
                  GeometryInfo<3>::face_to_cell_vertices(f, v);
              const Point<3> x = fe_values.quadrature_point(q) + u[q];
              const auto     e = PrincipalStrains::compute(
                  unit_symmetric_tensor<3>() + grad_u[q]);
              quads.insert(quads.end(),
                           {1e3 * x[0], 1e3 * x[1], 1e3 * x[2], e.e_max()});
            }
      }
      return Utilities::MPI::gather(system.communicator(), quads, 0);
    }

    /// The quads as gnuplot pm3d data; returns the largest e_max.
    double write_surface(const std::vector<std::vector<double>> &all,
                         const std::string                      &file)
    {
      double             e_top = 0;
      std::ostringstream out;
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
      AtomicFile::write(file, out.str());
      return e_top;
    }

    /// The triangles of the mesh geom named @p name in @p kinematics (none
    /// if it is not a mesh).
    const KinematicsData::Geom *mesh_geom(const KinematicsData &kinematics,
                                          const std::string    &name)
    {
      for (const auto &body : kinematics.bodies)
        for (const auto &geom : body.geoms)
          if (geom.name == name && !geom.triangles.empty())
            return &geom;
      return nullptr;
    }

    /**
     * Every geom's wire frame at its pose at @p time (mm) into @p file, and
     * the triangles of the mesh geoms, one polygon block each, into
     * @p faces_file (gnuplot 'with polygons' draws them as surfaces);
     * returns whether there were any.
     */
    bool write_geoms(const KinematicsData &kinematics,
                     const double          time,
                     const std::string    &file,
                     const std::string    &faces_file)
    {
      std::ostringstream out, faces;
      out << "# link geoms at t = " << time << " s: x y z (mm)\n";
      faces << "# mesh link triangles at t = " << time << " s: x y z (mm)\n";
      bool       any_faces = false;
      const auto write     = [](std::ostream &o, const Eigen::Vector3d &x)
      { o << 1e3 * x[0] << ' ' << 1e3 * x[1] << ' ' << 1e3 * x[2] << '\n'; };
      const RigidBodySet bodies = rigid_bodies_from(kinematics);
      for (const auto &body : bodies.bodies())
        for (unsigned int g = 0; g < body.geoms().size(); ++g)
        {
          const Pose pose = body.geom_pose(g, time);
          for (const auto &line : body.geoms()[g].shape->wireframe())
          {
            for (const auto &local : line)
              write(out, pose.to_world(local));
            out << "\n\n";
          }
          if (const auto *mesh = mesh_geom(kinematics, body.geoms()[g].name))
            for (const auto &t : mesh->triangles)
            {
              for (const unsigned int v : t)
                write(faces, pose.to_world(mesh->vertices[v]));
              faces << '\n';
              any_faces = true;
            }
        }
      AtomicFile::write(file, out.str());
      AtomicFile::write(faces_file, faces.str());
      return any_faces;
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
    const auto all = surface_quads(system, hidden_boundaries);
    if (Utilities::MPI::this_mpi_process(system.communicator()) != 0)
      return;
    const double e_top =
        write_surface(all, directory + "/" + base + "_surface.dat");
    const bool faces = write_geoms(kinematics,
                                   time,
                                   directory + "/" + base + "_geoms.dat",
                                   directory + "/" + base + "_mesh_links.dat");
    {
      AtomicFile::TextFile gp(directory + "/" + base + "_picture.gnuplot");
      gp << "set terminal pngcairo size 1100,900 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_picture.png")
         << "'\n"
         << "set title 'Indented body coloured by e_max = lambda_max - 1 "
            "(largest principal strain), finger links at t = "
         << time << " s'\n"
         << "set view 70, 30\nset view equal xyz\nset xyplane 0\n"
         << "set xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset zlabel 'z (mm)'\n"
         << "set pm3d depthorder\nset palette rgb 33,13,10\n"
         << "set cblabel 'e_max'\nset cbrange [0:" << std::max(e_top, 1e-6)
         << "]\n"
         << "splot '" << base
         << "_surface.dat' using 1:2:3:4 with pm3d notitle, '" << base
         << "_geoms.dat' using 1:2:3 with lines lc rgb '#202020' notitle";
      if (faces) // mesh links as grey surfaces
        gp << ", '" << base
           << "_mesh_links.dat' using 1:2:3 with polygons fs solid 1.0 "
              "fc rgb '#9a9aa6' notitle";
      gp << '\n';
      gp.commit();
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
                        const std::string              &closure_unit,
                        const std::string              &directory,
                        const std::string              &base,
                        std::ostream                   &log)
  {
    {
      AtomicFile::TextFile gp(directory + "/" + base + "_forces.gnuplot");
      gp << "set terminal pngcairo size 1400,650 noenhanced\n"
         << "set output '" << AtomicFile::temporary_name(base + "_forces.png")
         << "'\n"
         << "set datafile separator ','\nset key top left font ',8'\n"
         << "set grid\nset multiplot layout 1,2 title 'Link forces against "
            "closure: finite elements (solid, points) and MuJoCo (dashed)'\n";
      for (const std::string part : {"normal", "lateral"})
      {
        gp << "set xlabel 'closure beyond the equilibrium (" << closure_unit
           << ")'\n"
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
      gp.commit();
    }
    if (run_gnuplot(
            directory, base + "_forces.gnuplot", {base + "_forces.png"}, log))
      log << "Plot: " << directory << "/" << base << "_forces.png\n";
  }
} // namespace softgrasp
