#ifndef softgrasp_mechanics_volumetric_coupling_h
#define softgrasp_mechanics_volumetric_coupling_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <softgrasp/mechanics/linear_solver.h>
#include <softgrasp/mechanics/nodal_conditions.h>
#include <vector>

namespace softgrasp
{
  /**
   * The element-local volumetric coupling of the mixed u-p-J tangent (see
   * VolumetricOperator): per locally owned cell, G_e (pressure modes
   * against displacements, m^2), D_e (ElementDilatation's condensed
   * kernel, Pa/m^3), C_e = D_e^-1 and the approximate Schur complement
   * inverse, applied without global matrices. Displacements pass through
   * the constraints and the row transformation of the nodal conditions
   * exactly as the assembled tangent's rows and columns do.
   */
  template <int dim> class VolumetricCoupling : public VolumetricOperator
  {
  public:
    /// Forget all cells; the next ones are condensed through @p constraints
    /// (homogeneous; not copied, must outlive the use) and the rows
    /// transformed by @p conditions (may be null).
    void reinit(const dealii::IndexSet                  &owned,
                const dealii::IndexSet                  &relevant,
                MPI_Comm                                 communicator,
                const dealii::AffineConstraints<double> &constraints,
                const NodalConditions<dim>              *conditions);

    /// Record one cell: its dof indices, G (n_p x n_u), D and S^-1
    /// (n_p x n_p), and its volume (m^3).
    void add_cell(const std::vector<dealii::types::global_dof_index> &dofs,
                  const dealii::FullMatrix<double>                   &G,
                  const dealii::FullMatrix<double>                   &D,
                  const dealii::FullMatrix<double> &schur_inverse,
                  const double                      volume);

    /// Number the pressure unknowns after the last add_cell(). Collective.
    void finalize();

    const dealii::IndexSet &pressure_dofs() const override;
    void
    divergence(dealii::TrilinosWrappers::MPI::Vector       &p,
               const dealii::TrilinosWrappers::MPI::Vector &u) const override;
    void
         gradient(dealii::TrilinosWrappers::MPI::Vector       &u,
                  const dealii::TrilinosWrappers::MPI::Vector &p) const override;
    void multiply(dealii::TrilinosWrappers::MPI::Vector       &dst,
                  const dealii::TrilinosWrappers::MPI::Vector &src,
                  const PressureBlock block) const override;

  private:
    /// One recorded cell; matrices row-major, n_p x n_u and n_p x n_p.
    struct Cell
    {
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<int> local;  ///< positions in the ghosted vector
      std::vector<int> target; ///< local, or -1 for a constrained dof
      bool direct = true;      ///< no row transformation, no constraint entries
      std::vector<double> G, D, Sigma, P;
      double              h2; ///< volume^(2/3) (m^2)
    };

    std::vector<Cell>                             cells;
    unsigned int                                  n_pressure = 0;
    dealii::IndexSet                              pressure_partitioning;
    MPI_Comm                                      comm        = MPI_COMM_SELF;
    const dealii::AffineConstraints<double>      *constraints = nullptr;
    const NodalConditions<dim>                   *conditions  = nullptr;
    mutable dealii::TrilinosWrappers::MPI::Vector distributed, ghosted,
        accumulated;
    /// position of each ghosted-vector entry among the owned ones, or -1
    std::vector<int> owned_position;
    /// gradient() of the direct cells, per ghosted-vector entry (N)
    mutable std::vector<double> buffer;
  };
} // namespace softgrasp

#endif
