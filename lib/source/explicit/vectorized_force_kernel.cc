#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/fe/fe_values.h>
#include <limits>
#include <map>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/base/simd.h>
#include <softgrasp/explicit/vectorized_force_kernel.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    using V                      = simd::Double;
    constexpr unsigned int lanes = simd::width;

    constexpr unsigned int power(const unsigned int base,
                                 const unsigned int exponent)
    {
      return exponent == 0 ? 1 : base * power(base, exponent - 1);
    }

    /**
     * One direction of a sum factorisation on an n^dim array
     * (lexicographic, x fastest): out[.., r, ..] (+)= sum_s M(r, s) in[..,
     * s, ..] along @p direction, with M(r, s) = matrix[r n + s], or
     * matrix[s n + r] when @p transpose.
     */
    template <int dim, int n, int direction, bool transpose, bool add>
    void contract(const double *matrix, const V *in, V *out)
    {
      constexpr unsigned int stride = power(n, direction);
      constexpr unsigned int outer  = power(n, dim - 1 - direction);
      for (unsigned int o = 0; o < outer; ++o)
        for (unsigned int i = 0; i < stride; ++i)
        {
          const V *x = in + o * stride * n + i;
          V       *y = out + o * stride * n + i;
          for (unsigned int r = 0; r < n; ++r)
          {
            V sum = 0.0;
            for (unsigned int s = 0; s < n; ++s)
              sum += matrix[transpose ? s * n + r : r * n + s] * x[s * stride];
            y[r * stride] = add ? V(y[r * stride] + sum) : sum;
          }
        }
    }

    /// 1D Lagrange basis on the nodes and its derivative at the Gauss
    /// points, [q n + node].
    template <int n> struct Shape1D
    {
      std::array<double, n * n> value, gradient;
    };

    /// Reference gradients g[k][q] = du/dxi_k at the Gauss points of the
    /// nodal values u (one component).
    template <int dim, int n>
    void evaluate_gradients(const Shape1D<n> &shape,
                            const V          *u,
                            V (*g)[power(n, dim)])
    {
      const double *N = shape.value.data(), *D = shape.gradient.data();
      V             t1[power(n, dim)], t2[power(n, dim)];
      if constexpr (dim == 2)
      {
        contract<2, n, 1, false, false>(N, u, t1);
        contract<2, n, 0, false, false>(D, t1, g[0]);
        contract<2, n, 1, false, false>(D, u, t1);
        contract<2, n, 0, false, false>(N, t1, g[1]);
      }
      else
      {
        contract<3, n, 2, false, false>(N, u, t1);
        contract<3, n, 1, false, false>(N, t1, t2);
        contract<3, n, 0, false, false>(D, t2, g[0]);
        contract<3, n, 1, false, false>(D, t1, t2);
        contract<3, n, 0, false, false>(N, t2, g[1]);
        contract<3, n, 2, false, false>(D, u, t1);
        contract<3, n, 1, false, false>(N, t1, t2);
        contract<3, n, 0, false, false>(N, t2, g[2]);
      }
    }

    /// Nodal forces f_node = sum_q sum_k t[k][q] dN_node/dxi_k (the
    /// transpose of evaluate_gradients()).
    template <int dim, int n>
    void
    integrate_gradients(const Shape1D<n> &shape, V (*t)[power(n, dim)], V *f)
    {
      const double *N = shape.value.data(), *D = shape.gradient.data();
      V             a[power(n, dim)], b[power(n, dim)];
      if constexpr (dim == 2)
      {
        contract<2, n, 0, true, false>(D, t[0], a);
        contract<2, n, 1, true, false>(N, a, f);
        contract<2, n, 0, true, false>(N, t[1], a);
        contract<2, n, 1, true, true>(D, a, f);
      }
      else
      {
        contract<3, n, 0, true, false>(D, t[0], a);
        contract<3, n, 1, true, false>(N, a, b);
        contract<3, n, 0, true, false>(N, t[1], a);
        contract<3, n, 1, true, true>(D, a, b);
        contract<3, n, 2, true, false>(N, b, f);
        contract<3, n, 0, true, false>(N, t[2], a);
        contract<3, n, 1, true, false>(N, a, b);
        contract<3, n, 2, true, true>(D, b, f);
      }
    }

    /// A batch of cells of one material.
    struct Batch
    {
      const Material *material;
      unsigned int    n_cells; ///< active lanes
    };
  } // namespace

  template <int dim> struct VectorizedForceKernel<dim>::Data
  {
    unsigned int              degree = 1, n_q = 0, n_directions_max = 0;
    bool                      mean_dilatation = false;
    std::vector<unsigned int> other_cells;
    std::vector<Batch>        batches;
    /// [batch][component * n_nodes + lexicographic node][lane]
    std::vector<unsigned int> dof_indices;
    /// [batch][q][dim * dim inverse Jacobian (row-major), JxW][lane]
    std::vector<double> mapping;
    /// [batch][q][3 * max directions][lane] (anisotropic materials only)
    std::vector<double> directions;
    Shape1D<2>          shape1;
    Shape1D<3>          shape2;

    static constexpr unsigned int mapping_entries = dim * dim + 1;

    /// Values at the n^dim nodes or Gauss points of a batch's cells.
    template <int n> using Values = V[power(n, dim)];
    /// Per component c and reference direction k: [c][k][point].
    template <int n> using Gradients = V[dim][dim][power(n, dim)];
    /// Row-major 3x3 F per point.
    template <int n> using Deformations = V[power(n, dim)][9];

    /// What set-up needs for every batch.
    struct SetUp
    {
      const MatrixFree<dim, double>     &mf;
      FEValues<dim>                     &fe_values;
      const std::vector<unsigned int>   &lexicographic;
      const Utilities::MPI::Partitioner &partitioner;
    };

    void set_up_shapes();
    /// Cells by material id; cells with constrained DoFs to other_cells.
    std::map<types::material_id, std::vector<unsigned int>>
    classify_cells(const MatrixFree<dim, double>   &mf,
                   const AffineConstraints<double> &constraints);
    /// The batch of cells[first, first + lanes) (padded) of @p material.
    void add_batch(const SetUp                     &setup,
                   const Material                  &material,
                   const std::vector<unsigned int> &cells,
                   const unsigned int               first);
    /// DoF indices, mapping data and directions of one lane of batch @p b.
    void set_lane(const SetUp       &setup,
                  const Material    &material,
                  const unsigned int b,
                  const unsigned int lane,
                  const unsigned int cell,
                  const bool         padding);

    template <int n>
    void apply_batch(const unsigned int b,
                     const double      *src,
                     double            *dst,
                     V                 &energy,
                     V                 &min_J) const;
    template <int n>
    void gradients(const unsigned int b,
                   const double      *src,
                   Gradients<n>      &grad) const;
    /// F per point; inverted points (and padding) get F = I. Accumulates
    /// the cells' reference and deformed volumes.
    template <int n>
    void deformation(const unsigned int  b,
                     const Gradients<n> &grad,
                     Deformations<n>    &F,
                     V                  &volume,
                     V                  &dilated,
                     V                  &min_J) const;
    /// Mean dilatation: p = U'(v_e / V_e) per cell; adds V_e U to energy.
    V cell_pressure(const Batch &batch,
                    const V     &volume,
                    const V     &dilated,
                    V           &energy) const;
    /// t[c][k][q] = JxW sum_j P_cj dxi_k/dx_j; adds Psi JxW to energy.
    template <int n>
    void stresses(const unsigned int     b,
                  const Deformations<n> &F,
                  const V               &pressure,
                  Gradients<n>          &t,
                  V                     &energy) const;
    /// Forces at the nodes, added into dst lane by lane.
    template <int n>
    void
    scatter_forces(const unsigned int b, Gradients<n> &t, double *dst) const;

    /// The DoF indices and the mapping data of batch @p b.
    const unsigned int *dofs_of(const unsigned int b) const
    {
      return &dof_indices[std::size_t(b) * dim * n_q * lanes];
    }
    const double *mapping_of(const unsigned int b) const
    {
      return &mapping[std::size_t(b) * n_q * mapping_entries * lanes];
    }
    /// The structural directions of batch @p b (anisotropic materials).
    const double *directions_of(const unsigned int b) const
    {
      return &directions[std::size_t(b) * n_q * 3 * n_directions_max * lanes];
    }

    /// The 1D shape data of degree n - 1.
    template <int n> const Shape1D<n> &shape() const
    {
      if constexpr (n == 2)
        return shape1;
      else
        return shape2;
    }
  };

  namespace
  {
    template <int n> void fill_shape(Shape1D<n> &shape)
    {
      const auto nodes  = QGaussLobatto<1>(n).get_points();
      const auto points = QGauss<1>(n).get_points();
      for (unsigned int q = 0; q < n; ++q)
        for (unsigned int i = 0; i < n; ++i)
        {
          const double x     = points[q][0];
          double       value = 1, gradient = 0;
          for (unsigned int j = 0; j < n; ++j)
          {
            if (j == i)
              continue;
            const double scale = 1.0 / (nodes[i][0] - nodes[j][0]);
            // product rule: (value * (x - x_j) scale)'
            gradient = gradient * (x - nodes[j][0]) * scale + value * scale;
            value *= (x - nodes[j][0]) * scale;
          }
          shape.value[q * n + i]    = value;
          shape.gradient[q * n + i] = gradient;
        }
    }
  } // namespace

  template <int dim> void VectorizedForceKernel<dim>::Data::set_up_shapes()
  {
    fill_shape(shape1);
    fill_shape(shape2);
  }

  template <int dim>
  std::map<types::material_id, std::vector<unsigned int>>
  VectorizedForceKernel<dim>::Data::classify_cells(
      const MatrixFree<dim, double>   &mf,
      const AffineConstraints<double> &constraints)
  {
    std::map<types::material_id, std::vector<unsigned int>> cells_of;
    std::vector<types::global_dof_index>                    indices(
        mf.get_dof_handler().get_fe().dofs_per_cell);
    for (unsigned int c = 0; c < mf.n_cell_batches(); ++c)
      for (unsigned int l = 0; l < mf.n_active_entries_per_cell_batch(c); ++l)
      {
        const auto cell = mf.get_cell_iterator(c, l);
        cell->get_dof_indices(indices);
        const bool constrained = std::any_of(
            indices.begin(),
            indices.end(),
            [&](const auto i) { return constraints.is_constrained(i); });
        if (constrained || mf.n_active_entries_per_cell_batch(c) > 1)
        {
          if (l == 0)
            other_cells.push_back(c);
          continue;
        }
        cells_of[cell->material_id()].push_back(c);
      }
    return cells_of;
  }

  template <int dim>
  void VectorizedForceKernel<dim>::Data::add_batch(
      const SetUp                     &setup,
      const Material                  &material,
      const std::vector<unsigned int> &cells,
      const unsigned int               first)
  {
    const unsigned int n_cells =
        std::min<unsigned int>(lanes, cells.size() - first);
    batches.push_back({&material, n_cells});
    dof_indices.resize(dof_indices.size() + dim * n_q * lanes);
    mapping.resize(mapping.size() + n_q * mapping_entries * lanes);
    directions.resize(directions.size() + n_q * 3 * n_directions_max * lanes);
    // padding lanes repeat the first cell with JxW = 0
    for (unsigned int lane = 0; lane < lanes; ++lane)
      set_lane(setup,
               material,
               batches.size() - 1,
               lane,
               cells[first + (lane < n_cells ? lane : 0)],
               lane >= n_cells);
  }

  template <int dim>
  void VectorizedForceKernel<dim>::Data::set_lane(const SetUp       &setup,
                                                  const Material    &material,
                                                  const unsigned int b,
                                                  const unsigned int lane,
                                                  const unsigned int cell_index,
                                                  const bool         padding)
  {
    const auto &fe   = setup.mf.get_dof_handler().get_fe();
    const auto  cell = setup.mf.get_cell_iterator(cell_index, 0);
    std::vector<types::global_dof_index> indices(fe.dofs_per_cell);
    cell->get_dof_indices(indices);
    unsigned int *index = &dof_indices[std::size_t(b) * dim * n_q * lanes];
    for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
    {
      const auto [component, base] = fe.system_to_component_index(i);
      index[(component * n_q + setup.lexicographic[base]) * lanes + lane] =
          setup.partitioner.global_to_local(indices[i]);
    }
    setup.fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
    const unsigned int n_dir = 3 * n_directions_max;
    for (unsigned int q = 0; q < n_q; ++q)
    {
      double *m =
          &mapping[(std::size_t(b) * n_q + q) * mapping_entries * lanes];
      const auto &inverse = setup.fe_values.inverse_jacobian(q);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          m[(i * dim + j) * lanes + lane] =
              padding ? double(i == j) : inverse[i][j];
      m[dim * dim * lanes + lane] = padding ? 0.0 : setup.fe_values.JxW(q);
      if (n_dir == 0)
        continue;
      const StructuralDirections s = material.structural_directions(
          PlaneStrain::to_3d(setup.fe_values.quadrature_point(q)));
      double *dir = &directions[(std::size_t(b) * n_q + q) * n_dir * lanes];
      for (unsigned int a = 0; a < s.n_directions; ++a)
        for (unsigned int k = 0; k < 3; ++k)
          dir[(3 * a + k) * lanes + lane] = s.direction[a][k];
    }
  }

  template <int dim>
  VectorizedForceKernel<dim>::VectorizedForceKernel(
      const MatrixFree<dim, double>   &mf,
      const Mapping<dim>              &mapping,
      const AffineConstraints<double> &constraints,
      const MaterialLibrary           &materials,
      const bool                       mean_dilatation)
      : d(std::make_unique<Data>())
  {
    const auto &fe     = mf.get_dof_handler().get_fe();
    d->degree          = fe.degree;
    d->mean_dilatation = mean_dilatation;
    d->n_q             = power(d->degree + 1, dim); // nodes = Gauss points
    d->set_up_shapes();
    for (const auto id : materials.material_ids())
      d->n_directions_max = std::max(
          d->n_directions_max,
          materials.get(id).isochoric_model().n_structural_directions());

    const auto lexicographic =
        FETools::hierarchic_to_lexicographic_numbering<dim>(d->degree);
    FEValues<dim>              fe_values(mapping,
                            fe,
                            QGauss<dim>(d->degree + 1),
                            update_inverse_jacobians | update_JxW_values |
                                update_quadrature_points);
    const typename Data::SetUp setup{
        mf, fe_values, lexicographic, *mf.get_vector_partitioner()};
    for (const auto &[id, cells] : d->classify_cells(mf, constraints))
      for (unsigned int first = 0; first < cells.size(); first += lanes)
        d->add_batch(setup, materials.get(id), cells, first);
  }

  template <int dim>
  VectorizedForceKernel<dim>::~VectorizedForceKernel() = default;

  template <int dim>
  const std::vector<unsigned int> &
  VectorizedForceKernel<dim>::other_cells() const
  {
    return d->other_cells;
  }

  template <int dim> unsigned int VectorizedForceKernel<dim>::n_lanes()
  {
    return lanes;
  }

  template <int dim>
  template <int n>
  void VectorizedForceKernel<dim>::Data::apply_batch(const unsigned int b,
                                                     const double      *src,
                                                     double            *dst,
                                                     V                 &energy,
                                                     V &min_J) const
  {
    Gradients<n>    grad;
    Deformations<n> F;
    V               volume = 0.0, dilated = 0.0;
    gradients<n>(b, src, grad);
    deformation<n>(b, grad, F, volume, dilated, min_J);
    const V pressure = mean_dilatation
                           ? cell_pressure(batches[b], volume, dilated, energy)
                           : V(0.0);
    stresses<n>(b, F, pressure, grad, energy); // grad now holds t
    scatter_forces<n>(b, grad, dst);
  }

  template <int dim>
  template <int n>
  void VectorizedForceKernel<dim>::Data::gradients(const unsigned int b,
                                                   const double      *src,
                                                   Gradients<n> &grad) const
  {
    constexpr unsigned int nn    = power(n, dim);
    const unsigned int    *index = dofs_of(b);
    for (unsigned int c = 0; c < dim; ++c)
    {
      Values<n> u;
      for (unsigned int i = 0; i < nn; ++i)
      {
        const unsigned int *idx = index + (c * nn + i) * lanes;
        u[i] = V([&](const auto lane) { return src[idx[lane]]; });
      }
      evaluate_gradients<dim, n>(shape<n>(), u, grad[c]);
    }
  }

  template <int dim>
  template <int n>
  void VectorizedForceKernel<dim>::Data::deformation(const unsigned int  b,
                                                     const Gradients<n> &grad,
                                                     Deformations<n>    &F,
                                                     V                  &volume,
                                                     V &dilated,
                                                     V &min_J) const
  {
    constexpr unsigned int nn  = power(n, dim);
    const double          *map = mapping_of(b);
    const auto             active =
        V([](const auto i) { return double(i); }) < double(batches[b].n_cells);
    for (unsigned int q = 0; q < nn; ++q)
    {
      const double *m = map + q * mapping_entries * lanes;
      // F = I + grad u (plane strain: F_33 = 1)
      for (unsigned int i = 0; i < 9; ++i)
        F[q][i] = (i % 4 == 0) ? 1.0 : 0.0;
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int j = 0; j < dim; ++j)
        {
          V H = 0.0;
          for (unsigned int k = 0; k < dim; ++k)
            H += grad[c][k][q] * simd::load(m + (k * dim + j) * lanes);
          F[q][3 * c + j] += H;
        }
      const V *f = F[q];
      V        J = f[0] * (f[4] * f[8] - f[5] * f[7]) -
            f[1] * (f[3] * f[8] - f[5] * f[6]) +
            f[2] * (f[3] * f[7] - f[4] * f[6]);
      V J_active                           = J;
      simd::stdx::where(!active, J_active) = std::numeric_limits<double>::max();
      min_J                                = simd::stdx::min(min_J, J_active);
      const auto bad                       = !(J > 0.0) || !active;
      if (simd::stdx::any_of(bad))
      {
        for (unsigned int i = 0; i < 9; ++i)
          simd::stdx::where(bad, F[q][i]) = (i % 4 == 0) ? 1.0 : 0.0;
        simd::stdx::where(bad, J) = 1.0;
      }
      const V JxW = simd::load(m + dim * dim * lanes);
      volume += JxW;
      dilated += J * JxW;
    }
  }

  template <int dim>
  V VectorizedForceKernel<dim>::Data::cell_pressure(const Batch &batch,
                                                    const V     &volume,
                                                    const V     &dilated,
                                                    V           &energy) const
  {
    V                       pressure = 0.0;
    const VolumetricEnergy &U        = batch.material->volumetric_energy();
    for (unsigned int lane = 0; lane < batch.n_cells; ++lane)
    {
      const double J_e = volume[lane] > 0 ? dilated[lane] / volume[lane] : 1;
      pressure[lane]   = U.first_derivative(J_e);
      energy[lane] += volume[lane] * U.energy(J_e);
    }
    return pressure;
  }

  template <int dim>
  template <int n>
  void VectorizedForceKernel<dim>::Data::stresses(const unsigned int     b,
                                                  const Deformations<n> &F,
                                                  const V      &pressure,
                                                  Gradients<n> &t,
                                                  V            &energy) const
  {
    constexpr unsigned int nn          = power(n, dim);
    constexpr unsigned int q_per_block = point_block_size / lanes;
    const Batch           &batch       = batches[b];
    const double          *map         = mapping_of(b);
    const unsigned int     n_dir       = 3 * n_directions_max;
    MaterialPointBlock     block;
    block.given_pressure = mean_dilatation;
    block.isochoric.n_directions =
        batch.material->isochoric_model().n_structural_directions();
    for (unsigned int q0 = 0; q0 < nn; q0 += q_per_block)
    {
      const unsigned int n_block = std::min(q_per_block, nn - q0);
      block.n_points             = n_block * lanes;
      for (unsigned int qq = 0; qq < n_block; ++qq)
      {
        for (unsigned int i = 0; i < 9; ++i)
          simd::store(F[q0 + qq][i], &block.F[i][qq * lanes]);
        simd::store(pressure, &block.pressure[qq * lanes]);
        for (unsigned int e = 0; e < 3 * block.isochoric.n_directions; ++e)
          std::copy_n(directions_of(b) + ((q0 + qq) * n_dir + e) * lanes,
                      lanes,
                      &block.isochoric.directions[e][qq * lanes]);
      }
      batch.material->first_piola_block(block);
      for (unsigned int qq = 0; qq < n_block; ++qq)
      {
        const unsigned int q   = q0 + qq;
        const double      *m   = map + q * mapping_entries * lanes;
        const V            JxW = simd::load(m + dim * dim * lanes);
        energy += simd::load(&block.energy[qq * lanes]) * JxW;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int k = 0; k < dim; ++k)
          {
            V T = 0.0;
            for (unsigned int j = 0; j < dim; ++j)
              T += simd::load(&block.P[3 * c + j][qq * lanes]) *
                   simd::load(m + (k * dim + j) * lanes);
            t[c][k][q] = T * JxW;
          }
      }
    }
  }

  template <int dim>
  template <int n>
  void VectorizedForceKernel<dim>::Data::scatter_forces(const unsigned int b,
                                                        Gradients<n>      &t,
                                                        double *dst) const
  {
    constexpr unsigned int nn    = power(n, dim);
    const unsigned int    *index = dofs_of(b);
    for (unsigned int c = 0; c < dim; ++c)
    {
      Values<n> f;
      integrate_gradients<dim, n>(shape<n>(), t[c], f);
      for (unsigned int i = 0; i < nn; ++i)
      {
        const unsigned int *idx = index + (c * nn + i) * lanes;
        for (unsigned int lane = 0; lane < batches[b].n_cells; ++lane)
          dst[idx[lane]] += f[i][lane];
      }
    }
  }

  template <int dim>
  void VectorizedForceKernel<dim>::apply(const VectorType &src,
                                         VectorType       &dst,
                                         double           &energy,
                                         double           &min_J) const
  {
    V energy_sum = 0.0, smallest_J = std::numeric_limits<double>::max();
    for (unsigned int b = 0; b < d->batches.size(); ++b)
      if (d->degree == 1)
        d->template apply_batch<2>(
            b, src.begin(), dst.begin(), energy_sum, smallest_J);
      else
        d->template apply_batch<3>(
            b, src.begin(), dst.begin(), energy_sum, smallest_J);
    energy += simd::stdx::reduce(energy_sum);
    min_J = std::min(min_J, simd::stdx::hmin(smallest_J));
  }

  template class VectorizedForceKernel<2>;
  template class VectorizedForceKernel<3>;
} // namespace softgrasp
