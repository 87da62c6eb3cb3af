#ifndef softgrasp_contact_nodal_potential_h
#define softgrasp_contact_nodal_potential_h

#include <Eigen/Core>
#include <softgrasp/contact/nodal_contact_law.h>

namespace softgrasp
{
  /**
   * What one slave node's share of the incremental contact potential
   * depends on, in world coordinates (3D; a 2D problem has zero z entries
   * and one tangent).
   */
  struct NodalPotentialInput
  {
    double          gap = 0;                        ///< signed distance (m)
    Eigen::Vector3d n   = Eigen::Vector3d::UnitZ(); ///< grad gap (outward)
    /// grad n = grad^2 gap (1/m): the curvature of the rigid surface,
    /// positive semi-definite on a convex body.
    Eigen::Matrix3d H          = Eigen::Matrix3d::Zero();
    double          multiplier = 0; ///< augmented Lagrangian lam >= 0 (N)
    double          penalty    = 1; ///< k (N/m)
    double          mu         = 0; ///< Coulomb friction coefficient (1)
    double          lagged_normal_force = 0; ///< lambda^k >= 0 (N)
    /// Orthonormal tangent basis of the lagged normal: its columns span
    /// the plane the slip is measured in (the second column is zero in 2D).
    Eigen::Matrix<double, 3, 2> T = Eigen::Matrix<double, 3, 2>::Zero();
    /// The node's motion relative to the rigid body's material point over
    /// the step (m); depends on the node's position x with dw/dx = I.
    Eigen::Vector3d w              = Eigen::Vector3d::Zero();
    double          slip_tolerance = 1e-5; ///< eps of phi_eps (m)
    /// Friction against the node's current normal force lambda(x) instead
    /// of lagged_normal_force (the polish of a step whose lag does not
    /// settle): Coulomb's law exactly, no longer a potential, and the
    /// Hessian gains the non-symmetric k f_t n^T / lambda.
    bool current_normal_force = false;
  };

  /// The node's potential, its force and its Hessian at one position.
  struct NodalPotential
  {
    /// C + D (J): the augmented Lagrangian of the gap,
    /// (max(0, lam - k g)^2 - lam^2) / (2 k), and the lagged friction
    /// potential mu lambda^k phi_eps(|T^T w|).
    double energy = 0;
    /// -grad_x (C + D): the contact force on the tissue node (N).
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    /// The Hessian d(-force)/dx (N/m): k n n^T - lambda H while the node
    /// presses (exact; the term -lambda H of a convex body's curvature is
    /// negative semi-definite, the rest positive semi-definite) plus the
    /// friction potential's (positive semi-definite; T is fixed); with
    /// current_normal_force the Jacobian of the force, not symmetric.
    Eigen::Matrix3d hessian      = Eigen::Matrix3d::Zero();
    double          normal_force = 0; ///< lambda = max(0, lam - k g) (N)
    /// The friction part of force (N), opposing the slip, at most
    /// mu lambda^k.
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    Eigen::Vector3d slip     = Eigen::Vector3d::Zero(); ///< T T^T w (m)
    ContactStatus   status   = ContactStatus::inactive;
  };

  /**
   * One node's share of the incremental potential of frictional contact:
   * normal contact by an augmented Lagrangian on the gap, friction as the
   * dissipation potential mu lambda^k phi_eps(|s|) of the slip
   * s = T^T w, with the normal force lambda^k and the frame T lagged
   * (Li et al., Incremental Potential Contact, 2020; Simo and Laursen
   * 1992). phi_eps is IPC's f0: r^2 / eps - r^3 / (3 eps^2) + eps / 3
   * below eps and r above, convex and C2, so the friction force is
   * mu lambda^k f1(|s|) along -s/|s| with f1 = 2 q - q^2, q = |s| / eps,
   * below eps and 1 above (Coulomb, smoothed over a slip of eps, with a
   * stiffness that is continuous where a node starts to slip). Stick:
   * |s| < eps; slip: |s| >= eps; inactive: neither force.
   */
  NodalPotential evaluate_nodal_potential(const NodalPotentialInput &input);

  /// An orthonormal basis of the plane normal to @p n (unit), as the
  /// columns of a 3 x 2 matrix; in 2D (@p dim = 2, n in the x-y plane) the
  /// single tangent in that plane and a zero second column.
  Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d &n,
                                            const unsigned int     dim);
} // namespace softgrasp

#endif
