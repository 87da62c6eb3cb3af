#ifndef softgrasp_contact_potential_contact_h
#define softgrasp_contact_potential_contact_h

#include <array>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>
#include <softgrasp/contact/implicit_contact.h>
#include <softgrasp/contact/nodal_potential.h>
#include <vector>

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
   *
   * 'Contact/Potential integration = faces' evaluates these terms at the
   * Gauss points of the slave faces instead of at the nodes (each point
   * with its own multiplier, lag and penalty k = factor 2 mu_0 w / h for
   * its weight w): the position, gap and slip are interpolated from the
   * face's nodes, so a rigid edge cannot push in between the nodes. The
   * nodes then report the forces summed over their faces.
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
    void begin_step(const double step) override;
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

    /// The global numbers of points of the potential (nodes or face Gauss
    /// points) and of those pressed (normal force > 0) at the last
    /// evaluation. Collective.
    std::pair<unsigned int, unsigned int> count_points() const;

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
    using ContactSurface<dim>::cell_nodes;

    /// What a point's potential holds fixed within a Newton solve.
    struct Lag
    {
      double          multiplier   = 0;                       ///< lam (N)
      double          normal_force = 0;                       ///< lambda^k (N)
      Eigen::Vector3d normal       = Eigen::Vector3d::Zero(); ///< of T
      int             body         = -1; ///< geom of the slip (-1: none)
      unsigned int    geom         = 0;
    };

    /**
     * One point of the potential: a slave node ('Potential integration =
     * nodes') or a Gauss point of a slave face ('faces'). Its position is
     * x = X + sum_k N_k u_k over the nodes of its patch; its weight is the
     * node's area or the point's reference JxW. Holds its penalty and
     * spacing, the lag of the solve and of the last converged step, and its
     * potential at the last evaluation.
     */
    struct Point
    {
      unsigned int        patch = 0;
      std::vector<double> shape;                                    ///< N_k
      Eigen::Vector3d reference_position = Eigen::Vector3d::Zero(); ///< X (m)
      Eigen::Vector3d last_converged     = Eigen::Vector3d::Zero(); ///< x (m)
      double          weight             = 0; ///< m^2 (m in 2D)
      double          penalty            = 0; ///< k (N/m)
      double          spacing            = 0; ///< h (m)
      Lag             lag, accepted;
      NodalPotential  potential;
      Proximity       proximity; ///< of the last evaluation
      /// The gap to the nearest geom at the last evaluation (m; that of
      /// the potential may be to the lag's geom, find_proximity())
      double nearest_gap = 1e300;
    };

    /// The nodes a run of points interpolates: one slave node, or the
    /// support points of one slave face of an owned cell.
    struct Patch
    {
      std::vector<dealii::types::global_dof_index> dofs; ///< [k * dim + c]
      std::vector<bool>                            free; ///< not constrained
      unsigned int                                 begin = 0, end = 0;
    };

    /// One point per slave node (patch j = node j).
    void make_node_points();
    /// The Gauss points of the slave faces of the owned cells.
    void make_face_points(const SolidSystem<dim> &system);
    /// The penalty and spacing of each point, and force_floor.
    void set_penalties();
    /// Point @p i's position for the displacement @p u (ghosted).
    Eigen::Vector3d
    position(const unsigned int                           i,
             const dealii::TrilinosWrappers::MPI::Vector &u) const;
    /// The nodes' force, status, slip and nearest geom from the points'
    /// potentials (the force on face points summed over the faces of all
    /// ranks); the free dofs.
    void update_nodes(const SolidSystem<dim> &system);
    /// Face mode: sum the points' forces (N_k f_q), slips and closed
    /// weights onto the nodes (nodal_force, nodal_slip, nodal_weight; over
    /// all ranks). Collective.
    void gather_face_points();
    /// Face mode: the projected multipliers Lambda_k = max(0, sum_q N_k
    /// lambda_q / D_k), D_k = sum_q N_k w_q, into projected_multiplier, and
    /// the largest change of the nodal force D_k Lambda_k against the solve's
    /// multipliers (N), the largest such force (N), and the deepest weighted
    /// penetration -sum_q N_k w_q g_q / D_k over the node spacing (1; gaps
    /// capped at the spacing). Collective.
    std::array<double, 3> nodal_settle_measures();
    /**
     * Face mode, the Uzawa update: the multiplier field lives on the nodes,
     * Lambda = projected_multiplier (nodal_settle_measures()), and each
     * point's multiplier and lagged normal force are w_q sum_k N_k Lambda_k.
     * Where the contact is closed the step then converges to zero weighted
     * gaps int N_k g dA = 0 (the mortar condition: as many as there are
     * nodes), not to a zero gap at every Gauss point, which the nodes cannot
     * meet and which would let the multipliers gather on a few points and
     * stiffen the surface.
     */
    void project_multipliers();
    /// Set @p point's multiplier and lagged normal force to @p normal_force
    /// (N; the latter 0 away from any geom), its frame to its current normal.
    void lag_at(Point &point, const double normal_force);
    /// The pressure sum_k N_k(x_q) v_k (Pa) at @p point from the nodal
    /// values @p nodal (ghosted where the point's face is not owned).
    double
    point_pressure(const Point                                 &point,
                   const dealii::TrilinosWrappers::MPI::Vector &nodal) const;
    /// Face mode, in the polish: the points' friction against the pressure
    /// projected from their current forces (its derivative frozen);
    /// returns the potential's energy (J). Collective.
    double polish_on_faces(const dealii::TrilinosWrappers::MPI::Vector &u);
    /// Face mode, after nodal_settle_measures(): max_q (|f_t,q| - mu w_q
    /// sum_k N_k Lambda_k) over the points, Lambda the projected
    /// multipliers, relative to mu times the largest point force
    /// w_q sum_k N_k Lambda_k (coulomb_excess()). Collective.
    double coulomb_excess_on_faces();

    /**
     * The geom point @p i at @p x (m) acts with: the nearest, or the
     * lag's while the nearest does not penetrate the point beyond the
     * settle tolerance. Records the nearest gap.
     */
    Proximity find_proximity(const unsigned int i, const Eigen::Vector3d &x);

    /// The input of point @p i's potential at position @p x, to geom @p p.
    NodalPotentialInput potential_input(const unsigned int     i,
                                        const Eigen::Vector3d &x,
                                        const Proximity       &p) const;

    const double shear_modulus;
    double       fd_step = 1e-9; ///< m
    /// The slip length eps of the step begun last (m; 'Slip tolerance'
    /// until the first).
    double                         slip_length = 1e-5;
    dealii::TimerOutput           &timer;
    std::vector<std::vector<Pose>> poses_converged;
    std::vector<Point>             points;
    std::vector<Patch>             patches;
    /// Face mode: the nodes' forces, slips and closed weights, summed over
    /// the faces (writable ghosted vectors of the solid's dofs).
    dealii::TrilinosWrappers::MPI::Vector nodal_force, nodal_slip, nodal_weight;
    dealii::TrilinosWrappers::MPI::Vector nodal_change, nodal_gap; ///< scratch
    /// Face mode: Lambda_k (Pa) in component 0 of each node, owned and
    /// ghosted.
    dealii::TrilinosWrappers::MPI::Vector owned_multiplier, nodal_multiplier;
    /// Face mode: Lambda of the last converged step, before the polish, and
    /// projected from the last solve (owned).
    dealii::TrilinosWrappers::MPI::Vector accepted_multiplier,
        polish_multiplier, projected_multiplier;
    dealii::TrilinosWrappers::MPI::Vector projected_ghosted; ///< ghosted
    double                                total_energy = 0;
    /// Normal-force changes below this are round-off (N): 1e-8 of the
    /// largest k h (settle()).
    double force_floor = 0;
    bool   project     = false;
    /// In the polish (begin_polish()): friction against the current normal
    /// forces; the lag it started from.
    bool             polishing = false;
    std::vector<Lag> lag_before_polish; ///< per point
    double           excess = 0; ///< coulomb_excess() of the last settle()
    unsigned int     change_count = 0, step_changes = 0;
  };
} // namespace softgrasp

#endif
