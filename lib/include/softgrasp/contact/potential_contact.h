#ifndef softgrasp_contact_potential_contact_h
#define softgrasp_contact_potential_contact_h

#include <deal.II/base/timer.h>
#include <softgrasp/contact/implicit_contact.h>
#include <softgrasp/contact/nodal_potential.h>

namespace softgrasp
{
  /**
   * Frictional contact as one incremental potential per load step
   * ('Contact/Enforcement = incremental potential'). Each slave node adds
   * to the solid's potential (strain energy, inertia, minus external work)
   *   C + D = (max(0, lam - k g)^2 - lam^2) / (2 k)
   *           + mu lambda^k phi_eps(|T^T w|)
   * (evaluate_nodal_potential()): an augmented Lagrangian on the signed
   * distance g to the nearest rigid geom, and the lagged friction
   * potential of the node's slip w relative to the material point of the
   * rigid body it sat at when the last step converged. For fixed lam,
   * lambda^k and T the step is the minimisation of one C1 potential, which
   * Newton with a line search on that potential cannot cycle on.
   *
   * Outer iterations (settle()): after each converged Newton solve the
   * multipliers take the new normal forces (Uzawa: lam = lambda), and so
   * do the lagged normal forces lambda^k, with the frames T at the new
   * normals; the step is done when the normal forces change by at most
   * 'Contact/Settle tolerance' times the largest, the normals by at most
   * that angle, and the deepest penetration is at most that fraction of
   * the node spacing. Its rows are the node's own equilibrium rows; it
   * adds no constraints, and its tangent stays symmetric.
   */
  template <int dim> class PotentialContact : public ImplicitContact<dim>
  {
  public:
    using Node = ContactNode<dim>;

    PotentialContact(const ContactParameters &parameters,
                     const RigidBodySet      &bodies,
                     const double             shear_modulus,
                     dealii::TimerOutput     &timer);

    void setup(const SolidSystem<dim> &system) override;
    void accept_step(const SolidSystem<dim> &system,
                     const double            time) override;
    void begin_step() override;
    bool settle(const SolidSystem<dim> &system, std::string &report) override;
    unsigned int max_outer_iterations() const override;
    unsigned int max_newton_iterations() const override;
    double       coulomb_excess() const override;
    bool         accept_unsettled() const override;
    unsigned int changes_in_step() const override;

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
    bool is_potential() const override;
    bool backtrack_on_residual() const override;
    bool begin_polish() override;
    void end_polish(const bool keep) override;
    unsigned int polish_after() const override;
    void         project_to_positive(const bool on) override;
    double       energy() const override;
    std::string  iteration_report() const override;
    std::string
    describe_node(const dealii::types::global_dof_index dof) const override;

  private:
    using Proximity = typename ContactSurface<dim>::Proximity;
    using ContactSurface<dim>::node_list;
    using ContactSurface<dim>::poses_now;
    using ContactSurface<dim>::current_time;
    using ContactSurface<dim>::comm;
    using ContactSurface<dim>::parameters;
    using ContactSurface<dim>::active_count;
    using ContactSurface<dim>::slip_count;
    using ContactSurface<dim>::nearest;
    using ContactSurface<dim>::normal_at;
    using ContactSurface<dim>::place_bodies;

    /// What a node's potential holds fixed within a Newton solve.
    struct Lag
    {
      double          multiplier   = 0;                       ///< lam (N)
      double          normal_force = 0;                       ///< lambda^k (N)
      Eigen::Vector3d normal       = Eigen::Vector3d::Zero(); ///< of T
      int             body         = -1; ///< geom of the slip (-1: none)
      unsigned int    geom         = 0;
    };

    /// Per node: its penalty and spacing, the lag of the solve and of the
    /// last converged step, and its potential at the last evaluation.
    struct NodeData
    {
      double         penalty = 0; ///< k (N/m)
      double         spacing = 0; ///< h (m)
      Lag            lag, accepted;
      NodalPotential potential;
      /// The gap to the nearest geom at the last evaluation (m; that of
      /// the potential may be to the lag's geom, proximity())
      double nearest_gap = 1e300;
    };

    /// The input of node @p j's potential at position @p x, nearest to
    /// geom @p p.
    /// The geom node @p j at @p x (m) acts with: the nearest, or the
    /// lag's while the nearest does not penetrate the node beyond the
    /// settle tolerance. Records the nearest gap.
    Proximity proximity(const unsigned int j, const Eigen::Vector3d &x);

    NodalPotentialInput potential_input(const unsigned int     j,
                                        const Eigen::Vector3d &x,
                                        const Proximity       &p) const;

    const double                   shear_modulus;
    double                         fd_step = 1e-9; ///< m
    dealii::TimerOutput           &timer;
    std::vector<std::vector<Pose>> poses_converged;
    std::vector<NodeData>          data; ///< per node of node_list
    double                         total_energy = 0;
    /// Normal-force changes below this are round-off (N): 1e-8 of the
    /// largest k h (settle()).
    double force_floor = 0;
    bool   project     = false;
    /// In the polish (begin_polish()): friction against the current normal
    /// forces; the lag it started from.
    bool             polishing = false;
    std::vector<Lag> lag_before_polish;
    double           excess = 0; ///< coulomb_excess() of the last settle()
    unsigned int     change_count = 0, step_changes = 0;
  };
} // namespace softgrasp

#endif
