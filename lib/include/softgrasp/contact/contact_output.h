#ifndef softgrasp_contact_contact_output_h
#define softgrasp_contact_contact_output_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/data_out.h>
#include <softgrasp/contact/contact_surface.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The contact force on one rigid geom (e.g. a finger link), exerted by
   * the tissue: what a force sensor in the link would measure. In 2D the
   * forces are per unit thickness (N/m) and z entries are zero.
   */
  struct GeomContactForce
  {
    Eigen::Vector3d force  = Eigen::Vector3d::Zero();       ///< resultant F (N)
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();       ///< about the geom
                                                            ///< origin (N m)
    Eigen::Vector3d normal       = Eigen::Vector3d::Zero(); ///< reference n (1)
    Eigen::Vector3d normal_part  = Eigen::Vector3d::Zero(); ///< (n n^T) F
    Eigen::Vector3d lateral_part = Eigen::Vector3d::Zero(); ///< (I-nn^T) F
    /// The frictional traction alone, integrated: sum over the patch of
    /// each node's tangential force (N). lateral_part - friction is the
    /// lateral resistance from pressure on the tissue wrapping the geom.
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    /// Sum over the patch of each node's normal force magnitude (N): with
    /// Coulomb's law at every node, |friction| <= mu nodal_normal.
    double       nodal_normal = 0;
    double       area         = 0; ///< contact area, deformed (m^2; m in 2D)
    unsigned int active       = 0; ///< closed nodes
    unsigned int slipping     = 0; ///< sliding nodes

    /// Normal force magnitude: positive when the tissue pushes the geom
    /// against its reference normal, -n . F (N).
    double normal_force() const
    {
      return -normal.dot(force);
    }
  };

  /// The resultant force (N) and moment about the body's origin (N m) of
  /// the forces @p forces on the geoms of @p body at time @p time (s).
  std::pair<Eigen::Vector3d, Eigen::Vector3d>
  body_resultant(const RigidBody                     &body,
                 const std::vector<GeomContactForce> &forces,
                 const double                         time);

  /**
   * The forces on every geom, [body][geom], at one recorded step: the
   * typed contact history that studies read (rather than CSV columns).
   */
  struct ContactForceRecord
  {
    unsigned int                               step = 0;
    double                                     time = 0; ///< s
    std::vector<std::vector<GeomContactForce>> forces;

    /// The record as numbers (for checkpoints) and back.
    std::vector<double>       pack() const;
    static ContactForceRecord unpack(const std::vector<double> &data);
  };

  /**
   * A sudden drop of a geom's lateral force |(I - n n^T) F| between two
   * consecutive records: a stick-slip event of a drag (after it a
   * quasi-static, rate-independent pull has no determinate state;
   * doc/contact.md).
   */
  struct LateralForceDrop
  {
    unsigned int body = 0, geom = 0;
    double       before = 0, after = 0; ///< |lateral force| (N)
    /// The relative drop, 1 - after / before.
    double fraction() const
    {
      return 1 - after / before;
    }
  };

  /**
   * The geoms whose lateral force fell by more than @p threshold (a
   * fraction) from @p before to @p after, among those whose lateral force
   * was at least 5 % of their normal force before (a drag, not round-off
   * of a pressing geom).
   */
  std::vector<LateralForceDrop>
  lateral_force_drops(const ContactForceRecord &before,
                      const ContactForceRecord &after,
                      const double              threshold);

  /**
   * Output of a ContactSurface (implicit or explicit contact): per geom and per
   * body force resultants with the normal/lateral split f_n = (n n^T) F, f_mu =
   * (I - n n^T) F, where n is the geom's reference normal (ReferenceNormal:
   * the patch mean corrected for symmetry planes, a world direction or one
   * in the geom's frame), rows for the contact
   * history table, and surface fields for the VTU files: contact traction (Pa),
   * contact pressure (Pa), gap (m) and status (0 open, 1 stick, 2 slip).
   */
  /// The contact pressure (Pa; N/m in 2D per unit area) of a slave node
  /// with the current nodal area @p area: n . f / area if the node is
  /// closed, else 0 (as in the VTU field and the injury assessment).
  template <int dim>
  double contact_pressure(const ContactNode<dim> &node, const double area)
  {
    return node.status != ContactStatus::inactive && area > 0
               ? node.normal.dot(node.force) / area
               : 0.0;
  }

  template <int dim> class ContactOutput
  {
  public:
    explicit ContactOutput(const ContactSurface<dim> &contact);

    /// Build the scalar field numbering (after the system's setup()).
    void setup(const SolidSystem<dim> &system);

    /// Forces on every geom, [body][geom], at the current state.
    /// Collective.
    std::vector<std::vector<GeomContactForce>>
    geom_forces(const SolidSystem<dim> &system) const;

    /// Column names of history_values().
    std::vector<std::string> history_columns() const;
    /// Per geom and per body quantities at the current state. Collective.
    std::vector<double> history_values(const SolidSystem<dim> &system) const;
    /// The same from the geom forces of the current state.
    std::vector<double> history_values(
        const std::vector<std::vector<GeomContactForce>> &forces) const;

    /// Add the contact surface fields to @p data_out. Collective.
    void add_fields(const SolidSystem<dim> &system,
                    dealii::DataOut<dim>   &data_out);

    /// Deformed nodal areas int N_j da (m^2; m in 2D) of the owned slave
    /// nodes, in the order of ContactSurface::nodes(). Collective.
    std::vector<double> current_areas(const SolidSystem<dim> &system) const;

  private:
    /// The reference normal of geom @p g of body @p b (its
    /// ReferenceNormal), from the patch's area-weighted normal sum and the
    /// symmetry planes it touches (1 per axis whose plane it touches).
    Eigen::Vector3d
    reference_direction(const unsigned int     b,
                        const unsigned int     g,
                        const Eigen::Vector3d &normal_sum,
                        const Eigen::Vector3d &symmetry_planes) const;

    const ContactSurface<dim>               &contact;
    std::unique_ptr<dealii::FE_Q<dim>>       scalar_fe;
    std::unique_ptr<dealii::DoFHandler<dim>> scalar_dofs;
    /// Scalar dof of each owned node's location.
    std::vector<dealii::types::global_dof_index> scalar_index;
    dealii::TrilinosWrappers::MPI::Vector        traction;
    dealii::TrilinosWrappers::MPI::Vector        pressure, gap, status;
  };
} // namespace softgrasp

#endif
