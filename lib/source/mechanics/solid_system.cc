#include <algorithm>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>
#include <limits>
#include <softgrasp/mechanics/solid_system.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  SolidSystem<dim>::SolidSystem(parallel::distributed::Triangulation<dim> &tria,
                                const MaterialLibrary         &materials,
                                const BoundaryConditions<dim> &bcs,
                                const SolverParameters        &parameters,
                                const unsigned int             mapping_degree,
                                TimerOutput                   &timer)
      : triangulation(tria)
      , materials(materials)
      , boundary_conditions(bcs)
      , parameters(parameters)
      , timer(timer)
      , finite_element(FE_Q<dim>(parameters.discretization.degree), dim)
      , reference_mapping(mapping_degree)
      , quadrature(parameters.discretization.degree + 1)
      , face_quadrature(parameters.discretization.degree + 1)
      , dofs(tria)
      , assembler(materials,
                  bcs,
                  parameters.discretization.formulation,
                  parameters.linear_solver.block_augmentation)
      , linear_solver(parameters.linear_solver)
  {
  }

  template <int dim> SolidSystem<dim>::~SolidSystem()
  {
    linear_solver.abandon_factorization();
  }

  template <int dim> void SolidSystem<dim>::release_factorization()
  {
    linear_solver.forget_factorization();
  }

  template <int dim> void SolidSystem<dim>::setup()
  {
    TimerOutput::Scope scope(timer, "setup");
    dofs.distribute_dofs(finite_element);
    owned               = dofs.locally_owned_dofs();
    relevant            = DoFTools::extract_locally_relevant_dofs(dofs);
    const MPI_Comm comm = communicator();

    u.reinit(owned, comm);
    u_ghosted.reinit(owned, relevant, comm);
    for (auto *v : {&rhs, &residual, &f_int, &f_ext})
      v->reinit(owned, relevant, comm, /*vector_writable=*/true);

    update_constraints();
    if (with_tangent)
    {
      TrilinosWrappers::SparsityPattern sparsity(owned, owned, relevant, comm);
      DoFTools::make_sparsity_pattern(dofs,
                                      sparsity,
                                      homogeneous_constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));
      sparsity.compress();
      linear_solver.forget_matrix(); // before the matrix is replaced
      tangent.reinit(sparsity);
    }
    else
    {
      linear_solver.forget_matrix();
      tangent.clear();
    }

    reaction_dofs.clear();
    std::vector<IndexSet> component_dofs(dim);
    for (unsigned int c = 0; c < dim; ++c)
    {
      ComponentMask mask(dim, false);
      mask.set(c, true);
      component_dofs[c] = DoFTools::extract_dofs(dofs, mask);
    }
    for (const auto id : boundary_conditions.reaction_boundary_ids())
    {
      const IndexSet boundary =
          DoFTools::extract_boundary_dofs(dofs, ComponentMask(), {id}) & owned;
      std::vector<IndexSet> per_component;
      for (unsigned int c = 0; c < dim; ++c)
        per_component.push_back(boundary & component_dofs[c]);
      reaction_dofs.push_back(per_component);
    }
    linear_solver.set_problem_size(dofs.n_dofs());
    if (with_tangent && linear_solver.type() == LinearSolverType::iterative)
      compute_rigid_body_modes();
    split_volumetric =
        with_tangent && linear_solver.type() == LinearSolverType::iterative &&
        parameters.discretization.formulation == Formulation::mixed_upJ &&
        parameters.linear_solver.block_preconditioner;

    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
    {
      lower[d] = std::numeric_limits<double>::max();
      upper[d] = -std::numeric_limits<double>::max();
    }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], cell->vertex(v)[d]);
            upper[d] = std::max(upper[d], cell->vertex(v)[d]);
          }
    domain_size = 0;
    for (unsigned int d = 0; d < dim; ++d)
      domain_size =
          std::max(domain_size,
                   Utilities::MPI::max(upper[d], communicator()) +
                       Utilities::MPI::max(-lower[d], communicator()));
  }

  template <int dim> double SolidSystem<dim>::length_scale() const
  {
    return domain_size;
  }

  template <int dim> void SolidSystem<dim>::compute_rigid_body_modes()
  {
    // Translations and rotations evaluated at the support points.
    const unsigned int                         n_modes = dim == 2 ? 3 : 6;
    std::vector<TrilinosWrappers::MPI::Vector> modes(
        n_modes, TrilinosWrappers::MPI::Vector(owned, communicator()));
    const Quadrature<dim> support(finite_element.get_unit_support_points());
    FEValues<dim>         fe_values(
        reference_mapping, finite_element, support, update_quadrature_points);
    std::vector<types::global_dof_index> indices(
        finite_element.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      cell->get_dof_indices(indices);
      for (unsigned int k = 0; k < indices.size(); ++k)
      {
        if (!owned.is_element(indices[k]))
          continue;
        const unsigned int c =
            finite_element.system_to_component_index(k).first;
        const Point<dim> &x  = fe_values.quadrature_point(k);
        modes[c][indices[k]] = 1.0;
        if (dim == 2)
          modes[2][indices[k]] = (c == 0 ? -x[1] : x[0]);
        else
        {
          // rotations about x, y, z: (0,-z,y), (z,0,-x), (-y,x,0)
          const double rot[3][3] = {
              {0, -x[2], x[1]}, {x[2], 0, -x[0]}, {-x[1], x[0], 0}};
          for (unsigned int r = 0; r < 3; ++r)
            modes[3 + r][indices[k]] = rot[r][c];
        }
      }
    }
    for (auto &m : modes)
      m.compress(VectorOperation::insert);
    linear_solver.set_rigid_body_modes(modes);
  }

  template <int dim>
  void SolidSystem<dim>::set_tangent_needed(const bool needed)
  {
    with_tangent = needed;
  }

  template <int dim> double SolidSystem<dim>::update_constraints()
  {
    update_ghosts();
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    homogeneous_constraints.clear();
    homogeneous_constraints.reinit(relevant);
    homogeneous_constraints.merge(constraints);

    double violation = 0;
    for (const auto &d : boundary_conditions.dirichlet)
    {
      std::map<types::global_dof_index, double> values;
      VectorTools::interpolate_boundary_values(reference_mapping,
                                               dofs,
                                               d.boundary_id,
                                               *d.displacement,
                                               values,
                                               d.components);
      for (const auto &[index, g] : values)
      {
        if (constraints.is_constrained(index))
          continue;
        const double increment = g - u_ghosted[index];
        constraints.add_line(index);
        constraints.set_inhomogeneity(index, increment);
        homogeneous_constraints.add_line(index);
        if (owned.is_element(index))
          violation = std::max(violation, std::abs(increment));
      }
    }
    constraints.close();
    homogeneous_constraints.close();
    return Utilities::MPI::max(violation, communicator());
  }

  template <int dim>
  void SolidSystem<dim>::start_assembly(const bool with_matrix)
  {
    update_ghosts();
    if (with_matrix)
    {
      tangent = 0;
      rhs     = 0;
      build_tangent_constraints();
      if (split_volumetric)
        volumetric.reinit(owned,
                          relevant,
                          communicator(),
                          tangent_homogeneous,
                          nodal_conditions);
    }
    residual = 0;
    f_int    = 0;
    f_ext    = 0;
  }

  template <int dim>
  void SolidSystem<dim>::compress_assembly(const bool with_matrix)
  {
    if (with_matrix)
    {
      tangent.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
      if (split_volumetric)
        volumetric.finalize();
    }
    residual.compress(VectorOperation::add);
    f_int.compress(VectorOperation::add);
    f_ext.compress(VectorOperation::add);
  }

  template <int dim>
  bool SolidSystem<dim>::share_failure(AssemblyResult &result) const
  {
    const unsigned int none = std::numeric_limits<unsigned int>::max();
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator());
    const unsigned int failing_rank =
        Utilities::MPI::min(result.ok ? none : rank, communicator());
    if (failing_rank == none)
      return false;
    result.ok          = false;
    result.failed_cell = Utilities::MPI::broadcast(
        communicator(), result.failed_cell, failing_rank);
    result.failed_J = Utilities::MPI::broadcast(
        communicator(), result.failed_J, failing_rank);
    return true;
  }

  template <int dim>
  void SolidSystem<dim>::apply_nodal_conditions(const bool with_matrix)
  {
    if (nodal_conditions == nullptr)
      return;
    if (!with_matrix)
      nodal_conditions->evaluate(*this);
    else
      nodal_conditions->add_node_terms(tangent_constraints, tangent, rhs);
    nodal_conditions->apply_to_residual(residual);
  }

  template <int dim>
  typename SolidSystem<dim>::AssemblyResult
  SolidSystem<dim>::assemble(const bool with_matrix)
  {
    TimerOutput::Scope scope(timer, with_matrix ? "assembly" : "residual");
    AssertThrow(!with_matrix || with_tangent,
                ExcMessage("This SolidSystem was set up without a tangent "
                           "matrix (set_tangent_needed(false))."));
    start_assembly(with_matrix);
    AssemblyResult result;

    using Iterator   = typename DoFHandler<dim>::active_cell_iterator;
    using CellFilter = FilteredIterator<Iterator>;
    auto worker      = [&](const Iterator           &cell,
                      AssemblyScratchData<dim> &scratch,
                      AssemblyCopyData         &copy)
    {
      assembler.assemble(
          cell,
          u_ghosted,
          with_matrix,
          inertia,
          with_matrix && split_volumetric,
          dilatation_state.coefficients(cell->active_cell_index()),
          scratch,
          copy);
    };
    const bool recording =
        dilatation_state.active() && !dilatation_state.recorded();
    auto copier = [&](const AssemblyCopyData &copy)
    {
      if (copy.failed)
      {
        if (result.ok)
        {
          result.ok          = false;
          result.failed_cell = copy.failed_cell;
          result.failed_J    = copy.failed_J;
        }
        return;
      }
      result.energy += copy.energy;
      result.strain_energy += copy.strain_energy;
      result.load_potential += copy.load_potential;
      Vector<double> cell_rhs(copy.external);
      cell_rhs -= copy.internal;
      f_int.add(copy.dof_indices, copy.internal);
      f_ext.add(copy.dof_indices, copy.external);
      homogeneous_constraints.distribute_local_to_global(
          cell_rhs, copy.dof_indices, residual);
      if (with_matrix)
        distribute_cell_tangent(copy, cell_rhs);
      if (recording)
        dilatation_state.store(copy.cell_index, copy.coefficients);
      if (with_matrix && dilatation_state.active())
        dilatation_state.store(copy.cell_index, copy.linearization);
    };
    WorkStream::run(
        CellFilter(IteratorFilters::LocallyOwnedCell(), dofs.begin_active()),
        CellFilter(IteratorFilters::LocallyOwnedCell(), dofs.end()),
        worker,
        copier,
        AssemblyScratchData<dim>(reference_mapping,
                                 finite_element,
                                 quadrature,
                                 face_quadrature,
                                 parameters.discretization.pressure_degree()),
        AssemblyCopyData());

    compress_assembly(with_matrix);
    if (share_failure(result))
      return last_result = result;
    if (recording)
      dilatation_state.set_recorded(true);
    apply_nodal_conditions(with_matrix);
    // the energy and its parts in one reduction
    const double parts[3] = {
        result.energy, result.strain_energy, result.load_potential};
    double sums[3];
    Utilities::MPI::sum(
        make_array_view(parts), communicator(), make_array_view(sums));
    result.energy         = sums[0];
    result.strain_energy  = sums[1];
    result.load_potential = sums[2];
    if (nodal_conditions != nullptr)
      result.energy += nodal_conditions->energy();
    result.residual_norm = residual.l2_norm();
    result.residual_max  = residual.linfty_norm();
    result.force_scale   = std::max(f_int.l2_norm(), f_ext.l2_norm());
    return last_result   = result;
  }

  template <int dim>
  const typename SolidSystem<dim>::AssemblyResult &
  SolidSystem<dim>::last_assembly() const
  {
    return last_result;
  }

  template <int dim> void SolidSystem<dim>::begin_newton_solve()
  {
    // With a potential, J~ and p~ stay projected from the displacement, so
    // that the residual is the gradient of the condensed energy.
    const bool potential =
        nodal_conditions != nullptr && nodal_conditions->is_potential();
    if (parameters.discretization.formulation == Formulation::mixed_upJ &&
        !potential)
      dilatation_state.start(triangulation.n_active_cells());
  }

  template <int dim> void SolidSystem<dim>::end_newton_solve()
  {
    dilatation_state.clear();
  }

  template <int dim> void SolidSystem<dim>::begin_update()
  {
    u_start = u;
    dilatation_state.begin_update();
  }

  template <int dim>
  void SolidSystem<dim>::apply_update(const TrilinosWrappers::MPI::Vector &du,
                                      const double alpha)
  {
    u = u_start;
    u.add(alpha, du);
    if (!dilatation_state.recorded())
      return;
    du_ghosted.reinit(owned, relevant, communicator());
    du_ghosted = du;
    dilatation_state.apply_update(dofs, du_ghosted, alpha);
  }

  template <int dim>
  LinearSolver::Result
  SolidSystem<dim>::solve(TrilinosWrappers::MPI::Vector &du,
                          const double                   relative_tolerance)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    du.reinit(owned, communicator());
    const bool symmetric =
        !boundary_conditions.has_follower_loads() &&
        (nodal_conditions == nullptr || nodal_conditions->symmetric());
    const LinearSolver::Result result =
        split_volumetric
            ? linear_solver.solve(
                  tangent, volumetric, du, rhs, symmetric, relative_tolerance)
            : linear_solver.solve(
                  tangent, du, rhs, symmetric, relative_tolerance);
    tangent_constraints.distribute(du);
    return result;
  }

  template <int dim>
  void SolidSystem<dim>::distribute_cell_tangent(const AssemblyCopyData &copy,
                                                 Vector<double> &cell_rhs)
  {
    // The cell matrices are copied only where nodal conditions rewrite
    // their rows.
    const FullMatrix<double> *matrix = &copy.matrix;
    FullMatrix<double>        transformed;
    if (nodal_conditions != nullptr)
    {
      transformed = copy.matrix;
      nodal_conditions->transform_cell_rows(
          copy.dof_indices, transformed, cell_rhs);
      matrix = &transformed;
    }
    tangent_constraints.distribute_local_to_global(
        *matrix, cell_rhs, copy.dof_indices, tangent, rhs);
    if (!split_volumetric)
      return;
    // The volumetric coupling stays out of the matrix; only its share of
    // the inhomogeneous constraints enters the right-hand side.
    const FullMatrix<double> *coupling = &copy.volumetric;
    Vector<double>            zero(cell_rhs.size());
    if (nodal_conditions != nullptr)
    {
      transformed = copy.volumetric;
      nodal_conditions->transform_cell_rows(
          copy.dof_indices, transformed, zero);
      coupling = &transformed;
      zero     = 0;
    }
    tangent_constraints.distribute_local_to_global(
        zero, copy.dof_indices, rhs, *coupling);
    volumetric.add_cell(
        copy.dof_indices, copy.G, copy.D, copy.S_inverse, copy.volume);
  }

  template <int dim> void SolidSystem<dim>::build_tangent_constraints()
  {
    tangent_constraints.clear();
    tangent_constraints.reinit(relevant);
    if (nodal_conditions != nullptr)
      nodal_conditions->add_constraints(tangent_constraints);
    // The nodal conditions constrain only dofs that are free here.
    tangent_constraints.merge(
        constraints,
        AffineConstraints<double>::MergeConflictBehavior::no_conflicts_allowed);
    tangent_constraints.close();
    if (!split_volumetric)
      return;
    tangent_homogeneous.clear();
    tangent_homogeneous.reinit(relevant);
    for (const auto &line : tangent_constraints.get_lines())
    {
      tangent_homogeneous.add_line(line.index);
      tangent_homogeneous.add_entries(line.index, line.entries);
    }
    tangent_homogeneous.close();
  }

  template <int dim> void SolidSystem<dim>::set_inertia(const InertiaTerm &term)
  {
    inertia = term;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector SolidSystem<dim>::lumped_mass() const
  {
    TrilinosWrappers::MPI::Vector mass;
    mass.reinit(owned, relevant, communicator(), /*vector_writable=*/true);
    FEValues<dim>                        fe_values(reference_mapping,
                            finite_element,
                            quadrature,
                            update_values | update_JxW_values);
    std::vector<types::global_dof_index> indices(
        finite_element.n_dofs_per_cell());
    Vector<double> local;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        CellAssembler<dim>::lumped_mass(
            fe_values, materials.get(cell->material_id()).density(), local);
        cell->get_dof_indices(indices);
        mass.add(indices, local); // hanging nodes keep their own mass
      }
    mass.compress(VectorOperation::add);
    TrilinosWrappers::MPI::Vector owned_mass(owned, communicator());
    owned_mass = mass;
    return owned_mass;
  }

  template <int dim> std::string SolidSystem<dim>::linear_solver_name() const
  {
    return LinearSolverParameters::name(linear_solver.type()) +
           (split_volumetric
                ? " (block: AMG on u, element Schur complement for p)"
                : "");
  }

  template <int dim>
  double
  SolidSystem<dim>::residual_dot(const TrilinosWrappers::MPI::Vector &du) const
  {
    return residual * du;
  }

  template <int dim>
  void SolidSystem<dim>::set_forces(
      const std::function<double(types::global_dof_index)> &internal,
      const std::function<double(types::global_dof_index)> &external)
  {
    TrilinosWrappers::MPI::Vector a(owned, communicator()), b(a);
    for (const auto i : owned)
    {
      a[i] = internal(i);
      b[i] = external(i);
    }
    a.compress(VectorOperation::insert);
    b.compress(VectorOperation::insert);
    f_int = a;
    f_ext = b;
  }

  template <int dim>
  std::map<types::boundary_id, Tensor<1, dim>>
  SolidSystem<dim>::reactions() const
  {
    std::map<types::boundary_id, Tensor<1, dim>> result;
    const auto ids = boundary_conditions.reaction_boundary_ids();
    for (unsigned int b = 0; b < ids.size(); ++b)
    {
      Tensor<1, dim> force;
      for (unsigned int c = 0; c < dim; ++c)
        for (const auto index : reaction_dofs[b][c])
          force[c] += f_int[index] - f_ext[index];
      result[ids[b]] = Utilities::MPI::sum(force, communicator());
    }
    return result;
  }

  template <int dim>
  std::vector<Tensor<1, dim>> SolidSystem<dim>::point_displacements(
      const std::vector<Point<dim>> &points) const
  {
    std::vector<Tensor<1, dim>> result;
    for (const Point<dim> &p : points)
    {
      Tensor<1, dim> value;
      double         found = 0;
      try
      {
        const auto cell_and_point = GridTools::find_active_cell_around_point(
            reference_mapping, dofs, p);
        if (cell_and_point.first.state() == IteratorState::valid &&
            cell_and_point.first->is_locally_owned())
        {
          const Quadrature<dim> q(
              GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
          FEValues<dim> fe_values(
              reference_mapping, finite_element, q, update_values);
          fe_values.reinit(cell_and_point.first);
          std::vector<Tensor<1, dim>> u_q(1);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(
              u_ghosted, u_q);
          value = u_q[0];
          found = 1;
        }
      }
      catch (...)
      {
        // not in this rank's part of the mesh
      }
      value = Utilities::MPI::sum(value, communicator());
      found = Utilities::MPI::sum(found, communicator());
      if (found > 0)
        result.push_back(value / found);
      else
      {
        Tensor<1, dim> nan;
        for (unsigned int d = 0; d < dim; ++d)
          nan[d] = std::numeric_limits<double>::quiet_NaN();
        result.push_back(nan);
      }
    }
    return result;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &SolidSystem<dim>::residual_vector() const
  {
    return residual;
  }

  template <int dim>
  const TrilinosWrappers::SparseMatrix &SolidSystem<dim>::tangent_matrix() const
  {
    return tangent;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &SolidSystem<dim>::internal_forces() const
  {
    return f_int;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &SolidSystem<dim>::external_forces() const
  {
    return f_ext;
  }

  template <int dim>
  const AffineConstraints<double> &SolidSystem<dim>::constraint_set() const
  {
    return homogeneous_constraints;
  }

  template <int dim>
  const IndexSet &SolidSystem<dim>::locally_owned_dofs() const
  {
    return owned;
  }

  template <int dim>
  const IndexSet &SolidSystem<dim>::locally_relevant_dofs() const
  {
    return relevant;
  }

  template <int dim> void SolidSystem<dim>::update_ghosts()
  {
    u_ghosted = u;
  }

  template <int dim> TrilinosWrappers::MPI::Vector &SolidSystem<dim>::solution()
  {
    return u;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  SolidSystem<dim>::ghosted_solution() const
  {
    return u_ghosted;
  }

  template <int dim>
  const DoFHandler<dim> &SolidSystem<dim>::dof_handler() const
  {
    return dofs;
  }

  template <int dim> DoFHandler<dim> &SolidSystem<dim>::dof_handler()
  {
    return dofs;
  }

  template <int dim> const Mapping<dim> &SolidSystem<dim>::mapping() const
  {
    return reference_mapping;
  }

  template <int dim> const FiniteElement<dim> &SolidSystem<dim>::fe() const
  {
    return finite_element;
  }

  template <int dim> MPI_Comm SolidSystem<dim>::communicator() const
  {
    return triangulation.get_communicator();
  }

  template <int dim> types::global_dof_index SolidSystem<dim>::n_dofs() const
  {
    return dofs.n_dofs();
  }

  template class SolidSystem<2>;
  template class SolidSystem<3>;
} // namespace softgrasp
