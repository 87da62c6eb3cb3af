#ifndef softgrasp_grasp_link_force_history_h
#define softgrasp_grasp_link_force_history_h

#include <Eigen/Core>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The contact force history of one finger link (a geom, "body/geom"),
   * one entry per recorded step: what a grasp study reports and plots.
   * normal is -n . F with n the link's reference normal, lateral is
   * |(I - n n^T) F| and friction the magnitude of the frictional traction
   * alone, integrated (lateral - friction is the resistance of tissue
   * pressed against the link's sides). All in N, time in s.
   */
  struct LinkForceHistory
  {
    std::string                  link;
    std::vector<double>          time;
    std::vector<Eigen::Vector3d> force;
    std::vector<double>          normal, lateral, friction;
    /// Sum of the nodes' normal force magnitudes: Coulomb's law bounds
    /// friction by mu times it (GeomContactForce::nodal_normal).
    std::vector<double> nodal_normal;
    /// Contact nodes on the link: closed, and of those sliding (counts).
    std::vector<double> closed, slipping;

    /// The largest normal force over the history (N; 0 if empty).
    double largest_normal() const;

    /// The entries from time @p start (s) on, their time counted from it.
    LinkForceHistory since(const double start) const;
  };

  /// One LinkForceHistory per geom of @p bodies, from the solver's typed
  /// contact records.
  std::vector<LinkForceHistory>
  link_force_histories(const RigidBodySet                    &bodies,
                       const std::vector<ContactForceRecord> &records);
} // namespace softgrasp

#endif
