#ifndef softgrasp_contact_mortar_contact_h
#define softgrasp_contact_mortar_contact_h

#include <array>
#include <deal.II/base/timer.h>
#include <softgrasp/contact/contact_parameters.h>
#include <softgrasp/contact/nodal_contact_law.h>
#include <softgrasp/mechanics/nodal_conditions.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/rigid/rigid_body_set.h>

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
   * In 2D, the plane problem lies in the world x-y plane (z = 0) and the
   * rigid geoms must be invariant along z there (cylinders along z, spheres
   * centred at z = 0, planes containing z).
   */
  template <int dim> class MortarContact : public NodalConditions<dim>
  {
  public:
    /// Per owned slave node, after evaluate().
    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      std::array<bool, dim>                            free{};
      Eigen::Vector3d reference_position = Eigen::Vector3d::Zero(); ///< X (m)
      Eigen::Vector3d last_converged     = Eigen::Vector3d::Zero(); ///< x (m)
      double          reference_area     = 0; ///< D_j in the reference (m^2)
      double          c                  = 0; ///< complementarity (N/m)
      ContactStatus   status             = ContactStatus::inactive;
      int             body               = -1; ///< nearest body (-1: none)
      unsigned int    geom               = 0;
      double          gap    = std::numeric_limits<double>::infinity(); ///< m
      Eigen::Vector3d normal = Eigen::Vector3d::Zero(); ///< rigid outward
      Eigen::Vector3d force  = Eigen::Vector3d::Zero(); ///< on the body (N)
      Eigen::Vector3d slip   = Eigen::Vector3d::Zero(); ///< in the step (m)
      Eigen::Vector3d phi    = Eigen::Vector3d::Zero();
      Eigen::Matrix3d A      = Eigen::Matrix3d::Identity();
      Eigen::Matrix3d B      = Eigen::Matrix3d::Zero();
    };

    MortarContact(const ContactParameters &parameters,
                  const RigidBodySet      &bodies,
                  const double             shear_modulus,
                  dealii::TimerOutput     &timer);

    /// Find the slave nodes of @p system (after its setup()).
    void setup(const SolidSystem<dim> &system);

    /// Time (s) at which the rigid bodies are placed in evaluate().
    void set_time(const double time);

    /// Record the converged state at @p time (s) as the start of the next
    /// step's slip (call after each converged step and after a restart).
    void accept_step(const SolidSystem<dim> &system, const double time);

    void evaluate(const SolidSystem<dim> &system) override;
    void apply_to_residual(
        dealii::TrilinosWrappers::MPI::Vector &residual) const override;
    void transform_cell_rows(
        const std::vector<dealii::types::global_dof_index> &dof_indices,
        dealii::FullMatrix<double>                         &matrix,
        dealii::Vector<double>                             &rhs) const override;
    void
                add_node_terms(dealii::TrilinosWrappers::SparseMatrix &tangent,
                               dealii::TrilinosWrappers::MPI::Vector  &rhs) const override;
    std::string iteration_report() const override;

    /// The locally owned slave nodes.
    const std::vector<Node> &nodes() const;
    const RigidBodySet      &rigid_bodies() const;
    bool   is_slave_boundary(const dealii::types::boundary_id id) const;
    double time() const;

    /// Global numbers of the last evaluation: active and slipping nodes,
    /// and status changes since the evaluation before.
    unsigned int n_active() const;
    unsigned int n_slip() const;
    unsigned int n_changes() const;
    /// Status changes summed over all evaluations since the last
    /// accept_step() (the active-set changes of a load step).
    unsigned int changes_in_step() const;

  private:
    struct Proximity
    {
      int             body = -1;
      unsigned int    geom = 0;
      double          gap  = std::numeric_limits<double>::infinity();
      Eigen::Vector3d normal;
    };
    Proximity       nearest(const Eigen::Vector3d &x) const;
    Eigen::Vector3d normal_at(const Proximity       &p,
                              const Eigen::Vector3d &x) const;
    Eigen::Matrix3d normal_gradient(const Proximity       &p,
                                    const Eigen::Vector3d &x) const;
    void            place_bodies(const double                    time,
                                 std::vector<std::vector<Pose>> &poses) const;

    const ContactParameters        parameters;
    const RigidBodySet            &bodies;
    const double                   shear_modulus;
    dealii::TimerOutput           &timer;
    MPI_Comm                       comm         = MPI_COMM_SELF;
    double                         current_time = 0, converged_time = 0;
    double                         fd_step = 1e-9; ///< m
    std::vector<std::vector<Pose>> poses_now, poses_converged;
    std::vector<Node>              node_list;
    /// Local dofs of each support point of a cell: [point][component].
    std::vector<std::array<unsigned int, dim>>             cell_nodes;
    std::array<dealii::TrilinosWrappers::MPI::Vector, dim> row_combination;
    dealii::TrilinosWrappers::MPI::Vector                  governed;
    dealii::TrilinosWrappers::MPI::Vector                  owned_scratch;
    unsigned int active_count = 0, slip_count = 0, change_count = 0;
    unsigned int step_changes = 0;
  };
} // namespace softgrasp

#endif
