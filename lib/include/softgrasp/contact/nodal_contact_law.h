#ifndef softgrasp_contact_nodal_contact_law_h
#define softgrasp_contact_nodal_contact_law_h

#include <Eigen/Core>

namespace softgrasp
{
  /// The state of a contact node.
  enum class ContactStatus
  {
    inactive = 0, ///< open gap, no force
    stick    = 1, ///< closed, no tangential slip
    slip     = 2  ///< closed, sliding (always for frictionless contact)
  };

  /**
   * What a slave node knows about its contact with a rigid surface, all in
   * world coordinates (3D; a 2D problem lies in the x-y plane with zero z
   * entries).
   */
  struct NodalContactInput
  {
    Eigen::Vector3d f;   ///< contact force on the body at the node (N)
    double          gap; ///< signed distance to the rigid surface (m)
    Eigen::Vector3d n;   ///< outward unit normal of the rigid surface
    Eigen::Matrix3d H;   ///< gradient of n with respect to the point (1/m)
    Eigen::Vector3d w;   ///< displacement relative to the rigid surface's
                         ///< material point since the last converged step (m)
    double mu  = 0;      ///< Coulomb friction coefficient
    double c   = 1;      ///< complementarity parameter, normal (N/m)
    double c_t = 1;      ///< complementarity parameter, tangential (N/m)
  };

  /**
   * The node's semi-smooth Newton equation Phi = 0 and its linearisation
   * dPhi = A df + B du, where df is the change of the nodal contact force
   * (the node's rows of the global tangent times the increment) and du the
   * node's own displacement increment.
   */
  struct NodalContactLinearization
  {
    ContactStatus   status = ContactStatus::inactive;
    Eigen::Vector3d phi;        ///< residual of the node's conditions (N)
    Eigen::Matrix3d A;          ///< d phi / d f
    Eigen::Matrix3d B;          ///< d phi / d u (at fixed f) (N/m)
    Eigen::Vector3d slip;       ///< tangential slip s = (I - n n^T) w (m)
    double          normal = 0; ///< normal force n . f (N)
  };

  /**
   * The discrete contact conditions at one node of the slave surface, as
   * nonlinear complementarity functions (Hueber, Stadler and Wohlmuth 2008;
   * Popp et al. 2010), with the active set decided by the trial values
   *   t_n = n . f - c g,   t_t = (I - n n^T) f - c s:
   * - inactive (t_n <= 0):            Phi = f (no contact force);
   * - stick (|t_t| <= mu t_n):        Phi = c g n + c_t s (closed, no
   *                                          slip);
   * - slip (frictionless, or
   *   |t_t| > mu t_n):                Phi = c g n + (I - n n^T) f
   *                                          - mu (n . f) t_t / |t_t|.
   * The linearisation is complete (it includes the rotation of the normal
   * through H), so Newton converges quadratically once the active set has
   * settled. c and c_t scale only the active-set prediction, not the
   * solution; they should be of the order of the node's stiffness, or the
   * prediction is decided by the unconverged forces alone.
   */
  NodalContactLinearization
  evaluate_nodal_contact(const NodalContactInput &input);
} // namespace softgrasp

#endif
