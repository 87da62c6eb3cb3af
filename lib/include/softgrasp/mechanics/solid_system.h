#ifndef softgrasp_mechanics_solid_system_h
#define softgrasp_mechanics_solid_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <map>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/cell_assembler.h>
#include <softgrasp/mechanics/dilatation_state.h>
#include <softgrasp/mechanics/linear_solver.h>
#include <softgrasp/mechanics/nodal_conditions.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <softgrasp/mechanics/volumetric_coupling.h>

namespace softgrasp
{
  /**
   * The discrete solid: degrees of freedom of the displacement (FE_Q^dim on
   * a distributed triangulation), constraints, the Trilinos tangent matrix
   * and vectors, and the WorkStream assembly over locally owned cells.
   *
   * Dirichlet conditions are imposed on the Newton increment as
   * inhomogeneous constraints du = g(t) - u, rebuilt every iteration, so a
   * boundary value reached only partially (after a line search) is
   * completed by the next iteration.
   */
  template <int dim> class SolidSystem
  {
  public:
    struct AssemblyResult
    {
      bool        ok = true;         ///< false if an element inverted
      std::string failed_cell;       ///< where, if !ok
      double      failed_J      = 0; ///< the J found there
      double      residual_norm = 0; ///< |f_int - f_ext| on free dofs (N)
      double      residual_max  = 0; ///< its largest entry (N)
      double      force_scale   = 0; ///< max(|f_int|, |f_ext|) (N)
      /// The step's potential: strain energy + inertia term - f_ext . u +
      /// the nodal conditions' potential (J; J/m in 2D). Exact for dead
      /// loads; a follower pressure has none (has_potential() is false).
      double energy = 0;
      /// Its parts: the strain energy (the condensed u-p-J energy with the
      /// mixed formulation) and -f_ext . u (J; J/m in 2D).
      double strain_energy = 0, load_potential = 0;
    };

    SolidSystem(dealii::parallel::distributed::Triangulation<dim> &tria,
                const MaterialLibrary                             &materials,
                const BoundaryConditions<dim>                     &bcs,
                const SolverParameters                            &parameters,
                const unsigned int   mapping_degree,
                dealii::TimerOutput &timer);

    /// Abandons (does not free) a direct factorisation still held: freeing
    /// it is collective, and a destructor may run on one rank only while
    /// an error unwinds. In the normal flow release_factorization() has
    /// freed it.
    ~SolidSystem();

    /// Distribute dofs and size matrix and vectors (the solution is zeroed).
    void setup();

    /// Whether setup() allocates the tangent matrix (default: yes). An
    /// explicit solver needs residuals only and saves its memory.
    void set_tangent_needed(const bool needed);

    /**
     * Rebuild the constraints for the boundary values at the current time
     * of the boundary conditions. Returns the largest |g - u| (m) at
     * Dirichlet dofs, i.e. how far the boundary values are from reached.
     */
    double update_constraints();

    /// Assemble f_int - f_ext (and the tangent) at the current solution.
    AssemblyResult assemble(const bool with_matrix);
    /// What the last assemble() returned (on every process).
    const AssemblyResult &last_assembly() const;

    /**
     * Start a Newton solve: with the mixed formulation, the element
     * pressure and dilatation become unknowns (DilatationState), recorded
     * from the solution at the next assembly and moved by apply_update().
     * end_newton_solve() returns to projecting them from the solution.
     */
    void begin_newton_solve();
    void end_newton_solve();
    /// Remember the solution (and the element unknowns) as the start of an
    /// update.
    void begin_update();
    /// solution = start + @p alpha @p du (m), and the element unknowns
    /// alike through the linearisation of the last tangent.
    void apply_update(const dealii::TrilinosWrappers::MPI::Vector &du,
                      const double                                 alpha);

    /// Include the inertia of an implicit dynamic step in the assemblies
    /// that follow (InertiaTerm; a default-constructed one removes it).
    void set_inertia(const InertiaTerm &inertia);

    /// The row-sum lumped mass per dof (kg; kg/m in 2D), owned entries;
    /// the same masses as the inertia term. Collective.
    dealii::TrilinosWrappers::MPI::Vector lumped_mass() const;

    /// Free the direct solver's factorisation (MUMPS keeps its symbolic
    /// factorisation between the solves of one Newton solve). Collective.
    void release_factorization();

    /// Solve K du = -r with the last assembled system; du obeys constraints.
    /// An iterative solver stops at @p relative_tolerance times |rhs|
    /// (at least 'Linear solver/Relative tolerance').
    LinearSolver::Result solve(dealii::TrilinosWrappers::MPI::Vector &du,
                               const double relative_tolerance = 0);

    /// The linear solver in use, for the run summary (after setup()).
    std::string linear_solver_name() const;

    /// du . (f_ext - f_int) on free dofs, from the last assembly (N m).
    double residual_dot(const dealii::TrilinosWrappers::MPI::Vector &du) const;

    /**
     * Take f_int and f_ext (N) from elsewhere (owned entries, e.g. the
     * explicit solver's matrix-free forces) instead of an assemble(), for
     * reactions() and internal_forces(). Collective.
     */
    void set_forces(
        const std::function<double(dealii::types::global_dof_index)> &f_int,
        const std::function<double(dealii::types::global_dof_index)> &f_ext);

    /// Reaction force f_int - f_ext (N) summed over each Dirichlet boundary.
    std::map<dealii::types::boundary_id, dealii::Tensor<1, dim>>
    reactions() const;

    /// Displacement (m) at reference points; NaN where outside the mesh.
    std::vector<dealii::Tensor<1, dim>>
    point_displacements(const std::vector<dealii::Point<dim>> &points) const;

    /// Largest extent (m) of the reference mesh's bounding box.
    double length_scale() const;

    /**
     * Let @p conditions replace the equations of the nodes they govern
     * (e.g. contact); nullptr removes them. Not owned.
     */
    void set_nodal_conditions(NodalConditions<dim> *conditions);
    bool has_nodal_conditions() const;
    /// Whether the residual is the negative gradient of the energy of
    /// assemble() (no follower loads; no nodal conditions, or potential
    /// ones), so that Newton may search its line on that energy.
    bool has_potential() const;
    /// Whether the nodal conditions ask Newton to backtrack on the
    /// residual norm (NodalConditions::backtrack_on_residual()).
    bool backtrack_on_residual() const;
    /// Whether the tangents that follow project the nodal conditions' node
    /// Hessians to positive semi-definite (NodalConditions::
    /// project_to_positive()).
    void project_nodal_hessians(const bool on);
    /// The nodal conditions' line for the Newton log ("" without them).
    std::string nodal_conditions_report() const;

    /**
     * Where the residual of the last assembly is largest: its value (N),
     * the equation (component) and the reference position (m) of its node,
     * and what the nodal conditions say about that node. For the message
     * of a Newton solve that does not converge. Collective.
     */
    std::string describe_largest_residual() const;

    /// f_int and f_ext (N) of the last assembly (owned entries valid).
    const dealii::TrilinosWrappers::MPI::Vector &internal_forces() const;
    const dealii::TrilinosWrappers::MPI::Vector &external_forces() const;
    /// The residual f_ext - f_int (+ the nodal conditions' forces) of the
    /// last assembly (N), zero in constrained rows: with a potential, its
    /// negative gradient on the free dofs.
    const dealii::TrilinosWrappers::MPI::Vector &residual_vector() const;
    /// The tangent of the last assemble(true) (N/m), rows and columns of
    /// constrained dofs condensed; with a split volumetric coupling the
    /// displacement block only.
    const dealii::TrilinosWrappers::SparseMatrix &tangent_matrix() const;
    /// Hanging-node and Dirichlet constraints (homogeneous form).
    const dealii::AffineConstraints<double> &constraint_set() const;
    const dealii::IndexSet                  &locally_owned_dofs() const;
    const dealii::IndexSet                  &locally_relevant_dofs() const;

    /// Make the ghosted copy agree with solution().
    void update_ghosts();

    dealii::TrilinosWrappers::MPI::Vector       &solution();
    const dealii::TrilinosWrappers::MPI::Vector &ghosted_solution() const;
    const dealii::DoFHandler<dim>               &dof_handler() const;
    dealii::DoFHandler<dim>                     &dof_handler();
    const dealii::Mapping<dim>                  &mapping() const;
    const dealii::FiniteElement<dim>            &fe() const;
    MPI_Comm                                     communicator() const;
    dealii::types::global_dof_index              n_dofs() const;

  private:
    void compute_rigid_body_modes();
    /// tangent_constraints = constraints + the nodal conditions' ones.
    void build_tangent_constraints();
    /// Add one cell's tangent and right-hand side (rows transformed by the
    /// nodal conditions, condensed through tangent_constraints); with a
    /// split tangent, record its volumetric coupling.
    void distribute_cell_tangent(const AssemblyCopyData &copy,
                                 dealii::Vector<double> &cell_rhs);
    /// Zero the vectors (and the tangent) that assemble() adds into.
    void start_assembly(const bool with_matrix);
    /// Exchange what assemble() added between processes.
    void compress_assembly(const bool with_matrix);
    /// Make @p result's failure (an inverted element on any process) the
    /// failure on every process; returns whether one failed.
    bool share_failure(AssemblyResult &result) const;
    /// Let the nodal conditions (contact) evaluate themselves at the new
    /// residual, or add their rows to the tangent, and act on the residual.
    void apply_nodal_conditions(const bool with_matrix);

    dealii::parallel::distributed::Triangulation<dim> &triangulation;
    const MaterialLibrary                             &materials;
    const BoundaryConditions<dim>                     &boundary_conditions;
    const SolverParameters                            &parameters;
    dealii::TimerOutput                               &timer;
    const dealii::FESystem<dim>                        finite_element;
    const dealii::MappingQ<dim>                        reference_mapping;
    const dealii::QGauss<dim>                          quadrature;
    const dealii::QGauss<dim - 1>                      face_quadrature;
    dealii::DoFHandler<dim>                            dofs;
    CellAssembler<dim>                                 assembler;
    LinearSolver                                       linear_solver;

    dealii::IndexSet                  owned, relevant;
    dealii::AffineConstraints<double> constraints;
    dealii::AffineConstraints<double> homogeneous_constraints;
    /// constraints plus the nodal conditions' constraints of the tangent
    /// last assembled (what the last linear solve obeys)
    dealii::AffineConstraints<double> tangent_constraints;
    /// tangent_constraints without inhomogeneities (split tangent only)
    dealii::AffineConstraints<double> tangent_homogeneous;
    /// The tangent is A (in 'tangent') + the matrix-free volumetric
    /// coupling (mixed formulation, iterative solver, block preconditioner)
    bool                                       split_volumetric = false;
    VolumetricCoupling<dim>                    volumetric;
    dealii::TrilinosWrappers::SparseMatrix     tangent;
    dealii::TrilinosWrappers::MPI::Vector      u, u_ghosted;
    dealii::TrilinosWrappers::MPI::Vector      rhs, residual, f_int, f_ext;
    std::vector<std::vector<dealii::IndexSet>> reaction_dofs; ///< [id][c]
    double                                     domain_size      = 1; ///< m
    NodalConditions<dim>                      *nodal_conditions = nullptr;
    DilatationState<dim>                       dilatation_state;
    dealii::TrilinosWrappers::MPI::Vector      u_start, du_ghosted;
    bool                                       with_tangent = true;
    InertiaTerm                                inertia;
    AssemblyResult                             last_result;
  };
} // namespace softgrasp

#endif
