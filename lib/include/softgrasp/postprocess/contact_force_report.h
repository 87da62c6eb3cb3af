#ifndef softgrasp_postprocess_contact_force_report_h
#define softgrasp_postprocess_contact_force_report_h

#include <deal.II/base/mpi.h>
#include <ostream>
#include <softgrasp/contact/contact_output.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The contact forces of a run on every rigid body and geom, whatever
   * their names: a summary of the last recorded step, a table over time and
   * its picture. Reads the typed force history (ContactForceRecord) of a
   * solver, never its CSV columns. Forces in N (N/m in 2D), moments in N m
   * (N m/m). Call on one rank.
   */
  class ContactForceReport
  {
  public:
    /// @p dim selects the units (2: per metre of thickness).
    ContactForceReport(const RigidBodySet                    &bodies,
                       const std::vector<ContactForceRecord> &records,
                       const unsigned int                     dim);

    /// True if no step was recorded or there are no rigid bodies.
    bool empty() const;

    /**
     * Per body the resultant force and moment (about the body origin), per
     * geom its force, moment (about the geom origin), reference normal,
     * normal and lateral force, the friction-only part of the lateral force
     * and the rest (pressure on the tissue wrapping the geom), contact area
     * and active/slipping nodes, at the last recorded step.
     */
    void print(std::ostream &out) const;

    /**
     * Write @p base.dat (time, then per geom: normal, lateral,
     * friction-only and pressure part of the lateral force) and
     * @p base.png (these over time, one colour per geom) into
     * @p directory. Returns true if the picture was made; a missing
     * gnuplot is reported on @p log and the table stays.
     */
    bool write_table_and_picture(const std::string &directory,
                                 const std::string &base,
                                 std::ostream      &log) const;

    /// "N" in 3D, "N/m" in 2D.
    std::string force_unit() const;

  private:
    const RigidBodySet                    &bodies;
    const std::vector<ContactForceRecord> &records;
    unsigned int                           dim;

    std::vector<std::string> geom_labels() const;
  };

  /**
   * After a run: print the ContactForceReport of @p records on rank 0 of
   * @p comm and write @p base.dat and @p base.png into @p directory. Does
   * nothing for a run without rigid bodies.
   */
  void report_contact_forces(MPI_Comm                               comm,
                             const RigidBodySet                    &bodies,
                             const std::vector<ContactForceRecord> &records,
                             unsigned int                           dim,
                             const std::string                     &directory,
                             const std::string                     &base,
                             std::ostream                          &out);
} // namespace softgrasp

#endif
