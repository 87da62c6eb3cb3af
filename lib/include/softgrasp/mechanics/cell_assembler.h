#ifndef softgrasp_mechanics_cell_assembler_h
#define softgrasp_mechanics_cell_assembler_h

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/dilatation_state.h>
#include <softgrasp/mechanics/element_dilatation.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /// Per-thread scratch space of the WorkStream assembly.
  template <int dim> struct AssemblyScratchData
  {
    AssemblyScratchData(const dealii::Mapping<dim>        &mapping,
                        const dealii::FiniteElement<dim>  &fe,
                        const dealii::Quadrature<dim>     &quadrature,
                        const dealii::Quadrature<dim - 1> &face_quadrature,
                        const unsigned int                 dilatation_degree);
    AssemblyScratchData(const AssemblyScratchData &other);

    dealii::FEValues<dim>               fe_values;
    dealii::FEFaceValues<dim>           fe_face_values;
    std::vector<dealii::Tensor<2, dim>> grad_u;
    std::vector<double>                 J, JxW;
    /// Spatial gradients grad_x N_I = F^-T grad_X N_I of the scalar shape
    /// functions of the displacement element, [q][I] (1/m). DoF k of the
    /// primitive vector element is component[k] of node[k]; its shape
    /// gradient is e_c (x) grad_x N_I.
    std::vector<std::vector<dealii::Tensor<1, dim>>> grad_x;
    std::vector<unsigned int>                        component, node;
    std::vector<unsigned int> dof; ///< of (node I, component c): [I dim + c]
    /// Work arrays of the tangent, node index J fastest with the node count
    /// padded to the SIMD width (stride): the spatial gradients [b][J]
    /// (1/m), tau grad_x N_J JxW [b][J] (N/m), cc_{c a d b} grad_x N_J[b]
    /// JxW [(c dim + d) dim + a][J] (N/m), and the tangent summed over the
    /// quadrature points [c dim + d][I][J] (N/m).
    unsigned int           stride = 0;
    std::vector<double>    grad_j, tau_grad, c_grad, node_tangent;
    ElementDilatation<dim> dilatation;
  };

  /// What one cell contributes; copied into the global system serially.
  struct AssemblyCopyData
  {
    dealii::FullMatrix<double>                   matrix;
    dealii::Vector<double>                       internal; ///< f_int (N)
    dealii::Vector<double>                       external; ///< f_ext (N)
    std::vector<dealii::types::global_dof_index> dof_indices;
    unsigned int cell_index = 0; ///< active cell index
    /// With a split tangent (mixed formulation): matrix holds the
    /// displacement block A (with the augmented Lagrangian term), volumetric
    /// the coupling G^T D G, and G, D and S_inverse its factors
    /// (VolumetricCoupling; ElementDilatation::augment).
    dealii::FullMatrix<double> volumetric, G, D, S_inverse;
    /// Mixed formulation: the cell's J~ and p~ coefficients used, and with
    /// the matrix how they change with the displacement increment
    /// (ElementDilatation; DilatationState).
    DilatationCoefficients  coefficients;
    DilatationLinearization linearization;
    double                  volume = 0; ///< of the cell (m^3)
    /// The cell's share of the step's potential: strain energy (the
    /// condensed u-p-J energy for the mixed formulation) plus the inertia
    /// term minus the work of the external forces at their present values
    /// (J; J/m in 2D).
    double energy = 0;
    /// Its parts: the strain energy, and minus the work of the external
    /// forces at their present values, -f_ext . u (J; J/m in 2D).
    double      strain_energy = 0, load_potential = 0;
    bool        failed   = false; ///< inverted element
    double      failed_J = 0;
    std::string failed_cell;
  };

  /**
   * The inertia of an implicit dynamic (backward Euler) step: on every cell
   * f_k += m_k (u_k - u*_k) / dt^2 and K_kk += m_k / dt^2, with the
   * row-sum lumped element mass m_k = int rho_0 N_k dV (positive for FE_Q of
   * degree 1 and 2) and the predictor u* = u_n + dt v_n. Inactive (quasi-
   * static) when predictor is null.
   */
  struct InertiaTerm
  {
    /// u* (m), ghosted; null: no inertia.
    const dealii::TrilinosWrappers::MPI::Vector *predictor = nullptr;
    double inverse_dt_squared = 0; ///< 1/dt^2 (1/s^2)
    bool   active() const
    {
      return predictor != nullptr;
    }
  };

  /**
   * The weak form of the quasi-static solid on one cell, in the spatial
   * (updated) form of the total-Lagrangian equations (as deal.II step-44):
   *   internal force  f_k = int tau : sym(grad_x N_k) dV,
   *   tangent         K_kl = int sym(grad_x N_k) : J cc : sym(grad_x N_l)
   *                          + grad_x N_k : (grad_x N_l tau) dV
   *                          (+ K_con of ElementDilatation for u-p-J),
   *   body force      int N_k rho_0 g dV,
   *   dead traction   int N_k t_0 dA,
   *   follower load   -int N_k p J F^-T N dA, with its (unsymmetric)
   *                   linearisation,
   *   inertia         (implicit dynamics only) see InertiaTerm.
   * Integrals are over the reference configuration. In 2D the material is
   * evaluated in plane strain.
   */
  template <int dim> class CellAssembler
  {
  public:
    /// @p augmentation: with a split volumetric coupling, the augmented
    /// Lagrangian weight of the displacement block in units of the initial
    /// shear modulus (ElementDilatation::augment; 0: none).
    CellAssembler(const MaterialLibrary         &materials,
                  const BoundaryConditions<dim> &boundary_conditions,
                  const Formulation              formulation,
                  const double                   augmentation = 0);

    /// Fill @p copy for @p cell at displacement @p u (ghosted). With
    /// @p split_volumetric the mixed formulation's volumetric coupling is
    /// kept apart from the matrix (see AssemblyCopyData). The mixed
    /// formulation takes J~ and p~ from @p given, or projects them from
    /// @p u where it is null (ElementDilatation).
    void
    assemble(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
             const dealii::TrilinosWrappers::MPI::Vector                  &u,
             const bool                    with_matrix,
             const InertiaTerm            &inertia,
             const bool                    split_volumetric,
             const DilatationCoefficients *given,
             AssemblyScratchData<dim>     &scratch,
             AssemblyCopyData             &copy) const;

    /// The row-sum lumped mass m_k = int rho_0 N_k dV (kg; kg/m in 2D) of
    /// the cell that @p fe_values was last reinit'ed on.
    static void lumped_mass(const dealii::FEValues<dim> &fe_values,
                            const double                 density,
                            dealii::Vector<double>      &mass);

  private:
    void add_inertia(const dealii::TrilinosWrappers::MPI::Vector &u,
                     const Material                              &material,
                     const bool                                   with_matrix,
                     const InertiaTerm                           &inertia,
                     AssemblyScratchData<dim>                    &scratch,
                     AssemblyCopyData                            &copy) const;

    /// The spatial shape gradients and J at every quadrature point; throws
    /// InvertedMaterialState where J <= 0.
    static void
    spatial_gradients(const dealii::TrilinosWrappers::MPI::Vector &u,
                      AssemblyScratchData<dim>                    &scratch);

    /// Material and geometric tangent of one quadrature point, added to
    /// scratch.node_tangent (lower triangle of node pairs, J <= I).
    static void add_tangent(const unsigned int                     q,
                            const dealii::SymmetricTensor<4, dim> &Jc,
                            const dealii::SymmetricTensor<2, dim> &tau,
                            const double                           JxW,
                            AssemblyScratchData<dim>              &scratch);

    /// scratch.node_tangent into the lower triangle of @p matrix.
    static void scatter_tangent(AssemblyScratchData<dim>   &scratch,
                                dealii::FullMatrix<double> &matrix);

    void assemble_volume(const dealii::TrilinosWrappers::MPI::Vector &u,
                         const Material                              &material,
                         const bool                    with_matrix,
                         const bool                    split_volumetric,
                         const DilatationCoefficients *given,
                         AssemblyScratchData<dim>     &scratch,
                         AssemblyCopyData             &copy) const;

    /// Mixed formulation with given J~ and p~: G (into copy.G), the force
    /// correction G^T s and, with the matrix, the linearisation of the
    /// element unknowns.
    void add_dilatation_terms(const bool                with_matrix,
                              AssemblyScratchData<dim> &scratch,
                              AssemblyCopyData         &copy) const;

    /// K_con of the mixed formulation, into the matrix or, with @p split,
    /// into copy.volumetric with its factors. Needs copy.G.
    void add_volumetric_coupling(const Material           &material,
                                 const bool                split,
                                 AssemblyScratchData<dim> &scratch,
                                 AssemblyCopyData         &copy) const;

    /// The lower triangle (with diagonal) of G^T DG added to @p target.
    static void add_lower_product(const dealii::FullMatrix<double> &G,
                                  const dealii::FullMatrix<double> &DG,
                                  dealii::FullMatrix<double>       &target);

    void assemble_boundary(
        const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
        const dealii::TrilinosWrappers::MPI::Vector                  &u,
        const bool                with_matrix,
        AssemblyScratchData<dim> &scratch,
        AssemblyCopyData         &copy) const;

    /// The follower pressure @p p (Pa) on the face that
    /// scratch.fe_face_values was set up for: its external force
    /// -int p J F^-T N N_k dA and, with @p with_matrix, its tangent.
    void add_pressure(const dealii::Function<dim>                 &p,
                      const dealii::TrilinosWrappers::MPI::Vector &u,
                      const bool                                   with_matrix,
                      AssemblyScratchData<dim>                    &scratch,
                      AssemblyCopyData                            &copy) const;

    /// The element dilatation of a mixed cell: J~ and p~ given, or
    /// projected from J; their coefficients into @p copy.
    void start_dilatation(const Material               &material,
                          const DilatationCoefficients *given,
                          AssemblyScratchData<dim>     &scratch,
                          AssemblyCopyData             &copy) const;

    const MaterialLibrary         &materials;
    const BoundaryConditions<dim> &boundary_conditions;
    const Formulation              formulation;
    const double                   augmentation; ///< of the split coupling; 1
  };
} // namespace softgrasp

#endif
