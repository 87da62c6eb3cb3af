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

    void set_up_shapes();
    template <int n>
    void apply_batch(const unsigned int b,
                     const double      *src,
                     double            *dst,
                     V                 &energy,
                     V                 &min_J) const;
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
  VectorizedForceKernel<dim>::VectorizedForceKernel(
      const MatrixFree<dim, double>   &mf,
      const Mapping<dim>              &mapping,
      const AffineConstraints<double> &constraints,
      const MaterialLibrary           &materials,
      const bool                       mean_dilatation)
      : d(std::make_unique<Data>())
  {
    const DoFHandler<dim> &dofs = mf.get_dof_handler();
    const auto            &fe   = dofs.get_fe();
    d->degree                   = fe.degree;
    d->mean_dilatation          = mean_dilatation;
    d->set_up_shapes();
    const unsigned int n_nodes = power(d->degree + 1, dim);
    d->n_q                     = n_nodes;
    for (const auto id : materials.material_ids())
      d->n_directions_max = std::max(
          d->n_directions_max,
          materials.get(id).isochoric_model().n_structural_directions());

    // Cells by material id; cells with constrained DoFs go to the caller.
    std::map<types::material_id, std::vector<unsigned int>> cells_of;
    std::vector<types::global_dof_index> indices(fe.dofs_per_cell);
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
            d->other_cells.push_back(c);
          continue;
        }
        cells_of[cell->material_id()].push_back(c);
      }

    // Per batch: DoF indices, inverse Jacobians and JxW, directions.
    const auto lexicographic =
        FETools::hierarchic_to_lexicographic_numbering<dim>(d->degree);
    const auto        &partitioner = *mf.get_vector_partitioner();
    const QGauss<dim>  quadrature(d->degree + 1);
    FEValues<dim>      fe_values(mapping,
                            fe,
                            quadrature,
                            update_inverse_jacobians | update_JxW_values |
                                update_quadrature_points);
    const unsigned int n_dir_entries = 3 * d->n_directions_max;
    for (const auto &[id, cells] : cells_of)
    {
      const Material &material = materials.get(id);
      for (unsigned int first = 0; first < cells.size(); first += lanes)
      {
        const unsigned int n_cells =
            std::min<unsigned int>(lanes, cells.size() - first);
        d->batches.push_back({&material, n_cells});
        const std::size_t dof_offset = d->dof_indices.size();
        const std::size_t map_offset = d->mapping.size();
        const std::size_t dir_offset = d->directions.size();
        d->dof_indices.resize(dof_offset + dim * n_nodes * lanes);
        d->mapping.resize(map_offset + d->n_q * Data::mapping_entries * lanes);
        d->directions.resize(dir_offset + d->n_q * n_dir_entries * lanes);
        for (unsigned int lane = 0; lane < lanes; ++lane)
        {
          // padding lanes repeat the first cell with JxW = 0
          const bool padding = lane >= n_cells;
          const auto cell =
              mf.get_cell_iterator(cells[first + (padding ? 0 : lane)], 0);
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
          {
            const auto [component, base] = fe.system_to_component_index(i);
            d->dof_indices[dof_offset +
                           (component * n_nodes + lexicographic[base]) * lanes +
                           lane] = partitioner.global_to_local(indices[i]);
          }
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
          for (unsigned int q = 0; q < d->n_q; ++q)
          {
            double *m =
                &d->mapping[map_offset + q * Data::mapping_entries * lanes];
            const auto &inverse = fe_values.inverse_jacobian(q);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                m[(i * dim + j) * lanes + lane] =
                    padding ? double(i == j) : inverse[i][j];
            m[dim * dim * lanes + lane] = padding ? 0.0 : fe_values.JxW(q);
            if (n_dir_entries == 0)
              continue;
            const StructuralDirections s = material.structural_directions(
                PlaneStrain::to_3d(fe_values.quadrature_point(q)));
            for (unsigned int a = 0; a < s.n_directions; ++a)
              for (unsigned int k = 0; k < 3; ++k)
                d->directions[dir_offset +
                              (q * n_dir_entries + 3 * a + k) * lanes + lane] =
                    s.direction[a][k];
          }
        }
      }
    }
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
    constexpr unsigned int nn    = power(n, dim); // nodes = Gauss points
    const Shape1D<n>      &shape = [this]() -> const Shape1D<n> &
    {
      if constexpr (n == 2)
        return shape1;
      else
        return shape2;
    }();
    const Batch        &batch = batches[b];
    const unsigned int *index = &dof_indices[std::size_t(b) * dim * nn * lanes];
    const double *map = &mapping[std::size_t(b) * nn * mapping_entries * lanes];
    const unsigned int n_dir = 3 * n_directions_max;
    const auto         active =
        V([](const auto i) { return double(i); }) < double(batch.n_cells);

    // Gradients at the Gauss points, reference coordinates: grad[c][k][q].
    V grad[dim][dim][nn];
    for (unsigned int c = 0; c < dim; ++c)
    {
      V u[nn];
      for (unsigned int i = 0; i < nn; ++i)
      {
        const unsigned int *idx = index + (c * nn + i) * lanes;
        u[i] = V([&](const auto lane) { return src[idx[lane]]; });
      }
      evaluate_gradients<dim, n>(shape, u, grad[c]);
    }

    // F = I + grad u (plane strain: F_33 = 1); inverted points get F = I.
    V F[nn][9];
    V volume = 0.0, dilated = 0.0;
    for (unsigned int q = 0; q < nn; ++q)
    {
      const double *m = map + q * mapping_entries * lanes;
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

    // Mean dilatation: J_e = v_e / V_e and p = U'(J_e) per cell.
    V pressure = 0.0;
    if (mean_dilatation)
    {
      const VolumetricEnergy &U = batch.material->volumetric_energy();
      for (unsigned int lane = 0; lane < batch.n_cells; ++lane)
      {
        const double J_e = volume[lane] > 0 ? dilated[lane] / volume[lane] : 1;
        pressure[lane]   = U.first_derivative(J_e);
        energy[lane] += volume[lane] * U.energy(J_e);
      }
    }

    // Stress in blocks of points; t[c][k][q] = JxW sum_j P_cj dxi_k/dx_j.
    constexpr unsigned int q_per_block = point_block_size / lanes;
    MaterialPointBlock     block;
    block.given_pressure = mean_dilatation;
    block.isochoric.n_directions =
        batch.material->isochoric_model().n_structural_directions();
    V t[dim][dim][nn];
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
          std::copy_n(
              &directions[((std::size_t(b) * nn + q0 + qq) * n_dir + e) *
                          lanes],
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
        {
          V P[dim];
          for (unsigned int j = 0; j < dim; ++j)
            P[j] = simd::load(&block.P[3 * c + j][qq * lanes]);
          for (unsigned int k = 0; k < dim; ++k)
          {
            V T = 0.0;
            for (unsigned int j = 0; j < dim; ++j)
              T += P[j] * simd::load(m + (k * dim + j) * lanes);
            t[c][k][q] = T * JxW;
          }
        }
      }
    }

    // Forces at the nodes, added into dst lane by lane.
    for (unsigned int c = 0; c < dim; ++c)
    {
      V f[nn];
      integrate_gradients<dim, n>(shape, t[c], f);
      for (unsigned int i = 0; i < nn; ++i)
      {
        const unsigned int *idx = index + (c * nn + i) * lanes;
        for (unsigned int lane = 0; lane < batch.n_cells; ++lane)
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
