#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <softgrasp/base/plane_strain.h>
#include <softgrasp/base/simd.h>
#include <softgrasp/mechanics/cell_assembler.h>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    const FEValuesExtractors::Vector displacement(0);

    template <int dim>
    SymmetricTensor<2, dim> restrict(const SymmetricTensor<2, 3> &t)
    {
      SymmetricTensor<2, dim> r;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          r[i][j] = t[i][j];
      return r;
    }

    template <int dim>
    SymmetricTensor<4, dim> restrict(const SymmetricTensor<4, 3> &t)
    {
      SymmetricTensor<4, dim> r;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              r[i][j][k][l] = t[i][j][k][l];
      return r;
    }

    template <int dim> Point<3> to_3d(const Point<dim> &p)
    {
      Point<3> r;
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = p[d];
      return r;
    }
  } // namespace

  template <int dim>
  AssemblyScratchData<dim>::AssemblyScratchData(
      const Mapping<dim>        &mapping,
      const FiniteElement<dim>  &fe,
      const Quadrature<dim>     &quadrature,
      const Quadrature<dim - 1> &face_quadrature,
      const unsigned int         dilatation_degree)
      : fe_values(mapping,
                  fe,
                  quadrature,
                  update_values | update_gradients | update_quadrature_points |
                      update_JxW_values)
      , fe_face_values(mapping,
                       fe,
                       face_quadrature,
                       update_values | update_gradients |
                           update_quadrature_points | update_normal_vectors |
                           update_JxW_values)
      , grad_u(quadrature.size())
      , J(quadrature.size())
      , JxW(quadrature.size())
      , grad_x(quadrature.size(),
               std::vector<Tensor<1, dim>>(fe.n_dofs_per_cell() / dim))
      , component(fe.n_dofs_per_cell())
      , node(fe.n_dofs_per_cell())
      , dof(fe.n_dofs_per_cell())
      , dilatation(dilatation_degree)
  {
    const unsigned int n_nodes = fe.n_dofs_per_cell() / dim;
    const unsigned int width   = simd::width;
    stride                     = (n_nodes + width - 1) / width * width;
    grad_j.resize(dim * stride);
    tau_grad.resize(dim * stride);
    c_grad.resize(dim * dim * dim * stride);
    node_tangent.resize(dim * dim * n_nodes * stride);
    AssertThrow(fe.is_primitive() && fe.n_components() == dim &&
                    fe.n_dofs_per_cell() % dim == 0,
                ExcMessage("The solid's element must be a primitive vector "
                           "element with one node per dim DoFs."));
    for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
    {
      component[k] = fe.system_to_component_index(k).first;
      node[k]      = fe.system_to_component_index(k).second;
      dof[node[k] * dim + component[k]] = k;
    }
  }

  template <int dim>
  AssemblyScratchData<dim>::AssemblyScratchData(const AssemblyScratchData &o)
      : fe_values(o.fe_values.get_mapping(),
                  o.fe_values.get_fe(),
                  o.fe_values.get_quadrature(),
                  o.fe_values.get_update_flags())
      , fe_face_values(o.fe_face_values.get_mapping(),
                       o.fe_face_values.get_fe(),
                       o.fe_face_values.get_quadrature(),
                       o.fe_face_values.get_update_flags())
      , grad_u(o.grad_u)
      , J(o.J)
      , JxW(o.JxW)
      , grad_x(o.grad_x)
      , component(o.component)
      , node(o.node)
      , dof(o.dof)
      , stride(o.stride)
      , grad_j(o.grad_j)
      , tau_grad(o.tau_grad)
      , c_grad(o.c_grad)
      , node_tangent(o.node_tangent)
      , dilatation(o.dilatation)
  {
  }

  template <int dim>
  CellAssembler<dim>::CellAssembler(
      const MaterialLibrary         &materials,
      const BoundaryConditions<dim> &boundary_conditions,
      const Formulation              formulation,
      const double                   augmentation)
      : materials(materials)
      , boundary_conditions(boundary_conditions)
      , formulation(formulation)
      , augmentation(augmentation)
  {
  }

  template <int dim>
  void CellAssembler<dim>::assemble(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &u,
      const bool                                            with_matrix,
      const InertiaTerm                                    &inertia,
      const bool                                            split_volumetric,
      const DilatationCoefficients                         *given,
      AssemblyScratchData<dim>                             &scratch,
      AssemblyCopyData                                     &copy) const
  {
    const unsigned int n = cell->get_fe().n_dofs_per_cell();
    copy.dof_indices.resize(n);
    cell->get_dof_indices(copy.dof_indices);
    copy.cell_index     = cell->active_cell_index();
    copy.energy         = 0;
    copy.strain_energy  = 0;
    copy.load_potential = 0;
    copy.internal.reinit(n);
    copy.external.reinit(n);
    if (with_matrix)
      copy.matrix.reinit(n, n);
    copy.failed = false;

    scratch.fe_values.reinit(cell);
    try
    {
      const Material &material = materials.get(cell->material_id());
      assemble_volume(
          u, material, with_matrix, split_volumetric, given, scratch, copy);
      if (inertia.active())
        add_inertia(u, material, with_matrix, inertia, scratch, copy);
      assemble_boundary(cell, u, with_matrix, scratch, copy);
      // minus the work of the external forces at their present values
      // (exact for dead loads)
      for (unsigned int k = 0; k < n; ++k)
        copy.load_potential -= copy.external[k] * u[copy.dof_indices[k]];
      copy.energy += copy.load_potential;
    }
    catch (const InvertedMaterialState &e)
    {
      copy.failed   = true;
      copy.failed_J = e.J;
      std::ostringstream where;
      where << "cell " << cell->id().to_string() << " (material id "
            << static_cast<unsigned>(cell->material_id())
            << ", centre at reference position " << cell->center() << " m)";
      copy.failed_cell = where.str();
      copy.internal    = 0;
      copy.external    = 0;
      if (with_matrix)
        copy.matrix = 0;
    }
  }

  template <int dim>
  void
  CellAssembler<dim>::spatial_gradients(const TrilinosWrappers::MPI::Vector &u,
                                        AssemblyScratchData<dim> &scratch)
  {
    const FEValues<dim> &fe_values = scratch.fe_values;
    const unsigned int   n_nodes   = scratch.grad_x[0].size();
    fe_values[displacement].get_function_gradients(u, scratch.grad_u);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
    {
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + scratch.grad_u[q];
      scratch.J[q]           = determinant(F);
      scratch.JxW[q]         = fe_values.JxW(q);
      if (!(scratch.J[q] > 0) || !std::isfinite(scratch.J[q]))
        throw InvertedMaterialState(scratch.J[q]);
      const Tensor<2, dim> F_inv = invert(F);
      for (unsigned int I = 0; I < n_nodes; ++I)
        scratch.grad_x[q][I] =
            fe_values.shape_grad(scratch.dof[I * dim], q) * F_inv;
    }
  }

  template <int dim>
  void CellAssembler<dim>::add_tangent(const unsigned int             q,
                                       const SymmetricTensor<4, dim> &Jc,
                                       const SymmetricTensor<2, dim> &tau,
                                       const double                   JxW,
                                       AssemblyScratchData<dim>      &scratch)
  {
    // K_(I c)(J d) = g_I . (cc_{c . d .} g_J) + delta_cd g_I . tau g_J with
    // g = grad_x N (cc's minor symmetries make sym() of the gradients void),
    // in SIMD lanes over J.
    using V                    = simd::Double;
    const unsigned int n_nodes = scratch.grad_x[q].size();
    const unsigned int stride  = scratch.stride;
    const unsigned int width   = simd::width;
    const double      *g       = scratch.grad_j.data();
    double             cc[dim][dim][dim][dim];
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            cc[c][d][a][b] = Jc[c][a][d][b] * JxW;
    for (unsigned int J = 0; J < n_nodes; ++J)
      for (unsigned int b = 0; b < dim; ++b)
        scratch.grad_j[b * stride + J] = scratch.grad_x[q][J][b];
    for (unsigned int j = 0; j < stride; j += width)
    {
      V gj[dim];
      for (unsigned int b = 0; b < dim; ++b)
        gj[b] = simd::load(g + b * stride + j);
      for (unsigned int a = 0; a < dim; ++a)
      {
        V t = 0.;
        for (unsigned int b = 0; b < dim; ++b)
          t += (tau[a][b] * JxW) * gj[b];
        simd::store(t, &scratch.tau_grad[a * stride + j]);
      }
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int a = 0; a < dim; ++a)
          {
            V h = 0.;
            for (unsigned int b = 0; b < dim; ++b)
              h += cc[c][d][a][b] * gj[b];
            simd::store(
                h, &scratch.c_grad[((c * dim + d) * dim + a) * stride + j]);
          }
    }
    for (unsigned int cd = 0; cd < dim * dim; ++cd)
    {
      const bool    diagonal = cd % (dim + 1) == 0;
      const double *h        = &scratch.c_grad[cd * dim * stride];
      for (unsigned int I = 0; I < n_nodes; ++I)
      {
        double *row = &scratch.node_tangent[(cd * n_nodes + I) * stride];
        for (unsigned int j = 0; j <= I; j += width)
        {
          V value = simd::load(row + j);
          for (unsigned int a = 0; a < dim; ++a)
          {
            const V h_a = simd::load(h + a * stride + j);
            value += g[a * stride + I] * h_a;
            if (diagonal)
            {
              const V t = simd::load(&scratch.tau_grad[a * stride + j]);
              value += g[a * stride + I] * t;
            }
          }
          simd::store(value, row + j);
        }
      }
    }
  }

  template <int dim>
  void CellAssembler<dim>::scatter_tangent(AssemblyScratchData<dim> &scratch,
                                           FullMatrix<double>       &matrix)
  {
    const unsigned int               n_nodes = scratch.grad_x[0].size();
    const std::vector<unsigned int> &dof     = scratch.dof;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int I = 0; I < n_nodes; ++I)
        {
          const double *row =
              &scratch.node_tangent[((c * dim + d) * n_nodes + I) *
                                    scratch.stride];
          // the node block (I, I) is symmetric: its lower half suffices
          for (unsigned int J = 0; J < (d > c ? I : I + 1); ++J)
          {
            const unsigned int k = dof[I * dim + c], l = dof[J * dim + d];
            matrix(std::max(k, l), std::min(k, l)) += row[J];
          }
        }
  }

  template <int dim>
  void
  CellAssembler<dim>::assemble_volume(const TrilinosWrappers::MPI::Vector &u,
                                      const Material &material,
                                      const bool      with_matrix,
                                      const bool      split_volumetric,
                                      const DilatationCoefficients *given,
                                      AssemblyScratchData<dim>     &scratch,
                                      AssemblyCopyData             &copy) const
  {
    const FEValues<dim> &fe_values = scratch.fe_values;
    const unsigned int   n_q       = fe_values.n_quadrature_points;
    const unsigned int   n         = copy.internal.size();
    const unsigned int   n_nodes   = scratch.grad_x[0].size();
    spatial_gradients(u, scratch);

    const bool mixed = formulation == Formulation::mixed_upJ;
    if (mixed)
      start_dilatation(material, given, scratch, copy);

    const bool         gravity = boundary_conditions.has_gravity();
    Material::Response response;
    // zeroed here, not after the scatter: a cell whose material evaluation
    // threw leaves partial sums behind
    if (with_matrix)
      std::fill(scratch.node_tangent.begin(), scratch.node_tangent.end(), 0.);
    for (unsigned int q = 0; q < n_q; ++q)
    {
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + scratch.grad_u[q];
      const Point<dim>    &X = fe_values.quadrature_point(q);
      const auto directions  = material.structural_directions(to_3d(X));
      if (mixed)
        material.evaluate_spatial_with_pressure(PlaneStrain::to_3d(F),
                                                directions,
                                                scratch.dilatation.pressure(q),
                                                with_matrix,
                                                response);
      else
        material.evaluate_spatial(
            PlaneStrain::to_3d(F), directions, with_matrix, response);
      const SymmetricTensor<2, dim> tau = restrict<dim>(response.stress);
      const double                  JxW = scratch.JxW[q];
      // the condensed u-p-J energy int Psi_iso + U(J~) dV: with J~ the
      // projection of J onto the pressure space, int p~ (J - J~) dV = 0
      const double strain =
          (response.energy + (mixed ? material.volumetric_energy().energy(
                                          scratch.dilatation.dilatation(q))
                                    : 0.)) *
          fe_values.JxW(q);
      copy.energy += strain;
      copy.strain_energy += strain;

      // f_(I c) = int (tau grad_x N_I)_c dV
      for (unsigned int I = 0; I < n_nodes; ++I)
      {
        const Tensor<1, dim> f = tau * scratch.grad_x[q][I];
        for (unsigned int c = 0; c < dim; ++c)
          copy.internal[scratch.dof[I * dim + c]] += f[c] * JxW;
      }
      if (gravity)
      {
        const Tensor<1, dim> body_force =
            material.density() * boundary_conditions.gravity(X);
        for (unsigned int k = 0; k < n; ++k)
          copy.external[k] += fe_values.shape_value(k, q) *
                              body_force[scratch.component[k]] * JxW;
      }
      if (with_matrix)
        add_tangent(q, restrict<dim>(response.tangent), tau, JxW, scratch);
    }
    if (with_matrix)
      scatter_tangent(scratch, copy.matrix);

    if (mixed && (with_matrix || given != nullptr))
      add_dilatation_terms(with_matrix, scratch, copy);
    if (with_matrix && mixed)
      add_volumetric_coupling(material, split_volumetric, scratch, copy);
    if (with_matrix)
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = k + 1; l < n; ++l)
          copy.matrix(k, l) = copy.matrix(l, k);
  }

  template <int dim>
  void
  CellAssembler<dim>::add_volumetric_coupling(const Material &material,
                                              const bool      split,
                                              AssemblyScratchData<dim> &scratch,
                                              AssemblyCopyData &copy) const
  {
    // K_con = G^T D G (G and D G from add_dilatation_terms), D the kernel
    const ElementDilatation<dim> &d  = scratch.dilatation;
    const unsigned int            nb = d.n_basis();
    const unsigned int            n  = copy.matrix.m();
    const FullMatrix<double>     &G  = copy.G;
    if (!split)
    {
      // D G is the rate of p~ (add_dilatation_terms)
      add_lower_product(G, copy.linearization.p_rate, copy.matrix);
      return;
    }
    FullMatrix<double> DG(nb, n);
    // Split for the block preconditioner: the displacement block takes
    // G^T W G (W = w M^-1, the augmented Lagrangian term), the coupling
    // keeps G^T D G with D = A - W; their sum is K_con unchanged.
    copy.volumetric.reinit(n, n);
    copy.volume = 0;
    for (const double w : scratch.JxW)
      copy.volume += w;
    const double mu = material.initial_shear_modulus();
    const double w  = d.augment(augmentation * mu, mu, copy.D, copy.S_inverse);
    copy.D.mmult(DG, G);
    add_lower_product(G, DG, copy.volumetric);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < k; ++l)
        copy.volumetric(l, k) = copy.volumetric(k, l);
    if (w > 0)
    {
      d.mass_inverse().mmult(DG, G);
      DG *= w;
      add_lower_product(G, DG, copy.matrix);
    }
  }

  template <int dim>
  void
  CellAssembler<dim>::add_dilatation_terms(const bool with_matrix,
                                           AssemblyScratchData<dim> &scratch,
                                           AssemblyCopyData         &copy) const
  {
    // G_ak = int N_a J div_x N_k dV
    const ElementDilatation<dim> &d   = scratch.dilatation;
    const unsigned int            nb  = d.n_basis();
    const unsigned int            n   = copy.internal.size();
    const unsigned int            n_q = scratch.J.size();
    FullMatrix<double>           &G   = copy.G;
    G.reinit(nb, n);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int k = 0; k < n; ++k)
      {
        // div_x of DoF k's shape function: component c of grad_x N_I
        const double div =
            scratch.grad_x[q][scratch.node[k]][scratch.component[k]];
        for (unsigned int a = 0; a < nb; ++a)
          G(a, k) += d.basis(a, q) * scratch.J[q] * div * scratch.JxW[q];
      }
    // The condensed element equations: f_int += G^T s (zero where J~ and
    // p~ are the projections); dJ~ = M^-1 (R_p + G du), dp~ = s + A G du.
    G.Tvmult_add(copy.internal, d.pressure_offset());
    if (!with_matrix)
      return;
    DilatationLinearization &l = copy.linearization;
    l.J_offset                 = d.dilatation_offset();
    l.p_offset                 = d.pressure_offset();
    l.J_rate.reinit(nb, n);
    l.p_rate.reinit(nb, n);
    d.mass_inverse().mmult(l.J_rate, G);
    d.condensed_kernel().mmult(l.p_rate, G);
  }

  template <int dim>
  void CellAssembler<dim>::add_lower_product(const FullMatrix<double> &G,
                                             const FullMatrix<double> &DG,
                                             FullMatrix<double>       &target)
  {
    for (unsigned int k = 0; k < G.n(); ++k)
      for (unsigned int l = 0; l <= k; ++l)
      {
        double value = 0;
        for (unsigned int a = 0; a < G.m(); ++a)
          value += G(a, k) * DG(a, l);
        target(k, l) += value;
      }
  }

  template <int dim>
  void CellAssembler<dim>::lumped_mass(const FEValues<dim> &fe_values,
                                       const double         density,
                                       Vector<double>      &mass)
  {
    const unsigned int n = fe_values.get_fe().n_dofs_per_cell();
    mass.reinit(n);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      for (unsigned int k = 0; k < n; ++k)
        mass[k] += density * fe_values.shape_value(k, q) * fe_values.JxW(q);
  }

  template <int dim>
  void CellAssembler<dim>::add_inertia(const TrilinosWrappers::MPI::Vector &u,
                                       const Material           &material,
                                       const bool                with_matrix,
                                       const InertiaTerm        &inertia,
                                       AssemblyScratchData<dim> &scratch,
                                       AssemblyCopyData         &copy) const
  {
    Vector<double> mass;
    lumped_mass(scratch.fe_values, material.density(), mass);
    const double factor = inertia.inverse_dt_squared;
    for (unsigned int k = 0; k < mass.size(); ++k)
    {
      const auto   index = copy.dof_indices[k];
      const double lag   = u[index] - (*inertia.predictor)[index];
      copy.internal[k] += mass[k] * factor * lag;
      copy.energy += 0.5 * mass[k] * factor * lag * lag;
      if (with_matrix)
        copy.matrix(k, k) += mass[k] * factor;
    }
  }

  template <int dim>
  void CellAssembler<dim>::start_dilatation(const Material &material,
                                            const DilatationCoefficients *given,
                                            AssemblyScratchData<dim> &scratch,
                                            AssemblyCopyData &copy) const
  {
    const auto &points = scratch.fe_values.get_quadrature_points();
    if (given != nullptr)
      scratch.dilatation.reinit(
          points, scratch.JxW, scratch.J, material.volumetric_energy(), *given);
    else
      scratch.dilatation.reinit(
          points, scratch.JxW, scratch.J, material.volumetric_energy());
    scratch.dilatation.get_coefficients(copy.coefficients);
  }

  template <int dim>
  void CellAssembler<dim>::add_pressure(const Function<dim> &pressure,
                                        const TrilinosWrappers::MPI::Vector &u,
                                        const bool                with_matrix,
                                        AssemblyScratchData<dim> &scratch,
                                        AssemblyCopyData         &copy) const
  {
    FEFaceValues<dim>          &fe_face = scratch.fe_face_values;
    const FiniteElement<dim>   &fe      = fe_face.get_fe();
    const unsigned int          n       = fe.n_dofs_per_cell();
    std::vector<Tensor<2, dim>> grad_u(fe_face.n_quadrature_points);
    fe_face[displacement].get_function_gradients(u, grad_u);
    for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
    {
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u[q];
      const double         J = determinant(F);
      if (!(J > 0))
        throw InvertedMaterialState(J);
      const Tensor<2, dim> F_inv = invert(F);
      const Tensor<1, dim> FinvT_N =
          transpose(F_inv) * fe_face.normal_vector(q);
      const double p   = pressure.value(fe_face.quadrature_point(q));
      const double JxW = fe_face.JxW(q);
      for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int c = fe.system_to_component_index(k).first;
        copy.external[k] -=
            fe_face.shape_value(k, q) * p * J * FinvT_N[c] * JxW;
      }
      if (!with_matrix)
        continue;
      for (unsigned int l = 0; l < n; ++l)
      {
        const Tensor<2, dim> g = fe_face[displacement].gradient(l, q) * F_inv;
        const Tensor<1, dim> dforce =
            p * J * (trace(g) * FinvT_N - transpose(g) * FinvT_N);
        for (unsigned int k = 0; k < n; ++k)
        {
          const unsigned int c = fe.system_to_component_index(k).first;
          copy.matrix(k, l) += fe_face.shape_value(k, q) * dforce[c] * JxW;
        }
      }
    }
  }

  template <int dim>
  void CellAssembler<dim>::assemble_boundary(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &u,
      const bool                                            with_matrix,
      AssemblyScratchData<dim>                             &scratch,
      AssemblyCopyData                                     &copy) const
  {
    if (!cell->at_boundary())
      return;
    const auto &tractions = boundary_conditions.tractions;
    const auto &pressures = boundary_conditions.pressures;
    if (tractions.empty() && pressures.empty())
      return;
    FEFaceValues<dim>        &fe_face = scratch.fe_face_values;
    const FiniteElement<dim> &fe      = fe_face.get_fe();
    const unsigned int        n       = fe.n_dofs_per_cell();

    for (const auto f : cell->face_indices())
    {
      if (!cell->face(f)->at_boundary())
        continue;
      const types::boundary_id id = cell->face(f)->boundary_id();
      for (const auto &traction : tractions)
      {
        if (traction.boundary_id != id)
          continue;
        fe_face.reinit(cell, f);
        for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
        {
          const Point<dim> &X = fe_face.quadrature_point(q);
          for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int c = fe.system_to_component_index(k).first;
            copy.external[k] += fe_face.shape_value(k, q) *
                                traction.traction->value(X, c) * fe_face.JxW(q);
          }
        }
      }
      for (const auto &pressure : pressures)
      {
        if (pressure.boundary_id != id)
          continue;
        fe_face.reinit(cell, f);
        add_pressure(*pressure.pressure, u, with_matrix, scratch, copy);
      }
    }
  }

  template struct AssemblyScratchData<2>;
  template struct AssemblyScratchData<3>;
  template class CellAssembler<2>;
  template class CellAssembler<3>;
} // namespace softgrasp
