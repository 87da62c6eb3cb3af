#ifndef softgrasp_contact_mortar_contact_h
#define softgrasp_contact_mortar_contact_h

#include <array>
#include <deal.II/base/timer.h>
#include <softgrasp/contact/implicit_contact.h>
#include <softgrasp/contact/nodal_contact_law.h>
#include <softgrasp/mechanics/nodal_conditions.h>

namespace softgrasp
{
  /**
   * Mortar contact between the slave surface of a deformable solid and
   * moving rigid bodies, with Coulomb friction, solved by a semi-smooth
   * Newton (primal-dual active set) method.
   *
   * Discretisation. The contact traction on the slave surface is
   * lambda_h = sum_j Psi_j lambda_j with dual basis functions Psi_j,
   * biorthogonal to the displacement shape functions N_k on the surface
   * (int Psi_j N_k dA = delta_jk D_j, D_j = int N_j dA). The gap is
   * interpolated from its nodal values g_j, the signed distance of node j
   * to the nearest rigid geom. The weighted gap is then
   * int Psi_j g_h dA = D_j g_j and the contact virtual work
   * int lambda_h . du dA = sum_j D_j lambda_j . du_j: the mortar matrix D is
   * diagonal, so the multipliers condense node by node. The nodal contact
   * force f_j = D_j lambda_j equals the node's out-of-balance force
   * f_int - f_ext, and the KKT conditions (g_j >= 0, n . f_j >= 0,
   * g_j n . f_j = 0, Coulomb's law for the tangential part) are imposed by
   * the complementarity functions of evaluate_nodal_contact(). No penalty
   * enters the converged solution.
   *
   * Friction is path dependent: the slip of a node in a load step is its
   * motion relative to the rigid surface point it sat at when the last
   * step converged (accept_step()).
   *
   * The surface geometry (nodes, rigid poses, distances) comes from
   * ContactSurface.
   */
  template <int dim> class MortarContact : public ImplicitContact<dim>
  {
  public:
    using Node = ContactNode<dim>;

    MortarContact(const ContactParameters &parameters,
                  const RigidBodySet      &bodies,
                  const double             shear_modulus,
                  dealii::TimerOutput     &timer);

    /// Find the slave nodes of @p system (after its setup()).
    void setup(const SolidSystem<dim> &system) override;

    /// Record the converged state at @p time (s) as the start of the next
    /// step's slip (call after each converged step and after a restart).
    void accept_step(const SolidSystem<dim> &system,
                     const double            time) override;

    void evaluate(const SolidSystem<dim> &system) override;
    void apply_to_residual(
        dealii::TrilinosWrappers::MPI::Vector &residual) const override;
    void transform_cell_rows(
        const std::vector<dealii::types::global_dof_index> &dof_indices,
        dealii::FullMatrix<double>                         &matrix,
        dealii::Vector<double>                             &rhs) const override;
    void add_constraints(
        dealii::AffineConstraints<double> &constraints) const override;
    void
         add_node_terms(const dealii::AffineConstraints<double> &constraints,
                        dealii::TrilinosWrappers::SparseMatrix  &tangent,
                        dealii::TrilinosWrappers::MPI::Vector   &rhs) const override;
    bool symmetric() const override;
    std::string iteration_report() const override;
    std::string
    describe_node(const dealii::types::global_dof_index dof) const override;

    /**
     * Implicit dynamics: add each node's inertia stiffness m_j/dt^2 to its
     * complementarity parameters (c_n = c_t = c + m_j/dt^2), so that the
     * open/closed and stick/slip predictions weigh gap and slip against
     * the stiffness the node really has; @p mass (kg per dof; ghosted) is
     * the lumped mass. @p inverse_dt_squared = 0 restores c (quasi-static).
     */
    void set_inertia(const dealii::TrilinosWrappers::MPI::Vector &mass,
                     const double inverse_dt_squared) override;

    /// Status changes since the evaluation before.
    unsigned int n_changes() const;
    /// Status changes summed over all evaluations since the last
    /// accept_step() (the active-set changes of a load step).
    unsigned int changes_in_step() const override;

  private:
    using Proximity = typename ContactSurface<dim>::Proximity;
    using ContactSurface<dim>::node_list;
    using ContactSurface<dim>::poses_now;
    using ContactSurface<dim>::current_time;
    using ContactSurface<dim>::comm;
    using ContactSurface<dim>::cell_nodes;
    using ContactSurface<dim>::parameters;
    using ContactSurface<dim>::active_count;
    using ContactSurface<dim>::slip_count;
    using ContactSurface<dim>::nearest;
    using ContactSurface<dim>::normal_at;
    using ContactSurface<dim>::place_bodies;

    /// The complementarity function of a node and its linearisation.
    struct NodeLaw
    {
      double          c   = 0; ///< complementarity parameter, static (N/m)
      double          c_n = 0; ///< used for the normal conditions (N/m)
      double          c_t = 0; ///< used for the tangential conditions
      Eigen::Vector3d phi = Eigen::Vector3d::Zero();
      Eigen::Matrix3d A   = Eigen::Matrix3d::Identity();
      Eigen::Matrix3d B   = Eigen::Matrix3d::Zero();
      /// The geom the node is closed against in this load step (-1: none),
      /// and how often it changed geom in the step (see pair()).
      int          pair_body     = -1;
      unsigned int pair_geom     = 0;
      unsigned int pair_switches = 0;
    };

    /// How a closed node's equations enter the linear solve (the value of
    /// `governed` at its first dof).
    enum Governance : int
    {
      free_rows   = 0, ///< its own equilibrium rows (open node)
      rows_only   = 1, ///< rows combined by A, no constraint (degenerate)
      normal_line = 2, ///< one constraint w . du = beta, rows by A
      fixed       = 3  ///< every free component prescribed (A = 0)
    };

    /**
     * The geom node @p j is held against at @p x: the nearest one, except
     * that a node closed in this load step keeps its geom unless it lies
     * deeper in another by more than 1 % of its size, at most twice per
     * step. In a crease between two geoms (a finger's links at their
     * joint) the nearest geom alternates between the two as Newton moves
     * the node, and the active set would cycle without end.
     */
    Proximity pair(const unsigned int j, const Eigen::Vector3d &x);

    /// The input of the nodal contact law of node @p j at @p x under the
    /// residual force @p f, paired with @p p.
    NodalContactInput contact_input(const unsigned int     j,
                                    const Eigen::Vector3d &x,
                                    const Eigen::Vector3d &f,
                                    const Proximity       &p) const;

    /// Stores the law's result @p lin for node @p j, paired with @p p, in
    /// the node and its rule.
    void store(const unsigned int               j,
               const Proximity                 &p,
               const NodalContactInput         &input,
               const NodalContactLinearization &lin);

    /// Constrained components (symmetry planes, hanging nodes) keep their
    /// own equations: @p rule's rows of them become du_a = 0 (A = I,
    /// B = 0, phi = f); the contact conditions act on the free ones.
    static void keep_constrained_rows(const Node            &node,
                                      NodeLaw               &rule,
                                      const Eigen::Vector3d &f);

    /// Collect relevant_nodes.
    void find_relevant_nodes(const SolidSystem<dim> &system);

    /**
     * The constraint data of a closed node from its law (free components
     * only): for a sticking node the prescribed increment du = -B^-1 phi;
     * for a sliding one the normal equation (B^T n) . du = -n . phi, with
     * w = c_n n in place of B^T n when it slides without friction (then
     * the condensed rows are tested with tangents, orthogonal to n, and
     * stay symmetric; the two differ by H f_t / c_n, which vanishes at
     * convergence). Writes coefficients and values at the node's dofs.
     */
    Governance constrain(const Node                            &node,
                         const NodeLaw                         &rule,
                         dealii::TrilinosWrappers::MPI::Vector &coefficients,
                         dealii::TrilinosWrappers::MPI::Vector &values) const;

    const double                   shear_modulus;
    dealii::TimerOutput           &timer;
    double                         converged_time = 0;
    double                         fd_step        = 1e-9; ///< m
    std::vector<std::vector<Pose>> poses_converged;
    std::vector<NodeLaw>           law; ///< per node of node_list
    std::array<dealii::TrilinosWrappers::MPI::Vector, dim> row_combination;
    /// Governance of each closed node at its first dof (ghosted), and its
    /// constraint coefficients and values at its dofs (see constrain()).
    dealii::TrilinosWrappers::MPI::Vector governed;
    dealii::TrilinosWrappers::MPI::Vector constraint_coefficients;
    dealii::TrilinosWrappers::MPI::Vector constraint_values;
    /// Dofs of every slave node on a locally owned cell (owned or ghost).
    std::vector<std::array<dealii::types::global_dof_index, dim>>
                 relevant_nodes;
    unsigned int unsymmetric_count = 0; ///< nodes sliding with friction etc.
    dealii::TrilinosWrappers::MPI::Vector owned_scratch;
    unsigned int                          change_count = 0, step_changes = 0;
    /// Closed nodes whose nearest geom changed at the last evaluation.
    unsigned int switch_count = 0;
  };
} // namespace softgrasp

#endif
