// Explicit dynamics (central difference, lumped Gauss-Lobatto mass,
// matrix-free internal forces): axial vibration of a bar fixed at x = 0 and
// free at x = L. With Poisson's ratio 0 the bar is one-dimensional and its
// first axial mode has the angular frequency omega_1 = pi c / (2 L), c =
// sqrt(E / rho). Started in the mode's velocity shape at small amplitude,
// the tip's period must match 2 pi / omega_1 within 1 % (Q1 and Q2), the
// energy balance must hold within 1 % at every step, and the step from the
// power iteration must be stable (for Q1 it equals the analytic h/c of
// linear elements with lumped mass). The lumped mass adds up to rho V.
// With stiffness-proportional damping the mode decays at the analytic rate.
#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>
#include <softgrasp/explicit/central_difference.h>
#include <softgrasp/explicit/lumped_mass.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  constexpr double L = 1, mu = 5e3, rho = 1000;

  class ModeVelocity : public Function<3>
  {
  public:
    explicit ModeVelocity(const double V)
        : Function<3>(3)
        , V(V)
    {
    }
    double value(const Point<3> &p, const unsigned int c) const override
    {
      return c == 0 ? V * std::sin(M_PI * p[0] / (2 * L)) : 0.0;
    }
    double V;
  };

  MaterialLibrary bar_material()
  {
    return softgrasp_tests::library_from_prm(
        {"set Model = neo-Hookean\nset Density = 1000\n"
         "subsection neo-Hookean\nset Shear modulus = 5e3\nend\n"
         "subsection Volumetric\nset Energy = quadratic\n"
         "set Poisson's ratio = 0\nend"});
  }

  /// A bar of n elements along x, cross-section 0.1 m x 0.1 m (boundary id
  /// 0 at x = 0), with its matrix-free force, lumped mass and vectors.
  struct Bar
  {
    Bar(const unsigned int     degree,
        const unsigned int     elements,
        const MaterialLibrary &materials)
        : tria(MPI_COMM_WORLD)
        , fe(FE_Q<3>(degree), 3)
        , dofs(tria)
        , mapping(1)
    {
      GridGenerator::subdivided_hyper_rectangle(
          tria, {elements, 1, 1}, Point<3>(), Point<3>(L, 0.1, 0.1), true);
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(0); // colorize also numbers the cells
      dofs.distribute_dofs(fe);
      none.close();
      force = std::make_unique<InternalForceOperator<3>>(
          mapping, dofs, none, materials);
      for (auto *v : {&mass, &u0, &v0})
        force->initialize_dof_vector(*v);
      compute_lumped_mass(mapping, dofs, none, materials, mass);
    }
    parallel::distributed::Triangulation<3>    tria;
    const FESystem<3>                          fe;
    DoFHandler<3>                              dofs;
    const MappingQ<3>                          mapping;
    AffineConstraints<double>                  none;
    std::unique_ptr<InternalForceOperator<3>>  force;
    LinearAlgebra::distributed::Vector<double> mass, u0, v0;
  };

  /// The tip dof, the x component at (L, 0, 0), if this rank owns it.
  types::global_dof_index tip_dof(const Bar &bar)
  {
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(bar.mapping, bar.dofs, support);
    types::global_dof_index tip = numbers::invalid_dof_index;
    for (const auto &[i, x] : support)
      if (bar.dofs.locally_owned_dofs().is_element(i) &&
          x.distance(Point<3>(L, 0, 0)) < 1e-12 &&
          (tip == numbers::invalid_dof_index || i < tip))
        tip = i; // the node's first dof is its x component (FESystem)
    return tip;
  }

  void run(const unsigned int     degree,
           const unsigned int     elements,
           const MaterialLibrary &materials)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    Bar            bar(degree, elements, materials);
    const auto    &dofs    = bar.dofs;
    const auto    &mapping = bar.mapping;
    const auto    &mass    = bar.mass;
    auto          &v0      = bar.v0;
    const double   total   = mass.l1_norm() / 3;
    SG_CHECK(std::abs(total - rho * L * 0.01) < 1e-12 * total,
             "lumped mass equals rho V");

    IndexSet fixed =
        DoFTools::extract_boundary_dofs(dofs, ComponentMask(), {0});
    fixed          = fixed & dofs.locally_owned_dofs();
    const double E = 2 * mu, c = std::sqrt(E / rho);
    const double omega = M_PI * c / (2 * L), V = 1e-3 * c;
    VectorTools::interpolate(mapping, dofs, ModeVelocity(V), v0);

    const types::global_dof_index tip = tip_dof(bar);

    CentralDifference<3> integrator(*bar.force, mass, fixed);
    integrator.initialize(0, bar.u0, v0);
    const double        dt_critical = integrator.critical_time_step();
    const double        dt          = 0.9 * dt_critical;
    const double        period      = 2 * M_PI / omega;
    std::vector<double> crossings;
    double              previous = 0, worst_balance = 0;
    bool                stable = true;
    while (integrator.time() < 1.6 * period && stable)
    {
      stable = integrator.step(dt) == CentralDifference<3>::StepResult::ok;
      const auto &u     = integrator.displacement();
      double      tip_u = tip != numbers::invalid_dof_index ? u[tip] : 0.0;
      tip_u             = Utilities::MPI::sum(tip_u, comm);
      if (previous > 0 && tip_u <= 0)
        crossings.push_back(integrator.time() -
                            dt * tip_u / (tip_u - previous));
      previous = tip_u;
      worst_balance =
          std::max(worst_balance, integrator.energies().balance_error);
    }
    SG_CHECK(stable && crossings.size() >= 1, "ran through half a period");
    // u_tip = V/omega sin(omega t) crosses zero downwards at t = T/2 (+ k T)
    const double measured = 2 * crossings[0];
    const double error    = std::abs(measured / period - 1);
    dealii::deallog << "Q" << degree << ", " << elements
                    << " elements: period within 1 %: " << (error < 0.01)
                    << ", energy balance within 1 %: " << (worst_balance < 0.01)
                    << ", time step 0.9 x 2/omega_max stable: " << stable
                    << std::endl;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "Q" << degree << ": period " << measured << " s, analytic "
                << period << " s, error " << error << ", energy balance "
                << worst_balance << ", dt " << dt << " s (critical "
                << dt_critical << " s, h/c = " << L / elements / degree / c
                << " s)" << std::endl;
    SG_CHECK(error < 0.01, "axial period");
    if (degree == 1) // 1D linear elements, lumped mass: omega_max = 2 c / h
    {
      const double h_over_c = L / elements / c;
      dealii::deallog << "Q1 critical step equals h/c within 2 %: "
                      << (std::abs(dt_critical / h_over_c - 1) < 0.02)
                      << std::endl;
      SG_CHECK(std::abs(dt_critical / h_over_c - 1) < 0.02, "critical step");
    }
    SG_CHECK(worst_balance < 0.01, "energy balance");
  }
  /// Stiffness damping beta (Rayleigh): started in the first mode, the tip
  /// swings with the logarithmic decrement 2 pi xi / sqrt(1 - xi^2) of
  /// xi = beta omega_1 / 2 (within 3 %), the energy balance with the
  /// damping's dissipation holds within 1 %, and the step shortened for the
  /// highest mode's damping (2/omega_max (sqrt(1 + xi^2) - xi)) is stable
  /// although that mode is overdamped.
  void damped(const MaterialLibrary &materials)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    Bar            bar(1, 20, materials);
    IndexSet       fixed =
        DoFTools::extract_boundary_dofs(bar.dofs, ComponentMask(), {0});
    fixed              = fixed & bar.dofs.locally_owned_dofs();
    const double c     = std::sqrt(2 * mu / rho);
    const double omega = M_PI * c / (2 * L);
    VectorTools::interpolate(
        bar.mapping, bar.dofs, ModeVelocity(1e-3 * c), bar.v0);
    const double         xi = 0.05, beta = 2 * xi / omega;
    CentralDifference<3> integrator(*bar.force, bar.mass, fixed, 0, beta);
    integrator.initialize(0, bar.u0, bar.v0);
    const double critical = integrator.critical_time_step();
    const double xi_max   = beta / critical;
    const double dt =
        0.9 * critical * (std::sqrt(1 + xi_max * xi_max) - xi_max);
    const types::global_dof_index tip = tip_dof(bar);
    // the largest tip displacement in each half period with u > 0
    std::vector<double> peaks;
    double              previous = 0, peak = 0, worst_balance = 0;
    bool                stable = true;
    while (integrator.time() < 2.6 * 2 * M_PI / omega && stable)
    {
      stable = integrator.step(dt) == CentralDifference<3>::StepResult::ok;
      double tip_u = tip != numbers::invalid_dof_index
                         ? integrator.displacement()[tip]
                         : 0.0;
      tip_u        = Utilities::MPI::sum(tip_u, comm);
      if (tip_u > 0)
        peak = std::max(peak, tip_u);
      if (previous > 0 && tip_u <= 0)
      {
        peaks.push_back(peak);
        peak = 0;
      }
      previous = tip_u;
      worst_balance =
          std::max(worst_balance, integrator.energies().balance_error);
    }
    SG_CHECK(stable && peaks.size() >= 3, "ran through two periods");
    const double decrement = std::log(peaks[0] / peaks[2]) / 2;
    const double measured =
        decrement / std::sqrt(4 * M_PI * M_PI + decrement * decrement);
    dealii::deallog << "stiffness damping: decay within 3 % of xi = beta "
                       "omega_1 / 2: "
                    << (std::abs(measured / xi - 1) < 0.03)
                    << ", energy balance within 1 %: " << (worst_balance < 0.01)
                    << ", damped step stable (xi = " << std::setprecision(2)
                    << xi_max << " at omega_max): " << stable << std::endl;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "stiffness damping: xi measured " << measured
                << ", expected " << xi << ", energy balance " << worst_balance
                << ", dt " << dt << " s (critical " << critical << " s)"
                << std::endl;
    SG_CHECK(std::abs(measured / xi - 1) < 0.03, "decay rate");
    SG_CHECK(worst_balance < 0.01, "energy balance with damping");
  }

  /// Ten times the critical step blows up: a step that inverts an element
  /// or produces NaN is refused and the last good state is kept.
  void unstable(const MaterialLibrary &materials)
  {
    Bar bar(1, 10, materials);
    VectorTools::interpolate(bar.mapping, bar.dofs, ModeVelocity(0.5), bar.v0);
    CentralDifference<3> integrator(
        *bar.force, bar.mass, IndexSet(bar.dofs.n_dofs()));
    integrator.initialize(0, bar.u0, bar.v0);
    const double dt      = 10 * integrator.critical_time_step();
    bool         refused = false;
    unsigned int steps   = 0;
    for (; steps < 200 && !refused; ++steps)
    {
      const auto   before = integrator.displacement();
      const double t      = integrator.time();
      refused = integrator.step(dt) != CentralDifference<3>::StepResult::ok;
      if (refused)
      {
        auto difference = integrator.displacement();
        difference -= before;
        SG_CHECK(difference.linfty_norm() == 0 && integrator.time() == t,
                 "the refused step leaves the state as it was");
      }
    }
    dealii::deallog << "10 x the critical step: blow-up detected and the step "
                       "refused, state kept: "
                    << refused << std::endl;
    SG_CHECK(refused, "blow-up detected");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const MaterialLibrary materials = bar_material();
  run(1, 20, materials);
  run(2, 10, materials);
  damped(materials);
  unstable(materials);
}
