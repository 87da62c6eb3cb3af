#ifndef softgrasp_contact_contact_surface_h
#define softgrasp_contact_contact_surface_h

#include <array>
#include <limits>
#include <softgrasp/contact/contact_parameters.h>
#include <softgrasp/contact/nodal_contact_law.h>
#include <softgrasp/mechanics/solid_system.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <utility>
#include <vector>

namespace softgrasp
{
  /// The contact state of one slave node (shared by every enforcement).
  template <int dim> struct ContactNode
  {
    std::array<dealii::types::global_dof_index, dim> dofs;
    std::array<bool, dim>                            free{};
    Eigen::Vector3d reference_position = Eigen::Vector3d::Zero(); ///< X (m)
    /// Position (m) at the start of the current step.
    Eigen::Vector3d last_converged = Eigen::Vector3d::Zero();
    double          reference_area = 0; ///< D_j = int N_j dA, reference (m^2)
    ContactStatus   status         = ContactStatus::inactive;
    int             body           = -1; ///< nearest body (-1: none)
    unsigned int    geom           = 0;
    double          gap    = std::numeric_limits<double>::infinity(); ///< m
    Eigen::Vector3d normal = Eigen::Vector3d::Zero(); ///< rigid, outward
    /// Contact force on the tissue node (N; N/m in 2D); the body receives
    /// its negative.
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d slip  = Eigen::Vector3d::Zero(); ///< in the step (m)
  };

  /**
   * The geometry half of contact between the slave surface of a deformable
   * solid and moving rigid bodies: which nodes form the surface (owned
   * nodes on the faces with the ids of 'Contact/Slave boundary ids'), their
   * reference areas, where the rigid geoms are at a time, and the signed
   * distance and outward normal of the nearest geom at a point. How the
   * contact conditions are enforced is left to the derived classes
   * (MortarContact: semi-smooth Newton in the implicit solver;
   * ExplicitContact: forward-increment Lagrange multipliers in the explicit
   * solver); ContactOutput reports both alike.
   *
   * In 2D, the plane problem lies in the world x-y plane (z = 0) and the
   * rigid geoms must be invariant along z there.
   */
  template <int dim> class ContactSurface
  {
  public:
    using Node = ContactNode<dim>;

    ContactSurface(const ContactParameters &parameters,
                   const RigidBodySet      &bodies);
    virtual ~ContactSurface() = default;

    /// Find the slave nodes of @p system (after its setup()).
    virtual void setup(const SolidSystem<dim> &system);

    /// Time (s) at which the rigid bodies are placed.
    void   set_time(const double time);
    double time() const;

    /// The locally owned slave nodes.
    const std::vector<Node> &nodes() const;
    const RigidBodySet      &rigid_bodies() const;
    bool is_slave_boundary(const dealii::types::boundary_id id) const;

    /**
     * How deep (m) each locally owned slave node lies inside a rigid body
     * at @p time when displaced by @p u (ghosted; 0 outside). Places the
     * bodies at @p time. For Trilinos and deal.II distributed vectors.
     */
    template <typename VectorType>
    std::vector<double> node_overlaps(const double time, const VectorType &u);

    /// The deepest penetration of a slave node into a rigid geom.
    struct Penetration
    {
      double          depth    = 0;                       ///< m, >= 0 (0: none)
      Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< of the node, m
    };

    /**
     * The deepest penetration over all slave nodes displaced by @p u
     * (ghosted), with the geoms where the last set_time() or update put
     * them: what the history reports per step. Collective.
     */
    Penetration
    deepest_penetration(const dealii::TrilinosWrappers::MPI::Vector &u) const;

    /// The global number of nodes with an overlap and the deepest (m).
    std::pair<unsigned int, double>
    overlap_summary(const std::vector<double> &overlaps) const;

    /// Global numbers of closed and of slipping nodes at the last
    /// evaluation.
    unsigned int n_active() const;
    unsigned int n_slip() const;

  private:
    /// Whether face @p f of @p cell lies on a slave boundary.
    template <typename CellIterator>
    bool on_slave(const CellIterator &cell, const unsigned int f) const;
    /// The reference nodal areas D_j = int N_j dA over the slave surface
    /// (m^2; m per metre of thickness in 2D), ghosted.
    dealii::TrilinosWrappers::MPI::Vector
    nodal_areas(const SolidSystem<dim> &system) const;
    /// node_list = the owned slave nodes, found from owned and ghost cells.
    void collect_nodes(const SolidSystem<dim>                      &system,
                       const dealii::TrilinosWrappers::MPI::Vector &area);

  protected:
    struct Proximity
    {
      int             body   = -1;
      unsigned int    geom   = 0;
      double          gap    = std::numeric_limits<double>::infinity(); ///< m
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    };
    /**
     * One slave face of a locally owned cell and its Gauss points (degree
     * + 2 per direction): the global dofs of the face's support points
     * ([k * dim + c]), the shape values N_k at each point ([q][k]), the
     * reference JxW (m^2; m in 2D) and the reference positions (m).
     */
    struct SlaveFace
    {
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<std::vector<double>>             shape;
      std::vector<double>                          weight;
      std::vector<Eigen::Vector3d>                 position;
    };
    /// The slave faces of the locally owned cells of @p system.
    std::vector<SlaveFace> slave_faces(const SolidSystem<dim> &system) const;

    /// The nearest geom to @p x (m) in the poses of poses_now.
    Proximity nearest(const Eigen::Vector3d &x) const;
    /// Signed distance and normal of geom (p.body, p.geom) at @p x.
    Proximity       distance_to(const int              body,
                                const unsigned int     geom,
                                const Eigen::Vector3d &x) const;
    Eigen::Vector3d normal_at(const Proximity       &p,
                              const Eigen::Vector3d &x) const;
    /// grad n of geom @p p at @p x (1/m), the rigid surface's curvature,
    /// by central differences of step @p h (m), symmetrised.
    Eigen::Matrix3d normal_gradient(const Proximity       &p,
                                    const Eigen::Vector3d &x,
                                    const double           h) const;
    void            place_bodies(const double                    time,
                                 std::vector<std::vector<Pose>> &poses) const;

    const ContactParameters        parameters;
    const RigidBodySet            &bodies;
    MPI_Comm                       comm         = MPI_COMM_SELF;
    double                         current_time = 0;
    std::vector<std::vector<Pose>> poses_now;
    std::vector<Node>              node_list;
    /// Local dofs of each support point of a cell: [point][component].
    std::vector<std::array<unsigned int, dim>> cell_nodes;
    unsigned int                               active_count = 0;
    unsigned int                               slip_count   = 0;
  };
} // namespace softgrasp

#endif
