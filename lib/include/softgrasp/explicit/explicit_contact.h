#ifndef softgrasp_explicit_explicit_contact_h
#define softgrasp_explicit_explicit_contact_h

#include <Eigen/SparseCore>
#include <array>
#include <deal.II/base/timer.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/contact/nodal_potential.h>

namespace softgrasp
{
  /**
   * Contact of the explicit solver: forward-increment Lagrange multipliers
   * (Carpenter, Taylor and Katona 1991) against moving rigid bodies, with
   * Coulomb friction.
   *
   * After the unconstrained central-difference update has predicted
   * u^{n+1}, each slave node j is corrected so that the step's KKT
   * conditions hold: with the diagonal (lumped) mass M and the gap
   * interpolated from nodal values, the multiplier equations of the
   * constraint are node-local. A node predicted inside the nearest geom
   * (gap g < 0, at the geom's pose at t^{n+1}) is moved back onto its
   * surface along the normal (iterated for curved surfaces), which takes
   * the normal force f_n = m |du_n| / (dt h) (h the velocity step of the
   * central difference); a node outside gets no force (g >= 0, f_n = 0,
   * g f_n = 0). The tangential correction that would keep the node at the
   * surface point it sat at at t^n (carried along by the body's motion in
   * the step) is the stick force f_t; if |f_t| > mu f_n the node slips and
   * f_t is scaled back to mu f_n. The correction du is the contact force's
   * effect on the step: the integrator applies it as the force
   * M du / (dt h) on the tissue at t^n, which is what nodes() report.
   *
   * Components fixed by Dirichlet conditions (symmetry planes) are not
   * moved: the correction is made in the free subspace.
   *
   * 'Contact/Potential integration = faces' enforces the gap integrated
   * over the slave faces instead of at the nodes, so that a rigid edge
   * cannot push in between the nodes (as the implicit solvers' face mode):
   * with dual mortar multipliers (Wohlmuth 2000; Popp et al. 2010) psi_k,
   * biorthogonal to the shape functions on each face (int psi_k N_l dA =
   * delta_kl D_k), the weighted gaps G_k = int psi_k g dA >= 0 of the nodes
   * are the constraints, with the normal pressure Lambda_k >= 0 on each
   * node and the traction t = sum_k psi_k Lambda_k n on the faces.
   * Biorthogonality makes the step's multiplier equations node-local to
   * first order (dG_k/dLambda_k = D_k^2 dt h / m_k on a flat surface), so
   * a few projected Jacobi sweeps solve them (enforce_on_faces()). Coulomb
   * friction stays node-wise, bounded by mu times the node's normal force.
   * This is 'Contact/Explicit faces = dual mortar'.
   *
   * 'Explicit faces = potential' (the default) shares the implicit
   * solvers' face potential instead (enforce_face_potential()): the
   * corrected positions x of the slave nodes minimise
   *   sum_j m_j / (2 dt h) |x_j - x_j^pred|^2 + sum_q Phi_q(x_q),
   * Phi_q the augmented Lagrangian and lagged friction potential of each
   * Gauss point of the slave faces (evaluate_nodal_potential(), the
   * penalty factor 2 mu_0 w_q / h_q). Newton's method with a sparse direct
   * solve on the slave dofs and a line search on that energy finds them;
   * after the step the multipliers take the nodes' projected pressures
   * and the friction lags the new normal forces (one Uzawa update per
   * step instead of the implicit solvers' outer iterations). The slip
   * length eps is scaled by dt / 'Time/Time step', so that the smoothing
   * of Coulomb's law is the same slip speed as in an implicit step.
   */
  template <int dim> class ExplicitContact : public ContactSurface<dim>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    /// @p shear_modulus (Pa): the largest initial one, for the face
    /// potential's penalty (as the implicit solvers').
    ExplicitContact(const ContactParameters &parameters,
                    const RigidBodySet      &bodies,
                    dealii::TimerOutput     &timer,
                    const double             shear_modulus = 0);

    /// The record interval 'Time/Time step' (s): the face potential's slip
    /// length is scaled by the explicit step over it.
    void set_reference_step(const double step);

    /// Find the slave nodes and their free components (those not
    /// constrained in the system's constraint set: Dirichlet, hanging).
    void setup(const SolidSystem<dim> &system) override;

    /**
     * Correct the predicted displacement @p u at t^{n+1} = @p time for
     * contact, given the displacement @p u_old at t^n = time - dt, the
     * step @p dt (s), the velocity step @p h (s) and the lumped @p mass
     * (kg). Updates nodes() (status, gap, normal, force on the tissue).
     * Collective (one reduction for the counts and the penetration).
     */
    void enforce(const double      time,
                 const double      dt,
                 const double      h,
                 const VectorType &mass,
                 const VectorType &u_old,
                 VectorType       &u);

    /**
     * Nodes that start inside a body at @p time (e.g. a grasp recorded by
     * a soft-contact simulator) keep their initial overlap as an allowance
     * that shrinks linearly to zero over the next @p relaxation_steps
     * steps, so the overlap is pushed out gradually instead of by one
     * impulsive step (which would excite the mesh's highest modes).
     * Returns the number of such nodes and the largest overlap (m), on all
     * ranks.
     */
    std::pair<unsigned int, double>
    relax_initial_overlap(const double       time,
                          const VectorType  &u,
                          const unsigned int relaxation_steps);

    /// Largest penetration (m, >= 0) after the last enforce(), on all
    /// ranks: over the nodes (node-wise), of the nodes' weighted gaps
    /// (dual mortar) or over the faces' Gauss points (face potential).
    double max_penetration() const;

    /// Face mode: the Jacobi sweeps (dual mortar) or Newton iterations
    /// (potential) of the last enforce(); 0 in node mode.
    unsigned int last_sweeps() const;

  private:
    using Proximity = typename ContactSurface<dim>::Proximity;
    using ContactSurface<dim>::node_list;
    using ContactSurface<dim>::poses_now;
    using ContactSurface<dim>::parameters;
    using ContactSurface<dim>::comm;

    /// Move @p x (free components only, @p free_mask) along the normal of
    /// geom (body, geom) until its gap is @p target_gap (m, <= 0); returns
    /// the final proximity.
    Proximity project(const int              body,
                      const unsigned int     geom,
                      const Eigen::Vector3d &free_mask,
                      Eigen::Vector3d       &x,
                      const double           target_gap = 0) const;

    using Node = typename ContactSurface<dim>::Node;
    /**
     * The correction of one node at @p x inside geom @p p: back onto the
     * surface (less its @p allowed overlap, m) with the normal multiplier,
     * then, within Coulomb's cone, to where the geom carried its old
     * position @p x_old. @p k (N/m) turns a move into a force; @p mask
     * holds the free components. Moves @p x and sets the node's force,
     * gap, normal, slip and status.
     */
    void correct(Node                  &node,
                 const Proximity       &p,
                 const Eigen::Vector3d &mask,
                 const Eigen::Vector3d &x_old,
                 const double           k,
                 const double           allowed,
                 Eigen::Vector3d       &x) const;

    /**
     * Face mode (enforce() with 'Potential integration = faces'): the
     * projected Jacobi sweeps on the nodal pressures until every weighted
     * gap meets its constraint within the tolerance (at most
     * max_sweeps), with the friction of each node against its normal
     * force. The overlaps still allowed are @p left times the allowance.
     * Collective.
     */
    void enforce_on_faces(const double      dt,
                          const double      h,
                          const VectorType &mass,
                          const VectorType &u_old,
                          const double      left,
                          VectorType       &u);
    /// Set @p node's nearest geom and its normal at the node's position
    /// for the displacement @p u (face modes' report).
    void report_nearest(Node &node, const VectorType &u) const;
    /// Dual mortar: what a step's sweeps share, per owned slave node: the
    /// predicted position (m), the free components (1 or 0), the compliance
    /// dt h / m (m/N), the weighted gap's lower bound (m^3; minus the
    /// allowed overlap times D_k) and the nearest geom of the last sweep.
    struct FaceStep
    {
      std::vector<Eigen::Vector3d> x_pred, mask;
      std::vector<double>          compliance, target;
      std::vector<Proximity>       near;
    };
    /// Dual mortar: the step's FaceStep from the prediction @p u, the
    /// position @p u_old of t^n and the lumped @p mass; resets the nodes'
    /// forces and status.
    FaceStep begin_face_step(const double      dt,
                             const double      h,
                             const VectorType &mass,
                             const VectorType &u_old,
                             const double      left,
                             const VectorType &u);
    /// Dual mortar: whether every weighted gap meets its constraint and
    /// complementarity within 1e-9 of the model's size (after a first
    /// sweep, unless nothing is pressed). Collective.
    bool pressures_settled(const FaceStep &step) const;
    /// Dual mortar: one projected Jacobi update of the pressures
    /// (multiplier, then ghosted), recording each node's nearest geom.
    void update_pressures(FaceStep &step, const VectorType &u);
    /// Dual mortar: each node at its prediction moved by its normal force
    /// (face_force) and Coulomb friction; sets the node's force, slip and
    /// status. Updates @p u's ghosts. Collective.
    void move_face_nodes(const FaceStep &step, VectorType &u);
    /// Face mode: G_k = int psi_k g dA into weighted_gap (owned, summed
    /// over the ranks), with each Gauss point's normal, for @p u (ghosted).
    void weighted_gaps(const VectorType &u);
    /// Face mode: the nodes' normal forces sum_q w_q N_k t_q n_q from the
    /// pressures (multiplier, ghosted) into face_force (owned, summed).
    void normal_forces();

    /// Face potential mode: what one Gauss point holds from step to step.
    struct FacePoint
    {
      double          penalty      = 0; ///< k (N/m)
      double          multiplier   = 0; ///< lam (N)
      double          normal_force = 0; ///< lambda^k (N), lagged
      Eigen::Vector3d lag_normal   = Eigen::Vector3d::Zero(); ///< of T
      int             body         = -1; ///< the lag's geom (-1: none)
      unsigned int    geom         = 0;
      Eigen::Vector3d last         = Eigen::Vector3d::Zero(); ///< x at t^n (m)
      NodalPotential  potential; ///< at the last evaluation
      Eigen::Vector3d x         = Eigen::Vector3d::Zero(); ///< there (m)
      int             near_body = -1; ///< the nearest geom there
      unsigned int    near_geom = 0;
    };

    /// Face mode: a slave face with its dual basis coefficients A = D M^-1
    /// (psi_k = sum_l A_kl N_l; M the face's mass matrix, D its row sums)
    /// and each Gauss point's gap (m, capped) and normal at the last
    /// weighted_gaps(); for the potential, the column of each face dof in
    /// the Newton system (-1: fixed) and the points' states.
    struct ContactFace
    {
      typename ContactSurface<dim>::SlaveFace face;
      dealii::FullMatrix<double>              dual;
      std::vector<double>                     gap;
      std::vector<Eigen::Vector3d>            normal;
      std::vector<int>                        column;
      std::vector<FacePoint>                  points;
    };
    std::vector<ContactFace> faces;
    /// Dual mortar: A = D M^-1 of @p face (M its mass matrix, D the row
    /// sums), so that psi_k = sum_l A_kl N_l.
    static dealii::FullMatrix<double>
    dual_coefficients(const typename ContactSurface<dim>::SlaveFace &face);

    /// Face potential mode: the columns of the free dofs of the slave
    /// nodes, the penalties, and the largest k h (N).
    void setup_face_potential(const SolidSystem<dim> &system);
    /// Face potential mode: the step's minimisation (Newton on the slave
    /// dofs) and the lag update; sets the nodes' report.
    void enforce_face_potential(const double      dt,
                                const double      h,
                                const VectorType &mass,
                                VectorType       &u);
    /// Face potential mode: @p x (by column) into @p u's slave dofs.
    void write_columns(const Eigen::VectorXd &x, VectorType &u) const;
    /// Face potential mode: Newton's method with a backtracking line search
    /// on the step's energy sum a_i (x_i - predicted_i)^2 / 2 + sum_q Phi_q
    /// (a = m / (dt h) by column; slip length @p eps, m), from the last
    /// step's correction; returns the minimiser x, also written into @p u.
    Eigen::VectorXd minimise_step(const Eigen::VectorXd &a,
                                  const Eigen::VectorXd &predicted,
                                  const double           eps,
                                  VectorType            &u);
    /**
     * Face potential mode: sum_q Phi_q at the displacement @p u (slip
     * length @p eps, m); with @p gradient and @p hessian also its gradient
     * (added, by column) and Hessian (triplets; the rigid surface's
     * curvature left out, so that it is positive semi-definite).
     */
    double face_potential(const VectorType                    &u,
                          const double                         eps,
                          Eigen::VectorXd                     *gradient,
                          std::vector<Eigen::Triplet<double>> *hessian);
    /// Face potential mode, after a step: the projected nodal pressures
    /// Lambda_k = max(0, sum_q N_k lambda_q / D_k) as each point's
    /// multiplier and lagged normal force (w_q sum_k N_k Lambda_k), the
    /// frames at the current normals, the positions; the nodes' report
    /// and the penetration (the deepest Gauss point's).
    void update_face_lags(const VectorType &u);

    double                          shear_modulus  = 0; ///< Pa
    double                          reference_step = 0; ///< s
    unsigned int                    degree         = 1;
    std::vector<std::array<int, 3>> node_column; ///< per node, -1: fixed
    unsigned int                    n_columns        = 0;
    double                          force_scale      = 0; ///< max k h (N)
    double                          smallest_spacing = 0; ///< of the faces (m)
    Eigen::VectorXd                 correction; ///< of the last step (m)
    unsigned int                    newton_iterations = 0; ///< last step
    /// Face mode, per dof of the solid (a node's in its x component):
    /// weighted gap (m^3), pressure Lambda (Pa, kept as the next step's
    /// start) and the normal force on the nodes (N).
    VectorType   weighted_gap, multiplier, face_force;
    double       gap_cap    = 0; ///< m
    unsigned int max_sweeps = 100;
    unsigned int sweeps     = 0; ///< of the last enforce()

    dealii::TimerOutput           &timer;
    std::vector<std::vector<Pose>> poses_old;
    double                         tolerance = 0; ///< m
    std::vector<double>            allowance;     ///< initial overlap, m
    unsigned int                   relaxation = 0, steps_done = 0;
    double                         penetration = 0; ///< m
  };
} // namespace softgrasp

#endif
