#ifndef softgrasp_meshes_layered_limb_h
#define softgrasp_meshes_layered_limb_h

#include <array>
#include <deal.II/grid/manifold.h>
#include <softgrasp/meshes/mesh_generator.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The shape of a layered limb segment (doc/layered_limb.md): its axis is
   * the local x axis from the shoulder end x = -L/2 to the elbow end
   * x = L/2; its cross-section in the y-z plane is an ellipse (semi-axis a
   * along y, b along z) that tapers linearly along x, with the tissue
   * layers skin, subcutaneous fat, deep fascia and muscle from the outside
   * in, on a circular humerus of constant radius on the axis. All lengths
   * in m.
   *
   * The interfaces are numbered from the inside: 0 the bone surface, 1
   * muscle/fascia, 2 fascia/fat, 3 fat/skin, 4 the skin surface. Interface
   * k at x is the ellipse with semi-axes (A_k(x), B_k(x)), A_k = a(x) minus
   * the layers outside it (so a layer has its nominal thickness on the
   * principal axes).
   */
  struct LimbGeometry
  {
    double length        = 0.300;  ///< m
    double circumference = 0.342;  ///< m, of the skin at mid-segment
    double aspect_ratio  = 1.0;    ///< b / a of the skin's cross-section, 1
    double taper         = 1.0;    ///< elbow / shoulder circumference, 1
    double skin          = 0.0021; ///< m
    double fat           = 0.0055; ///< m
    double fascia        = 0.0007; ///< m
    double bone_radius   = 0.0095; ///< m

    /// The semi-axis a of the skin at mid-segment (Ramanujan's perimeter).
    double mid_semi_axis() const;
    /// Semi-axes (A_k, B_k) of interface k (0 bone ... 4 skin) at x.
    std::array<double, 2> semi_axes(const unsigned int k, const double x) const;
    /// Throws an InputError if a layer does not fit anywhere along x.
    void check() const;
    /// Throws an InputError if a size lies outside the range of human limbs
    /// (a newborn's forearm to an adult's thigh): usually a unit typed
    /// wrong. 'Mesh/Layered limb/Check human size = false' skips it.
    void check_human_size() const;
  };

  /**
   * The chart (xi, theta, x) -> point of a limb: xi in [0, 4] runs across
   * the layers (interface k at xi = k, linear in between), theta is the
   * angle about the axis (2 pi periodic). Its push-forward and pull-back
   * include the placement, so refinement puts new vertices on the true
   * elliptic, tapered interfaces wherever the limb has been moved.
   */
  class LimbManifold : public dealii::ChartManifold<3, 3, 3>
  {
  public:
    LimbManifold(const LimbGeometry &geometry, const Placement<3> &placement);

    std::unique_ptr<dealii::Manifold<3, 3>> clone() const override;
    dealii::Point<3> pull_back(const dealii::Point<3> &space) const override;
    dealii::Point<3> push_forward(const dealii::Point<3> &chart) const override;
    dealii::DerivativeForm<1, 3, 3>
    push_forward_gradient(const dealii::Point<3> &chart) const override;

    /// The same in the limb's own frame (no placement).
    dealii::Point<3> local_point(const dealii::Point<3> &chart) const;
    dealii::Point<3> local_chart(const dealii::Point<3> &local) const;

  private:
    LimbGeometry         geometry;
    Placement<3>         placement;
    dealii::Tensor<2, 3> inverse_rotation;
  };

  /**
   * 'Mesh/Type = layered limb': a conforming hexahedral mesh of an upper-arm
   * segment (LimbGeometry), layer by layer, with a uniformly fine axial
   * zone where the hand grasps and geometric growth towards the ends.
   *
   * Material ids (settable): skin 1, fat 2, fascia 3, muscle 4, bone 5.
   * Boundary ids: 0 skin surface, 1 bone surface (rigid bone), 2 shoulder
   * end cap and 3 elbow end cap of the soft tissue, 4 and 5 the shoulder
   * and elbow ends of a solid bone. A layer of thickness 0 is left out.
   */
  class LayeredLimb : public MeshGenerator<3>
  {
  public:
    /// The humerus: a fixed boundary, or a stiff solid meshed to the axis.
    enum class Bone
    {
      rigid,
      solid
    };

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm) override;
    void
    create_coarse_mesh(dealii::Triangulation<3> &triangulation) const override;
    /// Manifold ids of every face and edge, and boundary ids from where
    /// each boundary face lies (skin, bone, the two ends).
    void set_ids(dealii::Triangulation<3> &triangulation) const;
    void attach_manifolds(dealii::Triangulation<3> &triangulation,
                          const Placement<3>       &placement) const override;
    bool is_curved() const override
    {
      return true;
    }
    bool sets_material_ids() const override
    {
      return true;
    }

    /// The chart coordinate xi of every radial node, from the bone out.
    std::vector<double> radial_nodes() const;
    /// The axial node coordinates x from the shoulder to the elbow end.
    std::vector<double> axial_nodes() const;
    double              n_coarse_cells() const override;

    LimbGeometry geometry;
    Bone         bone = Bone::rigid;
    /// cells across skin, fat, fascia, muscle (0 for an absent layer)
    std::array<unsigned int, 4> radial_cells = {{1, 1, 1, 3}};
    /// size ratio of neighbouring muscle cells from the fascia inwards, 1
    double       muscle_grading        = 1.5;
    unsigned int circumferential_cells = 24;  ///< multiple of 4 (8: solid)
    double       zone_center           = 0;   ///< m, on the axis
    double       zone_length           = 0.1; ///< m
    unsigned int zone_cells            = 8;   ///< axial, in the zone
    double       axial_growth          = 1.3; ///< outside the zone, 1
    /// skin, fat, fascia, muscle, bone
    std::array<dealii::types::material_id, 5> material_ids = {{1, 2, 3, 4, 5}};
  };
} // namespace softgrasp

#endif
