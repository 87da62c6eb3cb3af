// Matrix-free internal forces (InternalForceOperator, the explicit solver's
// kernel) against a plain FEValues assembly of f_int,i = int P : grad N_i dV
// with the material library's scalar stress: Q1 and Q2, 2D (plane strain)
// and 3D, two materials (neo-Hookean and a two-family HGO tissue, i.e.
// anisotropic with fibre directions per point), a randomly distorted mesh
// with hanging nodes, and a smooth finite displacement field. Forces and
// the strain energy agree to 1e-12 (relative).
// Patch test: under a homogeneous deformation u = (F0 - I) X the interior
// nodal forces vanish and the forces on the face x = 1 add up to the
// traction P0 N times the face area.
#include "../material_factory.h"
#include "../tests.h"

#include <deal.II/base/function_lib.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/explicit/internal_force_operator.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  template <int dim> class Displacement : public Function<dim>
  {
  public:
    Displacement()
        : Function<dim>(dim)
    {
    }
    double value(const Point<dim> &p, const unsigned int c) const override
    {
      return 0.08 * std::sin(1.3 * p[0] + 0.7 * c) * std::cos(0.9 * p[1]) +
             0.05 * p[(c + 1) % dim] + (dim == 3 ? 0.03 * p[2] * p[c] : 0);
    }
  };

  template <int dim> class Homogeneous : public Function<dim>
  {
  public:
    explicit Homogeneous(const Tensor<2, dim> &H)
        : Function<dim>(dim)
        , H(H)
    {
    }
    double value(const Point<dim> &p, const unsigned int c) const override
    {
      return (H * p)[c];
    }
    Tensor<2, dim> H;
  };

  MaterialLibrary two_materials()
  {
    const auto fragments =
        softgrasp_tests::model_fragments("Simo-Taylor", "0.4");
    return softgrasp_tests::library_from_prm(
        {fragments[0].second, fragments.back().second});
  }

  template <int dim>
  void compare(const unsigned int degree, const MaterialLibrary &materials)
  {
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 3, 0, 1);
    tria.refine_global(1);
    for (const auto &cell : tria.active_cell_iterators())
    {
      if (cell->is_locally_owned() && cell->center()[0] < 0.2 &&
          cell->center()[1] < 0.2)
        cell->set_refine_flag(); // hanging nodes
    }
    tria.execute_coarsening_and_refinement();
    GridTools::distort_random(0.2, tria, true, 5);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[0] > 0.5 ? 1 : 0);

    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dofs(tria);
    dofs.distribute_dofs(fe);
    const MappingQ<dim>       mapping(1);
    AffineConstraints<double> constraints;
    constraints.reinit(DoFTools::extract_locally_relevant_dofs(dofs));
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    InternalForceOperator<dim> op(mapping, dofs, constraints, materials);
    LinearAlgebra::distributed::Vector<double> u, f, reference;
    op.initialize_dof_vector(u);
    op.initialize_dof_vector(f);
    op.initialize_dof_vector(reference);
    VectorTools::interpolate(mapping, dofs, Displacement<dim>(), u);
    constraints.distribute(u);
    const auto result = op.apply(u, f);

    // Reference: FEValues with the scalar stress.
    u.update_ghost_values();
    const QGauss<dim>                    quadrature(degree + 1);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values |
                                update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<2, dim>>          grad_u(quadrature.size());
    Vector<double>                       local(fe.dofs_per_cell);
    std::vector<types::global_dof_index> indices(fe.dofs_per_cell);
    double                               energy = 0;
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_gradients(u, grad_u);
      const Material &material = materials.get(cell->material_id());
      local                    = 0;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        // F = I + grad u in the plane, then the plane-strain slice
        Tensor<2, dim> F_dim = grad_u[q];
        for (unsigned int d = 0; d < dim; ++d)
          F_dim[d][d] += 1;
        const Tensor<2, 3> F = PlaneStrain::to_3d<dim>(F_dim);
        Material::Response r;
        material.evaluate_material(
            F,
            material.structural_directions(
                PlaneStrain::to_3d(fe_values.quadrature_point(q))),
            false,
            r);
        const Tensor<2, 3> P = F * Tensor<2, 3>(r.stress);
        energy += r.energy * fe_values.JxW(q);
        for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
        {
          const Tensor<2, dim> grad_N = fe_values[displacement].gradient(i, q);
          double               value  = 0;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              value += P[a][b] * grad_N[a][b];
          local(i) += value * fe_values.JxW(q);
        }
      }
      cell->get_dof_indices(indices);
      constraints.distribute_local_to_global(local, indices, reference);
    }
    reference.compress(VectorOperation::add);
    energy             = Utilities::MPI::sum(energy, MPI_COMM_WORLD);
    const double scale = reference.linfty_norm();
    reference -= f;
    const double difference = reference.linfty_norm() / scale;
    const double energy_difference =
        std::abs(result.energy - energy) / std::abs(energy);
    dealii::deallog << dim << "D Q" << degree << ", " << dofs.n_dofs()
                    << " dofs, hanging nodes, 2 materials: forces agree to "
                       "1e-12: "
                    << (difference < 1e-12) << ", energy agrees to 1e-12: "
                    << (energy_difference < 1e-12)
                    << ", min J > 0.5: " << (result.min_J > 0.5) << std::endl;
    SG_CHECK(difference < 1e-12, "matrix-free forces equal the FEValues ones");
    SG_CHECK(energy_difference < 1e-12, "matrix-free energy");
  }

  template <int dim> void patch(const unsigned int degree)
  {
    const auto material = softgrasp_tests::material_from_prm(
        softgrasp_tests::model_fragments("Simo-Taylor", "0.4")[0].second);
    const MaterialLibrary library = softgrasp_tests::library_from_prm(
        {softgrasp_tests::model_fragments("Simo-Taylor", "0.4")[0].second});

    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 4, 0, 1);
    GridTools::distort_random(0.25, tria, true, 7);
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dofs(tria);
    dofs.distribute_dofs(fe);
    const MappingQ<dim>       mapping(1);
    AffineConstraints<double> none;
    none.close();
    InternalForceOperator<dim>                 op(mapping, dofs, none, library);
    LinearAlgebra::distributed::Vector<double> u, f;
    op.initialize_dof_vector(u);
    op.initialize_dof_vector(f);
    // The undeformed state is stress free: zero forces and energy (in 2D
    // this checks that the plane-strain F_33 is 1, not 1 + 1).
    const auto at_rest = op.apply(u, f);
    SG_CHECK(f.linfty_norm() < 1e-12 && std::abs(at_rest.energy) < 1e-12 &&
                 std::abs(at_rest.min_J - 1) < 1e-12,
             "no force at rest");
    Tensor<2, dim> H;
    H[0][0] = 0.2;
    H[0][1] = 0.05;
    H[1][1] = -0.06;
    if (dim == 3)
      H[2][2] = -0.05;
    VectorTools::interpolate(mapping, dofs, Homogeneous<dim>(H), u);
    const auto homogeneous = op.apply(u, f);

    // The u-p-J forms (one pressure per element, mean dilatation, and the
    // linear P1 projection) are exact for a homogeneous deformation:
    // J~ = J, the same forces and energy.
    for (const auto form :
         {InternalForceOperator<dim>::Dilatation::element_constant,
          InternalForceOperator<dim>::Dilatation::element_linear})
    {
      const InternalForceOperator<dim> mixed(
          mapping, dofs, none, library, form);
      LinearAlgebra::distributed::Vector<double> f_mixed;
      mixed.initialize_dof_vector(f_mixed);
      const auto mixed_result = mixed.apply(u, f_mixed);
      f_mixed -= f;
      SG_CHECK(f_mixed.linfty_norm() < 1e-12 * f.linfty_norm() &&
                   std::abs(mixed_result.energy - homogeneous.energy) <
                       1e-12 * homogeneous.energy,
               "u-p-J equals the standard form when J is uniform");
    }

    Tensor<2, dim> F_dim = H;
    for (unsigned int d = 0; d < dim; ++d)
      F_dim[d][d] += 1;
    const Tensor<2, 3> F = PlaneStrain::to_3d<dim>(F_dim);
    Material::Response r;
    material->evaluate_material(F, {}, false, r);
    const Tensor<2, 3> P = F * Tensor<2, 3>(r.stress);

    // Nodes by position: interior and on x = 1.
    std::map<types::global_dof_index, Point<dim>> support;
    DoFTools::map_dofs_to_support_points(mapping, dofs, support);
    double         interior = 0, scale = 0;
    Tensor<1, dim> face_force;
    for (const auto &[index, x] : support)
    {
      if (!f.locally_owned_elements().is_element(index))
        continue;
      bool on_boundary = false;
      for (unsigned int d = 0; d < dim; ++d)
        on_boundary = on_boundary || x[d] < 1e-12 || x[d] > 1 - 1e-12;
      scale = std::max(scale, std::abs(f[index]));
      if (!on_boundary)
        interior = std::max(interior, std::abs(f[index]));
    }
    // Face x = 1: sum the forces of its dofs per component.
    const IndexSet    owned = f.locally_owned_elements();
    std::vector<bool> selected(dofs.n_locally_owned_dofs());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              cell->face(face)->center()[0] > 1 - 1e-12)
          {
            std::vector<types::global_dof_index> indices(fe.dofs_per_face);
            cell->face(face)->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const auto index = indices[i];
              if (!owned.is_element(index))
                continue;
              const auto local = owned.index_within_set(index);
              if (selected[local])
                continue;
              selected[local] = true;
              face_force[fe.face_system_to_component_index(i).first] +=
                  f[index];
            }
          }
    for (unsigned int d = 0; d < dim; ++d)
      face_force[d] = Utilities::MPI::sum(face_force[d], MPI_COMM_WORLD);
    interior              = Utilities::MPI::max(interior, MPI_COMM_WORLD);
    scale                 = Utilities::MPI::max(scale, MPI_COMM_WORLD);
    double traction_error = 0;
    for (unsigned int d = 0; d < dim; ++d) // N = e_x, area 1
      traction_error =
          std::max(traction_error, std::abs(face_force[d] - P[d][0]));
    traction_error /= P.norm();
    dealii::deallog << dim << "D Q" << degree
                    << " patch: interior forces vanish (1e-10): "
                    << (interior < 1e-10 * scale)
                    << ", face x = 1 carries P0 N A (1e-10): "
                    << (traction_error < 1e-10) << std::endl;
    SG_CHECK(interior < 1e-10 * scale, "homogeneous state in equilibrium");
    SG_CHECK(traction_error < 1e-10, "face force equals the traction");
  }

  /**
   * The u-p-J forces are the gradient of the operator's energy
   * E(u) = int Psi_iso dV + int U(J~) dV (what the explicit energy balance
   * relies on): f(u) . w against (E(u + e w) - E(u - e w)) / 2e on a
   * distorted Q2 mesh with two materials and a non-uniform J, for the
   * constant and the linear projection; the two differ from each other and
   * from the pointwise form.
   */
  template <int dim> void energy_gradient(const MaterialLibrary &materials)
  {
    using Operator = InternalForceOperator<dim>;
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 3, 0, 1);
    GridTools::distort_random(0.2, tria, true, 3);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[0] > 0.5 ? 1 : 0);
    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    DoFHandler<dim>     dofs(tria);
    dofs.distribute_dofs(fe);
    const MappingQ<dim>       mapping(1);
    AffineConstraints<double> none;
    none.close();
    std::map<typename Operator::Dilatation, Vector<double>> forces;
    for (const auto form : {Operator::Dilatation::pointwise,
                            Operator::Dilatation::element_constant,
                            Operator::Dilatation::element_linear})
    {
      const Operator op(
          mapping, dofs, none, materials, form, Operator::Kernel::reference);
      LinearAlgebra::distributed::Vector<double> u, w, f, shifted;
      for (auto *v : {&u, &w, &f, &shifted})
        op.initialize_dof_vector(*v);
      VectorTools::interpolate(mapping, dofs, Displacement<dim>(), u);
      for (const auto i : u.locally_owned_elements())
        w[i] = std::sin(0.37 * i + 0.1); // a direction touching every dof
      op.apply(u, f);
      const double eps = 1e-6, derivative = f * w;
      shifted = u;
      shifted.add(eps, w);
      const double plus = op.apply(shifted, f).energy;
      shifted.add(-2 * eps, w);
      const double minus = op.apply(shifted, f).energy;
      const double error = std::abs((plus - minus) / (2 * eps) - derivative) /
                           std::abs(derivative);
      const char *name = form == Operator::Dilatation::pointwise ? "pointwise"
                         : form == Operator::Dilatation::element_constant
                             ? "P0"
                             : "P1";
      dealii::deallog << dim << "D Q2 " << name
                      << ": f . w equals dE/du . w within 1e-6: "
                      << (error < 1e-6) << std::endl;
      SG_CHECK(error < 1e-6, "forces are the energy's gradient");
      op.apply(u, f);
      forces[form] = Vector<double>(f.begin(), f.end());
    }
    const auto difference = [&](const auto a, const auto b)
    {
      Vector<double> d = forces[a];
      d -= forces[b];
      return Utilities::MPI::max(d.linfty_norm(), MPI_COMM_WORLD) /
             Utilities::MPI::max(forces[b].linfty_norm(), MPI_COMM_WORLD);
    };
    const bool distinct =
        difference(Operator::Dilatation::element_linear,
                   Operator::Dilatation::element_constant) > 1e-3 &&
        difference(Operator::Dilatation::element_linear,
                   Operator::Dilatation::pointwise) > 1e-3;
    dealii::deallog << dim
                    << "D Q2: P1, P0 and pointwise forces differ: " << distinct
                    << std::endl;
    SG_CHECK(distinct, "the three volumetric forms are different elements");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const MaterialLibrary materials = two_materials();
  for (const unsigned int degree : {1, 2})
  {
    compare<2>(degree, materials);
    compare<3>(degree, materials);
    patch<2>(degree);
    patch<3>(degree);
  }
  energy_gradient<2>(materials);
  energy_gradient<3>(materials);
}
