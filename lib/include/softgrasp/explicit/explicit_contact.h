#ifndef softgrasp_explicit_explicit_contact_h
#define softgrasp_explicit_explicit_contact_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <softgrasp/contact/contact_surface.h>

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
   */
  template <int dim> class ExplicitContact : public ContactSurface<dim>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    ExplicitContact(const ContactParameters &parameters,
                    const RigidBodySet      &bodies,
                    dealii::TimerOutput     &timer);

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

    /// Largest penetration (m, >= 0) over all nodes after the last
    /// enforce(), on all ranks.
    double max_penetration() const;

    /// Face mode: the Jacobi sweeps of the last enforce() (0 in node mode).
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
    /// Face mode: G_k = int psi_k g dA into weighted_gap (owned, summed
    /// over the ranks), with each Gauss point's normal, for @p u (ghosted).
    void weighted_gaps(const VectorType &u);
    /// Face mode: the nodes' normal forces sum_q w_q N_k t_q n_q from the
    /// pressures (multiplier, ghosted) into face_force (owned, summed).
    void normal_forces();

    /// Face mode: a slave face with its dual basis coefficients A = D M^-1
    /// (psi_k = sum_l A_kl N_l; M the face's mass matrix, D its row sums)
    /// and each Gauss point's gap (m, capped) and normal at the last
    /// weighted_gaps().
    struct DualFace
    {
      typename ContactSurface<dim>::SlaveFace face;
      dealii::FullMatrix<double>              dual;
      std::vector<double>                     gap;
      std::vector<Eigen::Vector3d>            normal;
    };
    std::vector<DualFace> faces;
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
