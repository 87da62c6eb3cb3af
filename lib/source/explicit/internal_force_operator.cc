#include <array>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/explicit/internal_force_operator.h>
#include <softgrasp/mechanics/element_dilatation.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    bool has_anisotropic_material(const MaterialLibrary &materials)
    {
      for (const auto id : materials.material_ids())
        if (materials.get(id).isochoric_model().n_structural_directions() > 0)
          return true;
      return false;
    }

    /// The structural directions at every quadrature point of every batch.
    template <int dim, int degree>
    std::vector<StructuralDirections>
    directions_at_points(const MatrixFree<dim, double> &data,
                         const MaterialLibrary         &materials)
    {
      constexpr unsigned int width = VectorizedDouble::size();
      FEEvaluation<dim, degree, degree + 1, dim, double> phi(data);
      std::vector<StructuralDirections> result(data.n_cell_batches() *
                                               phi.n_q_points * width);
      for (unsigned int cell = 0; cell < data.n_cell_batches(); ++cell)
      {
        phi.reinit(cell);
        const Material &material =
            materials.get(data.get_cell_iterator(cell, 0)->material_id());
        for (unsigned int q = 0; q < phi.n_q_points; ++q)
        {
          const auto x = phi.quadrature_point(q);
          for (unsigned int lane = 0;
               lane < data.n_active_entries_per_cell_batch(cell);
               ++lane)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = x[d][lane];
            result[(cell * phi.n_q_points + q) * width + lane] =
                material.structural_directions(PlaneStrain::to_3d(p));
          }
        }
      }
      return result;
    }

    /**
     * The linear (P1) element-wise pressure p~ at every quadrature point of
     * one cell batch (ElementDilatation, lane by lane), from the points'
     * F. Returns the volumetric energy int U(J~) dV of the batch. A lane
     * whose projected dilatation is not positive keeps p~ = 0 and lowers
     * @p min_J to J~ (the caller stops the run).
     */
    template <int dim, typename Evaluation, std::size_t n_q>
    double
    linear_pressures(const Evaluation                                      &phi,
                     const std::array<Tensor<2, 3, VectorizedDouble>, n_q> &F,
                     const unsigned int                 lanes,
                     const VolumetricEnergy            &energy,
                     ElementDilatation<dim>            &projection,
                     std::array<VectorizedDouble, n_q> &pressure,
                     double                            &min_J)
    {
      std::vector<Point<dim>> points(n_q);
      std::vector<double>     JxW(n_q), J(n_q);
      double                  volumetric = 0;
      for (unsigned int lane = 0; lane < lanes; ++lane)
      {
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const auto x = phi.quadrature_point(q);
          for (unsigned int d = 0; d < dim; ++d)
            points[q][d] = x[d][lane];
          JxW[q] = phi.JxW(q)[lane];
          J[q]   = determinant(F[q])[lane];
        }
        try
        {
          projection.reinit(points, JxW, J, energy, false);
        }
        catch (const InvertedMaterialState &inverted)
        {
          min_J = std::min(min_J, inverted.J);
          continue;
        }
        for (unsigned int q = 0; q < n_q; ++q)
        {
          pressure[q][lane] = projection.pressure(q);
          volumetric += energy.energy(projection.dilatation(q)) * JxW[q];
        }
      }
      return volumetric;
    }

    /**
     * F = I + grad u at every quadrature point of a cell batch, in the
     * plane-strain slice (F_33 = 1 in 2D); inverted points and padding
     * lanes get F = I. Accumulates the cells' reference and deformed
     * volumes and lowers @p min_J to the smallest det F of the real lanes.
     */
    template <int dim, typename Evaluation, std::size_t n_q>
    void deformation(const Evaluation                                &phi,
                     const unsigned int                               lanes,
                     std::array<Tensor<2, 3, VectorizedDouble>, n_q> &F,
                     VectorizedDouble                                &volume,
                     VectorizedDouble                                &dilated,
                     double                                          &min_J)
    {
      constexpr unsigned int width = VectorizedDouble::size();
      for (unsigned int q = 0; q < n_q; ++q)
      {
        Tensor<2, dim, VectorizedDouble> F_dim = phi.get_gradient(q);
        for (unsigned int d = 0; d < dim; ++d)
          F_dim[d][d] += 1.0;
        F[q]                     = PlaneStrain::to_3d<dim>(F_dim);
        const VectorizedDouble J = determinant(F[q]);
        for (unsigned int lane = 0; lane < width; ++lane)
        {
          if (lane < lanes)
            min_J = std::min(min_J, J[lane]);
          if (lane >= lanes || !(J[lane] > 0)) // padding or inverted: skip
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                F[q][i][j][lane] = (i == j) ? 1.0 : 0.0;
        }
        volume += phi.JxW(q);
        dilated += determinant(F[q]) * phi.JxW(q);
      }
    }
  } // namespace

  template <int dim>
  InternalForceOperator<dim>::InternalForceOperator(
      const Mapping<dim>              &mapping,
      const DoFHandler<dim>           &dofs,
      const AffineConstraints<double> &constraints,
      const MaterialLibrary           &materials,
      const Dilatation                 dilatation,
      const Kernel                     kernel)
      : materials(materials)
      , degree(dofs.get_fe().degree)
      , dilatation(dilatation)
  {
    if (degree != 1 && degree != 2)
      throw InputError("The explicit solver's matrix-free internal forces "
                       "support polynomial degree 1 or 2, not " +
                       std::to_string(degree) +
                       ". Fix: set 'Finite element/Polynomial degree' to 1 "
                       "or 2.");
    const bool anisotropic = has_anisotropic_material(materials);
    typename MatrixFree<dim, double>::AdditionalData additional;
    additional.tasks_parallel_scheme =
        MatrixFree<dim, double>::AdditionalData::none;
    additional.mapping_update_flags =
        update_gradients | update_JxW_values |
        (anisotropic || dilatation == Dilatation::element_linear
             ? update_quadrature_points
             : update_default);
    // One material per cell batch.
    const auto &tria = dofs.get_triangulation();
    additional.cell_vectorization_category.assign(tria.n_active_cells(), 0);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        additional.cell_vectorization_category[cell->active_cell_index()] =
            cell->material_id();
    additional.cell_vectorization_categories_strict = true;
    data.reinit(mapping, dofs, constraints, QGauss<1>(degree + 1), additional);
    if (kernel == Kernel::vectorized &&
        dilatation != Dilatation::element_linear)
      vectorized = std::make_unique<VectorizedForceKernel<dim>>(
          data,
          mapping,
          constraints,
          materials,
          dilatation == Dilatation::element_constant);
    if (anisotropic && (!vectorized || !vectorized->other_cells().empty()))
      directions = degree == 1 ? directions_at_points<dim, 1>(data, materials)
                               : directions_at_points<dim, 2>(data, materials);
  }

  template <int dim>
  void InternalForceOperator<dim>::initialize_dof_vector(VectorType &v) const
  {
    data.initialize_dof_vector(v);
  }

  template <int dim>
  const MatrixFree<dim, double> &InternalForceOperator<dim>::matrix_free() const
  {
    return data;
  }

  template <int dim>
  template <int p>
  void InternalForceOperator<dim>::local_apply(
      const MatrixFree<dim, double>               &data,
      VectorType                                  &dst,
      const VectorType                            &src,
      const std::pair<unsigned int, unsigned int> &cells) const
  {
    constexpr unsigned int                   width = VectorizedDouble::size();
    constexpr unsigned int                   n_q   = Utilities::pow(p + 1, dim);
    FEEvaluation<dim, p, p + 1, dim, double> phi(data);
    const std::vector<StructuralDirections>  isotropic(width);
    ElementDilatation<dim>                   projection(1);
    for (unsigned int cell = cells.first; cell < cells.second; ++cell)
    {
      phi.reinit(cell);
      phi.gather_evaluate(src, EvaluationFlags::gradients);
      const unsigned int lanes = data.n_active_entries_per_cell_batch(cell);
      const Material    &material =
          materials.get(data.get_cell_iterator(cell, 0)->material_id());
      std::array<Tensor<2, 3, VectorizedDouble>, n_q> F;
      VectorizedDouble                                volume = 0, dilated = 0;
      deformation<dim>(phi, lanes, F, volume, dilated, min_J);
      // u-p-J: the element's pressure p~ at every point. Mean dilatation:
      // J_e = v_e / V_e and p = U'(J_e), energy V_e U(J_e); linear: the P1
      // projections of ElementDilatation. Plus int Psi_iso dV below.
      std::array<VectorizedDouble, n_q> pressure;
      pressure.fill(VectorizedDouble(0.));
      const VolumetricEnergy &U = material.volumetric_energy();
      if (dilatation == Dilatation::element_constant)
        for (unsigned int lane = 0; lane < lanes; ++lane)
        {
          const double J_e = dilated[lane] / volume[lane];
          for (unsigned int q = 0; q < n_q; ++q)
            pressure[q][lane] = U.first_derivative(J_e);
          energy += volume[lane] * U.energy(J_e);
        }
      else if (dilatation == Dilatation::element_linear)
        energy += linear_pressures<dim>(
            phi, F, lanes, U, projection, pressure, min_J);
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const StructuralDirections *point_directions =
            directions.empty() ? isotropic.data()
                               : &directions[(cell * n_q + q) * width];
        Tensor<2, 3, VectorizedDouble> P;
        VectorizedDouble               psi;
        material.first_piola_batch(
            F[q],
            point_directions,
            lanes,
            P,
            psi,
            dilatation == Dilatation::pointwise ? nullptr : &pressure[q]);
        const VectorizedDouble JxW = phi.JxW(q);
        for (unsigned int lane = 0; lane < lanes; ++lane)
          energy += psi[lane] * JxW[lane];
        Tensor<2, dim, VectorizedDouble> P_dim;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            P_dim[i][j] = P[i][j];
        phi.submit_gradient(P_dim, q);
      }
      phi.integrate_scatter(EvaluationFlags::gradients, dst);
    }
  }

  template <int dim>
  typename InternalForceOperator<dim>::Result
  InternalForceOperator<dim>::apply(const VectorType &u, VectorType &f) const
  {
    energy = 0;
    min_J  = std::numeric_limits<double>::max();
    if (!vectorized)
    {
      if (degree == 1)
        data.cell_loop(
            &InternalForceOperator::local_apply<1>, this, f, u, true);
      else
        data.cell_loop(
            &InternalForceOperator::local_apply<2>, this, f, u, true);
    }
    else
    {
      // What MatrixFree::cell_loop does around the cells: zero f (ghosts
      // too), ghost values of u, and the sum of f's ghost entries.
      f                 = 0;
      const bool ghosts = u.has_ghost_elements();
      if (!ghosts)
        u.update_ghost_values();
      vectorized->apply(u, f, energy, min_J);
      apply_reference(u, f, vectorized->other_cells());
      f.compress(VectorOperation::add);
      if (!ghosts)
        u.zero_out_ghost_values();
    }
    const MPI_Comm comm = f.get_mpi_communicator();
    Result         result;
    result.energy = Utilities::MPI::sum(energy, comm);
    result.min_J  = Utilities::MPI::min(min_J, comm);
    return result;
  }

  template <int dim>
  void InternalForceOperator<dim>::apply_reference(
      const VectorType                &u,
      VectorType                      &f,
      const std::vector<unsigned int> &cells) const
  {
    // contiguous runs of cell batches in one call each
    for (std::size_t i = 0; i < cells.size();)
    {
      std::size_t end = i + 1;
      while (end < cells.size() && cells[end] == cells[end - 1] + 1)
        ++end;
      const std::pair<unsigned int, unsigned int> range(cells[i],
                                                        cells[end - 1] + 1);
      if (degree == 1)
        local_apply<1>(data, f, u, range);
      else
        local_apply<2>(data, f, u, range);
      i = end;
    }
  }

  template class InternalForceOperator<2>;
  template class InternalForceOperator<3>;
} // namespace softgrasp
