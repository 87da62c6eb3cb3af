/* ---------------------------------------------------------------------------
 * Example: a finger dragged across soft tissue, with friction
 *
 * A rescue robot's finger that pulls on a limb presses into the tissue and
 * drags it along. This example presses a rigid cylinder (a finger link,
 * R = 10 mm) 5 mm into a soft block bonded to a rigid base (plane strain)
 * and pulls it 20 mm along the surface with Coulomb friction mu = 0.5.
 *
 * What it shows:
 *  - 'Time/Integrator = implicit dynamic': the quasi-static solver stops on
 *    this drag after 8.5 mm of pull, where a contact node at the trailing
 *    edge has to snap from stick to slip and no static state is near; with
 *    inertia (backward Euler) the step is cut back, the node moves through
 *    and the run goes on quasi-statically (doc/contact.md).
 *  - The contact force on every geom, split with the patch's mean normal n
 *    into the normal force and the lateral (drag) force, and the lateral
 *    force split again into friction alone and the rest: the pressure of
 *    tissue heaped ahead of the finger. The drag exceeds mu times the
 *    normal force although no node exceeds Coulomb's cone.
 *  - A picture of the forces over time (drag_forces.png) and the numbers
 *    (drag_forces.dat, and the solver's own CSV/HDF5 and VTU files).
 *
 * The report names whatever bodies and geoms the .prm defines, so the
 * program runs any drag (2D or 3D) set up in a .prm.
 *
 * Run:   ./frictional_drag [frictional_drag.prm]
 * ------------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/mechanics/mechanics_solver.h>
#include <softgrasp/mechanics/solver_program.h>

namespace
{
  using softgrasp::GeomContactForce;

  /// Drag (lateral) force, its friction-only part and the rest (N or N/m).
  struct Split
  {
    double normal, lateral, friction, pressure;
  };

  Split split(const GeomContactForce &f)
  {
    const double lateral  = f.lateral_part.norm();
    const double friction = f.friction.norm();
    return {f.normal_force(), lateral, friction, lateral - friction};
  }

  /// Print the forces of every geom at the end and write the force table
  /// and its picture into the output directory.
  template <int dim> void report(const softgrasp::MechanicsSolver<dim> &solver)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const auto &records = solver.contact_force_history();
    const auto &bodies  = solver.rigid_bodies().bodies();
    if (records.empty())
      return;
    const std::string unit = dim == 2 ? "N/m" : "N";
    const std::string dir  = solver.parameters().output.directory;
    std::ofstream     table(dir + "/drag_forces.dat");
    table << "# time (s), then per geom: normal, lateral, friction-only, "
             "pressure part of the lateral force ("
          << unit << ")\n# geoms:";
    std::vector<std::string> names;
    for (const auto &body : bodies)
      for (const auto &geom : body.geoms())
        names.push_back(body.name() + "/" + geom.name);
    for (const auto &name : names)
      table << ' ' << name;
    table << '\n';
    for (const auto &record : records)
    {
      table << record.time;
      for (const auto &body_forces : record.forces)
        for (const auto &f : body_forces)
        {
          const Split s = split(f);
          table << ' ' << s.normal << ' ' << s.lateral << ' ' << s.friction
                << ' ' << s.pressure;
        }
      table << '\n';
    }
    table.close(); // complete before gnuplot reads it

    std::cout << "\nAt the end (t = " << records.back().time << " s), in "
              << unit << (dim == 2 ? " (per metre of finger)" : "") << ":\n";
    unsigned int k = 0;
    for (const auto &body_forces : records.back().forces)
      for (const auto &f : body_forces)
      {
        const Split s = split(f);
        std::cout << "  " << std::left << std::setw(24) << names[k++]
                  << std::right << " normal " << std::setw(9) << s.normal
                  << "  drag " << std::setw(9) << s.lateral << " ("
                  << std::setprecision(3)
                  << (s.normal > 0 ? s.lateral / s.normal : 0.0)
                  << " of normal)  friction alone " << std::setw(9)
                  << s.friction << "  pressure " << s.pressure
                  << std::setprecision(6) << '\n';
      }

    std::ofstream gp(dir + "/drag_forces.gnuplot");
    gp << "set terminal pngcairo size 1000,650 noenhanced\n"
       << "set output '"
       << softgrasp::AtomicFile::temporary_name("drag_forces.png") << "'\n"
       << "set title 'Contact forces on the finger: normal, drag (lateral) "
          "and its friction-only part'\n"
       << "set xlabel 'time t (s)'\nset ylabel 'force (" << unit << ")'\n"
       << "set key left top\nset grid\nplot ";
    for (unsigned int g = 0; g < names.size(); ++g)
    {
      const unsigned int c = 2 + 4 * g;
      gp << (g ? ", " : "") << "'drag_forces.dat' using 1:" << c
         << " with lines lw 2 title '" << names[g] << ": normal', "
         << "'' using 1:" << c + 1 << " with lines lw 2 title '" << names[g]
         << ": drag', '' using 1:" << c + 2 << " with lines dt 2 lw 2 title '"
         << names[g] << ": friction alone'";
    }
    gp << '\n';
    gp.close();
    if (softgrasp::run_gnuplot(
            dir, "drag_forces.gnuplot", {"drag_forces.png"}, std::cout))
      std::cout << "Picture: " << dir << "/drag_forces.png" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  softgrasp::SolverProgram program;
  program.default_parameter_file = "frictional_drag.prm";
  program.report_2d              = report<2>;
  program.report_3d              = report<3>;
  return program.run(argc, argv);
}
