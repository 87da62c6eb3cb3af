#include <Epetra_FEVector.h>
#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <softgrasp/mechanics/volumetric_coupling.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  void VolumetricCoupling<dim>::reinit(const IndexSet &owned,
                                       const IndexSet &relevant,
                                       MPI_Comm        communicator,
                                       const AffineConstraints<double> &c,
                                       const NodalConditions<dim>      *nodal)
  {
    cells.clear();
    comm        = communicator;
    constraints = &c;
    conditions  = nodal;
    if (distributed.size() == 0 ||
        distributed.locally_owned_elements() != owned)
    {
      distributed.reinit(owned, communicator);
      ghosted.reinit(owned, relevant, communicator);
      accumulated.reinit(owned, relevant, communicator, true);
      // where each entry of the ghosted vector sits among the owned ones
      const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
      owned_position.assign(map.NumMyElements(), -1);
      for (int i = 0; i < map.NumMyElements(); ++i)
        if (owned.is_element(map.GID(i)))
          owned_position[i] =
              static_cast<int>(owned.index_within_set(map.GID(i)));
      buffer.assign(map.NumMyElements(), 0.);
    }
  }

  template <int dim>
  void VolumetricCoupling<dim>::add_cell(
      const std::vector<types::global_dof_index> &dofs,
      const FullMatrix<double>                   &G,
      const FullMatrix<double>                   &D,
      const FullMatrix<double>                   &schur_inverse,
      const double                                volume)
  {
    n_pressure = G.m();
    Cell cell;
    cell.dofs                  = dofs;
    const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
    // Cells without row transformations or constraints with entries add
    // their gradient straight into the local entries (gradient()); a
    // constrained dof without entries (Dirichlet) receives nothing.
    cell.direct = conditions == nullptr;
    for (const auto index : dofs)
    {
      cell.local.push_back(map.LID(static_cast<int>(index)));
      if (constraints->is_constrained(index))
      {
        const auto *entries = constraints->get_constraint_entries(index);
        cell.direct         = cell.direct && entries->empty();
        cell.target.push_back(-1);
      }
      else
        cell.target.push_back(cell.local.back());
    }
    cell.h2 = std::pow(volume, 2.0 / dim);
    // P = (Sigma S)^-1 = S^-1 C / h^2
    FullMatrix<double> C(D.m(), D.n()), P(D.m(), D.n());
    C.invert(D);
    schur_inverse.mmult(P, C);
    P /= cell.h2;
    cell.G.assign(G.begin(), G.end());
    cell.D.assign(D.begin(), D.end());
    cell.Sigma.assign(D.begin(), D.end());
    for (double &x : cell.Sigma)
      x *= cell.h2;
    cell.P.assign(P.begin(), P.end());
    cells.push_back(std::move(cell));
  }

  template <int dim> void VolumetricCoupling<dim>::finalize()
  {
    const unsigned int np =
        Utilities::MPI::max(cells.empty() ? 0u : n_pressure, comm);
    n_pressure = np;
    const auto partitions =
        Utilities::MPI::create_ascending_partitioning(comm, cells.size() * np);
    pressure_partitioning = partitions[Utilities::MPI::this_mpi_process(comm)];
  }

  template <int dim>
  const IndexSet &VolumetricCoupling<dim>::pressure_dofs() const
  {
    return pressure_partitioning;
  }

  template <int dim>
  void VolumetricCoupling<dim>::divergence(
      TrilinosWrappers::MPI::Vector       &p,
      const TrilinosWrappers::MPI::Vector &u) const
  {
    // C u: constrained entries from the free ones (homogeneous).
    distributed = u;
    constraints->distribute(distributed);
    ghosted                 = distributed;
    const double *const x   = ghosted.trilinos_vector()[0];
    double *const       out = p.begin();
    const unsigned int  np  = n_pressure;
    for (std::size_t c = 0; c < cells.size(); ++c)
    {
      const Cell        &cell = cells[c];
      const unsigned int n    = cell.local.size();
      for (unsigned int a = 0; a < np; ++a)
      {
        double sum = 0;
        for (unsigned int k = 0; k < n; ++k)
          sum += cell.G[a * n + k] * x[cell.local[k]];
        out[c * np + a] = sum;
      }
    }
  }

  template <int dim>
  void VolumetricCoupling<dim>::gradient(
      TrilinosWrappers::MPI::Vector       &u,
      const TrilinosWrappers::MPI::Vector &p) const
  {
    accumulated            = 0;
    const double *const in = p.begin();
    const unsigned int  np = n_pressure;
    std::fill(buffer.begin(), buffer.end(), 0.);
    Vector<double>     local;
    FullMatrix<double> column;
    Vector<double>     unused;
    for (std::size_t c = 0; c < cells.size(); ++c)
    {
      const Cell        &cell = cells[c];
      const unsigned int n    = cell.dofs.size();
      local.reinit(n);
      for (unsigned int a = 0; a < np; ++a)
        for (unsigned int k = 0; k < n; ++k)
          local[k] += cell.G[a * n + k] * in[c * np + a];
      if (cell.direct)
      {
        for (unsigned int k = 0; k < n; ++k)
          if (cell.target[k] >= 0)
            buffer[cell.target[k]] += local[k];
        continue;
      }
      if (conditions != nullptr)
      {
        // the rows of governed nodes as the tangent's (linear in the rows)
        column.reinit(n, 1);
        unused.reinit(n);
        for (unsigned int k = 0; k < n; ++k)
          column(k, 0) = local[k];
        conditions->transform_cell_rows(cell.dofs, column, unused);
        for (unsigned int k = 0; k < n; ++k)
          local[k] = column(k, 0);
      }
      constraints->distribute_local_to_global(local, cell.dofs, accumulated);
    }
    // ghost entries of the direct cells go to their owners with the rest
    const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
    for (std::size_t i = 0; i < buffer.size(); ++i)
      if (owned_position[i] < 0 && buffer[i] != 0.)
        accumulated(static_cast<types::global_dof_index>(map.GID(i))) +=
            buffer[i];
    accumulated.compress(VectorOperation::add);
    u                  = accumulated;
    double *const dest = u.begin();
    for (std::size_t i = 0; i < buffer.size(); ++i)
      if (owned_position[i] >= 0)
        dest[owned_position[i]] += buffer[i];
  }

  template <int dim>
  void
  VolumetricCoupling<dim>::multiply(TrilinosWrappers::MPI::Vector       &dst,
                                    const TrilinosWrappers::MPI::Vector &src,
                                    const PressureBlock block) const
  {
    const double *const in  = src.begin();
    double *const       out = dst.begin();
    const unsigned int  np  = n_pressure;
    for (std::size_t c = 0; c < cells.size(); ++c)
    {
      const Cell &cell = cells[c];
      if (block == PressureBlock::scaled_compliance)
      {
        for (unsigned int a = 0; a < np; ++a)
          out[c * np + a] = cell.h2 * in[c * np + a];
        continue;
      }
      const std::vector<double> &X =
          block == PressureBlock::stiffness
              ? cell.D
              : (block == PressureBlock::scaled_stiffness ? cell.Sigma
                                                          : cell.P);
      for (unsigned int a = 0; a < np; ++a)
      {
        double sum = 0;
        for (unsigned int b = 0; b < np; ++b)
          sum += X[a * np + b] * in[c * np + b];
        out[c * np + a] = sum;
      }
    }
  }

  template class VolumetricCoupling<2>;
  template class VolumetricCoupling<3>;
} // namespace softgrasp
