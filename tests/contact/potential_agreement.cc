// Frictionless contact with each implicit step the minimisation of one
// potential ('Contact/Enforcement = incremental potential', 'Potential
// integration = nodes': an augmented Lagrangian on each node's gap, Uzawa outer
// iterations until the penetration is below 1e-3 of the node spacing) against
// the exact Lagrange multipliers of the default enforcement, on the same
// meshes:
//  1. the contact patch test (a flat rigid plate compresses a randomly
//     distorted block by 10 %; 2D and 3D, Q1 and Q2): the pressure uniform
//     within 0.1 %, the plate force within 0.1 % of the multipliers' and,
//     in 3D, of the homogeneous uniaxial solution, and equal to the support
//     reaction to the Newton tolerance;
//  2. the frictionless plane-strain drag (the block and cylinder of
//     examples/frictional_drag, pressed 5 mm, pulled 5 mm) and
//  3. the frictionless 3D tube drag (programs/softgrasp/tube_drag.prm,
//     coarse, pressed 5 mm, pulled 4 mm, quasi-static): the normal force
//     at every step within 0.1 % of the multipliers', the drag (a
//     discretisation error: a frictionless finger meets the same tissue
//     all along) within 0.1 % of the normal force of theirs.
// Everywhere the penetration stays within 1e-3 of the node spacing and the
// potential never rose along an accepted Newton update.
#include "../contact_factory.h"
#include "../material_factory.h"
#include "../solver_factory.h"
#include "../tests.h"
#include "problem_file.h"

#include <map>
#include <softgrasp/materials/homogeneous_loading.h>

using namespace softgrasp_tests;

namespace
{
  // at the nodes, as the multipliers (the implicit default is the faces)
  const std::string potential =
      "subsection Contact\n set Enforcement = incremental potential\n"
      " set Potential integration = nodes\nend\n";

  /// The largest penetration over the node spacing, and the Newton
  /// updates that raised the potential, of a finished run.
  template <int dim>
  std::pair<double, double>
  penetration_and_increases(const softgrasp::Simulation<dim> &run)
  {
    double penetration = 0;
    for (const auto &node : run.contact()->nodes())
      if (node.body >= 0)
        penetration = std::max(
            penetration,
            -node.gap / std::pow(node.reference_area, 1.0 / (dim - 1)));
    double      increases = 0;
    const auto &history   = run.history();
    for (std::size_t row = 1; row < history.rows.size(); ++row)
      increases += history.value(row, "energy_increases");
    return {dealii::Utilities::MPI::max(penetration, MPI_COMM_WORLD),
            increases};
  }

  template <int dim>
  void check_potential_run(const softgrasp::Simulation<dim> &run)
  {
    const auto [penetration, increases] = penetration_and_increases(run);
    SG_CHECK(penetration <= 1e-3, "penetration within 1e-3 of the spacing");
    SG_CHECK(increases == 0, "the potential never rose along an update");
  }

  struct Plate
  {
    double force = 0, spread = 0; ///< N; relative
  };

  template <int dim>
  Plate compress(const unsigned int degree, const std::string &enforcement)
  {
    auto run = make_solver<dim>(plate_compression_prm(dim, degree) +
                                "subsection Output\n"
                                " set Directory = output-patch\nend\n" +
                                enforcement);
    run->run();
    const auto [p_min, p_max] = closed_pressure_range(*run);
    const auto  &history      = run->history();
    const auto   forces = run->contact_output()->geom_forces(run->system());
    const Plate  plate{forces[0][0].force[dim - 1], (p_max - p_min) / p_max};
    const double support = history.value(
        history.rows.size() - 1, dim == 3 ? "reaction_4_z" : "reaction_2_y");
    SG_CHECK_CLOSE(
        plate.force, support, 1e-9, 0, "plate force = support reaction");
    if (!enforcement.empty())
      check_potential_run(*run);
    return plate;
  }

  template <int dim> void patch_test(const unsigned int degree)
  {
    const Plate lm = compress<dim>(degree, "");
    const Plate ip = compress<dim>(degree, potential);
    dealii::deallog << dim << "D Q" << degree << " patch test: plate force "
                    << ip.force << " N, pressure spread below 0.1 %: "
                    << (ip.spread <= 1e-3) << ", within 0.1 % of the "
                    << "multipliers' (" << lm.force << " N)";
    SG_CHECK(ip.spread <= 1e-3, "uniform pressure within 0.1 %");
    SG_CHECK_CLOSE(ip.force, lm.force, 1e-3, 0, "the multipliers' force");
    if (dim == 3)
    {
      const auto material = material_from_prm(
          "set Model = neo-Hookean\nset Density = 1000\n"
          "subsection neo-Hookean\nset Shear modulus = 1e4\nend\n"
          "subsection Volumetric\nset Poisson's ratio = 0.3\nend");
      const double exact =
          -softgrasp::HomogeneousLoading::uniaxial(
               *material, material->structural_directions({}), 0.9)
               .nominal_stress *
          1e-4;
      dealii::deallog << " and of the uniaxial solution (" << exact << " N)";
      SG_CHECK_CLOSE(ip.force, exact, 1e-3, 0, "the uniaxial solution");
    }
    dealii::deallog << std::endl;
  }

  /// Per recorded time after the press: normal force and drag (N).
  template <int dim>
  std::map<double, std::pair<double, double>>
  drag_history(const softgrasp::Simulation<dim> &run, const double t_press)
  {
    std::map<double, std::pair<double, double>> steps;
    for (const auto &record : run.contact_force_history())
      if (record.time > t_press + 1e-9)
        steps[std::round(record.time * 1e6) / 1e6] = {
            record.forces[0][0].normal_force(), record.forces[0][0].force[0]};
    return steps;
  }

  template <int dim>
  void drag(const std::string &name,
            const std::string &prm,
            const double       t_press,
            const double       t_end)
  {
    auto lm = make_solver<dim>(prm);
    lm->run();
    auto ip = make_solver<dim>(prm + potential);
    ip->run();
    check_potential_run(*ip);
    const auto a = drag_history(*lm, t_press), b = drag_history(*ip, t_press);
    SG_CHECK(lm->contact_force_history().back().time > t_end - 1e-9 &&
                 ip->contact_force_history().back().time > t_end - 1e-9,
             "both pulls ran to the end");
    // compared at the multipliers' steps (the potential may have cut
    // some back and taken more)
    double normal = 0, drag = 0, largest_drag = 0;
    for (const auto &[time, lm_forces] : a)
    {
      SG_CHECK(b.count(time) == 1, "the potential's run passed each step");
      const auto &ip_forces = b.at(time);
      normal =
          std::max(normal, std::abs(ip_forces.first / lm_forces.first - 1));
      drag = std::max(drag,
                      std::abs(ip_forces.second - lm_forces.second) /
                          std::abs(lm_forces.first));
      largest_drag =
          std::max(largest_drag, std::abs(ip_forces.second / ip_forces.first));
    }
    dealii::deallog << name << ": " << a.size() << " steps of the pull, "
                    << "normal force " << b.rbegin()->second.first
                    << " N at the end; at every step the normal force within "
                    << "0.1 % of the multipliers': " << (normal <= 1e-3)
                    << ", the drag within 0.1 % of the normal force of "
                    << "theirs: " << (drag <= 1e-3) << std::endl;
    std::cout << name << ": normal force difference " << normal
              << ", drag difference " << drag << ", largest drag/normal "
              << largest_drag << std::endl;
    SG_CHECK(normal <= 1e-3, "the normal force within 0.1 %");
    SG_CHECK(drag <= 1e-3, "the drag within 0.1 % of the normal force");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(4);
  for (const unsigned int degree : {1u, 2u})
  {
    patch_test<2>(degree);
    patch_test<3>(degree);
  }

  drag<2>("plane-strain drag",
          frictional_drag_prm(0) +
              "subsection Time\n set Integrator = quasi-static\n"
              " set End time = 0.75\n set Time step = 0.05\nend\n"
              "subsection Output\n set Directory = output-drag\n"
              " set VTU interval = 0\n set Verbose = false\nend\n",
          0.5,
          0.75);

  drag<3>("tube drag", frictionless_tube_pull(10, "output-tube"), 0.5, 1);
}
