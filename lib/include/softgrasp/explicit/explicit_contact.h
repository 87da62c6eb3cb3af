#ifndef softgrasp_explicit_explicit_contact_h
#define softgrasp_explicit_explicit_contact_h

#include <deal.II/base/timer.h>
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

    dealii::TimerOutput           &timer;
    std::vector<std::vector<Pose>> poses_old;
    double                         tolerance = 0; ///< m
    std::vector<double>            allowance;     ///< initial overlap, m
    unsigned int                   relaxation = 0, steps_done = 0;
    double                         penetration = 0; ///< m
  };
} // namespace softgrasp

#endif
