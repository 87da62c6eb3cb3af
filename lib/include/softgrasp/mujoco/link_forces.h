#ifndef softgrasp_mujoco_link_forces_h
#define softgrasp_mujoco_link_forces_h

#include <Eigen/Core>
#include <mujoco/mujoco.h>
#include <vector>

namespace softgrasp
{
  /// The contact force MuJoCo applies to one geom (a finger link).
  struct LinkContactForce
  {
    Eigen::Vector3d force        = Eigen::Vector3d::Zero(); ///< world (N)
    Eigen::Vector3d normal_force = Eigen::Vector3d::Zero(); ///< sum (n n^T)f
    /// Direction of normal_force (from the touched object into the link);
    /// zero without contact.
    Eigen::Vector3d normal     = Eigen::Vector3d::Zero();
    unsigned int    n_contacts = 0;

    /// The lateral (tangential) part, (I - n n^T) f summed over contacts.
    Eigen::Vector3d lateral_force() const
    {
      return force - normal_force;
    }
  };

  /**
   * The contact forces on each geom of @p geoms from the contacts with the
   * geoms of body @p object_body, from mj_contactForce(). MuJoCo returns
   * the force in the contact frame, whose rows are the normal, tangent 1
   * and tangent 2; the normal points from geom1 to geom2 and the force acts
   * on geom2. It is turned to world coordinates, split per contact into
   * the normal part (n n^T) f and the lateral part, and negated where the
   * link is geom1. Needs mj_forward() (or mj_step()) to have run.
   */
  std::vector<LinkContactForce>
  link_contact_forces(const mjModel          *m,
                      const mjData           *d,
                      const int               object_body,
                      const std::vector<int> &geoms);

  /**
   * For each geom of @p geoms: the mean speed (m/s) of its contact points
   * with body @p object_body relative to that body, tangential to each
   * contact, weighted by the contacts' normal forces (0 without contact).
   * A sliding link has the speed of the slide; a sticking one nearly 0.
   * Needs mj_forward() (or mj_step()) to have run.
   */
  std::vector<double> link_slip_speeds(const mjModel          *m,
                                       const mjData           *d,
                                       const int               object_body,
                                       const std::vector<int> &geoms);
} // namespace softgrasp

#endif
